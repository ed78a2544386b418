package toast;

/* Distance to the next object in front of the robot, in millimetres (platform component). */
<<handwritten>> component DistanceSensor {
  port out int value;
}
