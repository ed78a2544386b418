package toast;

/* Pushes the toaster lever down or releases it (platform component). */
<<handwritten>> component ToasterActuator {
  port <<sync>> in boolean leverDown;
}
