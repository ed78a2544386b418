package robot;

/* A compute block: translated by ros2.Components itself (supports: compute). */
component Scale(int factor = 2) {
  port <<sync>> in int raw,
       <<sync>> out int scaled;

  compute {
    scaled = raw * factor;
  }
}
