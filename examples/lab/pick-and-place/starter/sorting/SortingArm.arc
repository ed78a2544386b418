package sorting;

import sorting.types.*;

/*
 * YOUR TASK: the RobotArm programs of the sorting cell's arm (see the exercise description and
 * SortingArm.stream). Each constant of SortCmd other than NONE needs the program it names.
 */
component SortingArm {
  port in SortCmd cmd,
       in int partAngle,
       <<sync>> out ArmStatus status;

  robotarm {
    location aboveRedBin -90deg 30cm;
    location redBin -90deg 12cm;
    location aboveBlueBin 90deg 30cm;
    location blueBin 90deg 12cm;

    // Write the programs SortRed and SortBlue.
  }
}
