package toast;

/* Distance from the sensor at the bread holder to the next object in millimetres, sampled once per time slice (platform component). */
<<handwritten>> component DistanceSensor {
  port <<sync>> out int value;
}
