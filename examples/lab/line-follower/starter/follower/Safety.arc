package follower;

/* Passes the wheel speeds on until the bumper is hit; from then on both wheels stay at 0. */
component Safety {
  port <<sync>> in boolean bumped,
       <<sync>> in int leftIn,
       <<sync>> in int rightIn,
       <<sync>> out int left,
       <<sync>> out int right;

  <<sync>> automaton {
    initial state Driving;
    state Stopped;

    Driving -> Stopped [bumped] / { left = 0; right = 0; };
    Driving -> Driving [!bumped] / { left = leftIn; right = rightIn; };
    Stopped -> Stopped / { left = 0; right = 0; };
  }
}
