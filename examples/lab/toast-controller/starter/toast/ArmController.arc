package toast;

import toast.types.*;

/* The paper's Listing 2: RobotArm programs embedded in a component; `cmd` selects the program. */
component ArmController {
  port in ArmProgram cmd,
       in int angle,
       in int height,
       <<sync>> out ArmStatus status;

  robotarm {
    // Each place has a point above it at travel height: the base only turns up there, because
    // both joints move at once and the lift arrives first.
    location aboveBreadbox 0deg 30cm;
    location breadbox 0deg 7cm;
    location aboveToaster 120deg 30cm;
    location toaster 120deg 20cm;

    // Takes a slice of bread from the bread box and puts it into the toaster slot.
    program LoadBread {
      move top; open; move aboveBreadbox; move breadbox; close; move top;
      move aboveToaster; move toaster; open; move top;
    }

    // Listing 1, with the travel points: takes the toast out of the toaster and puts it onto
    // the plate at the angle and height the PlateLocator reports.
    program PickupAndDeploy {
      move top; open; move aboveToaster; move toaster; close; move top;
      move angle 30cm; move angle height; open; move top;
    }
  }
}
