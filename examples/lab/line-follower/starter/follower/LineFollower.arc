package follower;

/*
 * YOUR TASK: compose the line-following robot's controller from the given components
 * Threshold, Steering and Safety (see the exercise description and LineFollower.stream). Keep
 * the ports as they are: the robot's sensors and motors are wired to them.
 */
component LineFollower {
  port in int brightness,
       in boolean bumped,
       out int left,
       out int right;

  // Add the subcomponents and connect them.
}
