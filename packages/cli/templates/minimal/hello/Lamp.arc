package hello;

/* The top component of the application: a button wired to a Toggle that drives a lamp. */
component Lamp {
  port in boolean button,
       out boolean lamp;

  Toggle toggle;

  button -> toggle.press;
  toggle.light -> lamp;
}
