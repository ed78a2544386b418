package toast;

import toast.types.*;

/* Decides when to load bread, when the toast is done and when to serve it. */
component Controller(int threshold = 30) {
  port in int distance,
       in ToastColor color,
       in ArmStatus armStatus,
       <<delayed>> out ToasterCmd toaster,
       <<delayed>> out ArmProgram arm;

  int served = 0;

  <<sync>> automaton {
    initial { toaster = ToasterCmd.STOP; arm = ArmProgram.NONE; } state Idle;
    state Loading;
    state Toasting;
    state Serving;

    // A slice of bread in the holder (closer than `threshold` millimetres to the distance sensor) starts the service.
    Idle -> Loading [distance < threshold] / { arm = ArmProgram.LOAD_BREAD; };
    Loading -> Toasting [armStatus == ArmStatus.DONE] / { toaster = ToasterCmd.START; };
    Toasting -> Serving [color == ToastColor.GOLDEN] / { toaster = ToasterCmd.STOP; arm = ArmProgram.PICKUP_AND_DEPLOY; };
    Serving -> Idle [armStatus == ArmStatus.DONE] / { served++; };
  }
}
