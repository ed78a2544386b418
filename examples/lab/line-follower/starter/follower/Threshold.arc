package follower;

/* Classifies the light sensor's brightness: below `level` the sensor sees the dark line. */
component Threshold(int level = 50) {
  port <<sync>> in int brightness,
       <<sync>> out boolean onLine;

  <<sync>> automaton {
    initial state Watching;

    Watching -> Watching [brightness < level] / { onLine = true; };
    Watching -> Watching [brightness >= level] / { onLine = false; };
  }
}
