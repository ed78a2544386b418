package toast;

import toast.types.*;

/* Runs arm motion programs: fetch the bread into the toaster, deliver the toast to the plate. */
<<handwritten>> component ArmController {
  port in ArmProgram cmd;
  port <<sync>> out ArmStatus status;
}
