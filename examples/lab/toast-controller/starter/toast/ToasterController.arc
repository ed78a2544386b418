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
      // (MontiArc fires the first enabled transition in declaration order: this internal
      // transition must not shadow On -> Off on STOP below.)
      -> [cmd != ToasterCmd.STOP && slices < maxSlices] / { slices++; };
    };

    Off -> On [cmd == ToasterCmd.START];
    On -> Off [cmd == ToasterCmd.STOP];
    On -> Off [slices >= maxSlices];
  }
}
