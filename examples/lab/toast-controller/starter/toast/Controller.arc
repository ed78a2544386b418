package toast;

import toast.types.*;

/*
 * YOUR TASK: the main controller of the toast robot as an automaton. It decides when the arm
 * loads bread, when the toast is done and when the arm serves it (see the exercise description
 * and the stream tests in Controller.stream). Keep the ports and the parameter as they are: the
 * rest of the robot (ToastServiceRobot.arc) is wired to them.
 */
component Controller(int threshold = 30) {
  port in int distance,
       in ToastColor color,
       in ArmStatus armStatus,
       <<delayed>> out ToasterCmd toaster,
       <<delayed>> out ArmProgram arm;

  int served = 0;

  <<sync>> automaton {
    initial { toaster = ToasterCmd.STOP; arm = ArmProgram.NONE; } state Idle;

    // Add the states Loading, Toasting and Serving, and the transitions between them.
  }
}
