package sorting;

import sorting.types.*;

/*
 * The sorting cell's arm: picks the part from the end of the conveyor (at the angle `partAngle`
 * reports, on the belt 5cm above the table) and drops it into the bin of its color.
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

    // Picks the part at the conveyor's end and drops it into the red bin.
    program SortRed {
      move top; open; move partAngle 30cm; move partAngle 5cm; close; move top;
      move aboveRedBin; move redBin; open; move top;
    }

    // The same into the blue bin.
    program SortBlue {
      move top; open; move partAngle 30cm; move partAngle 5cm; close; move top;
      move aboveBlueBin; move blueBin; open; move top;
    }
  }
}
