package toast;

import toast.types.*;

/* The paper's Listing 2: RobotArm programs embedded in a component; `cmd` selects the program. */
component ArmController {
  port in ArmProgram cmd,
       in int angle,
       in int height,
       <<sync>> out ArmStatus status;

  robotarm {
    location breadbox 0deg 7cm;
    location toaster 120deg 20cm;

    // Takes a slice of bread from the bread box and puts it into the toaster slot.
    program LoadBread {
      move top; open; move breadbox; close; move top; move toaster; open; move top;
    }

    // Listing 1: takes the toast out of the toaster and puts it onto the plate at angle/height.
    program PickupAndDeploy {
      move top; open; move toaster; close; move top; move angle height; open;
    }
  }
}
