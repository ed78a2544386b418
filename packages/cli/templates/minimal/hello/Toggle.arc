package hello;

/* Toggles a light: each press of the button switches it on or off. */
component Toggle {
  port <<sync>> in boolean press,
       <<sync>> out boolean light;

  <<sync>> automaton {
    initial { light = false; } state Off;
    state On;

    Off -> On [press] / { light = true; };
    On -> Off [press] / { light = false; };
  }
}
