package toast;

/* Distance to the next object in front of the robot in millimetres, sampled once per time slice (platform component). */
<<handwritten>> component DistanceSensor {
  port <<sync>> out int value;
}
