package toast;

/* Where the plate stands: base angle (deg) and gripper height (cm) to put something on it (platform component). */
<<handwritten>> component PlateLocator {
  port <<sync>> out int angle,
       <<sync>> out int height;
}
