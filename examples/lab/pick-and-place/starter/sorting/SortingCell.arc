package sorting;

import sorting.types.*;

/*
 * The sorting cell: parts arrive on a conveyor; a color sensor at its end tells the Sorter what
 * came, and the SortingArm puts the part into the bin of its color.
 */
component SortingCell {
  port in PartColor color,
       in int partAngle,
       out ArmStatus status;

  Sorter sorter;
  SortingArm arm;

  color -> sorter.color;
  partAngle -> arm.partAngle;
  sorter.arm -> arm.cmd;
  arm.status -> sorter.armStatus;
  arm.status -> status;
}
