package sorting;

import sorting.types.*;

/* Sends the arm the program for the color of the part the sensor sees, and waits until it is done. */
component Sorter {
  port in PartColor color,
       in ArmStatus armStatus,
       <<delayed>> out SortCmd arm;

  int sorted = 0;

  <<sync>> automaton {
    initial { arm = SortCmd.NONE; } state Waiting;
    state Sorting;

    Waiting -> Sorting [color == PartColor.RED] / { arm = SortCmd.SORT_RED; };
    Waiting -> Sorting [color == PartColor.BLUE] / { arm = SortCmd.SORT_BLUE; };
    Sorting -> Waiting [armStatus == ArmStatus.DONE] / { sorted++; };
  }
}
