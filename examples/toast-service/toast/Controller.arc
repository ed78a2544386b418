package toast;

import toast.types.*;

/* Decides when to fetch bread, when the toast is done and when to deliver it. */
component Controller(int threshold = 30) {
  port in int distance,
       in ToastColor color,
       in ArmStatus armStatus,
       out ToasterCmd toaster,
       <<delayed>> out ArmProgram arm;

  int cycles = 0;

  <<sync>> automaton {
    initial { toaster = ToasterCmd.STOP; arm = ArmProgram.NONE; } state Idle;
    state Fetching;
    state Toasting {
      entry / { cycles++; }
    };
    state Delivering;

    Idle -> Fetching [distance < threshold] / { arm = ArmProgram.FETCH; };
    Fetching -> Toasting [armStatus == ArmStatus.DONE] / { toaster = ToasterCmd.START; arm = ArmProgram.NONE; };
    Toasting -> Delivering [color == ToastColor.GOLDEN] / { toaster = ToasterCmd.STOP; arm = ArmProgram.DELIVER; };
    Delivering -> Idle [armStatus == ArmStatus.DONE] / { arm = ArmProgram.NONE; };
  }
}
