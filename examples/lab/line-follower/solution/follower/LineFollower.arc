package follower;

/*
 * The line-following robot's controller: the light sensor's brightness goes through the
 * Threshold to the Steering, whose wheel speeds pass the Safety before they reach the motors.
 */
component LineFollower {
  port in int brightness,
       in boolean bumped,
       out int left,
       out int right;

  Threshold threshold(50);
  Steering steering(40);
  Safety safety;

  brightness -> threshold.brightness;
  threshold.onLine -> steering.onLine;
  steering.left -> safety.leftIn;
  steering.right -> safety.rightIn;
  bumped -> safety.bumped;
  safety.left -> left;
  safety.right -> right;
}
