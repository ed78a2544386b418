package toast;

import toast.types.*;

/* Holds the toaster lever down while toasting, and releases it on STOP or after a safety timeout. */
component ToasterController(int maxSlices = 600) {
  port <<sync>> in ToasterCmd cmd,
       <<sync>> out boolean leverDown;

  int slices = 0;

  <<sync>> automaton {
    initial { leverDown = false; } state Off;
    state On {
      entry / { slices = 0; leverDown = true; }
      exit / { leverDown = false; }
      -> [slices < maxSlices] / { slices++; };
    };

    Off -> On [cmd == ToasterCmd.START];
    On -> Off [cmd == ToasterCmd.STOP];
    On -> Off [slices >= maxSlices];
  }
}
