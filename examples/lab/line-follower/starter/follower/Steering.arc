package follower;

/*
 * Follows the edge of the line: on the line it curves right (the left wheel faster), off the
 * line it curves left, so the robot zig-zags along the edge.
 */
component Steering(int speed = 40) {
  port <<sync>> in boolean onLine,
       <<sync>> out int left,
       <<sync>> out int right;

  <<sync>> automaton {
    initial state Following;

    Following -> Following [onLine] / { left = speed; right = speed / 2; };
    Following -> Following [!onLine] / { left = speed / 2; right = speed; };
  }
}
