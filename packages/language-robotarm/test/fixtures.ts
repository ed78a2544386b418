// Models shared by the tests.

/** The paper's Listing 1, verbatim: a standalone RobotArm file. */
export const LISTING_1 = `robotarm ToastService {
  input int angle;
  input int height;
  location toaster 120deg 20cm;      // name, joint angle, gripper height
  program PickupAndDeploy {
    move top; open; move toaster; close; move top; move angle height; open;
  }
}`;

/**
 * The paper's Listing 2 as ARCHITECTURE.md section 3.4 describes it: the body of Listing 1
 * without `input` declarations, embedded in a component whose incoming ports `angle` and
 * `height` the moves read, with the ports of the RobotArm port protocol (docs/robotarm.md).
 */
export const LISTING_2 = `component ArmController {
  port in ArmCommand cmd,
       in int angle,
       in int height,
       out ArmStatus status;
  robotarm {
    location toaster 120deg 20cm;
    program PickupAndDeploy {
      move top; open; move toaster; close; move top; move angle height; open;
    }
  }
}`;

export const ARM_TYPES = `classdiagram ArmTypes {
  enum ArmCommand { NONE, PICKUP_AND_DEPLOY; }
  enum ArmStatus { IDLE, BUSY, DONE; }
}`;
