/**
 * The stable diagnostic codes of the RobotArm language (ARCHITECTURE.md section 5 and
 * docs/robotarm.md). Codes are released API: never rename one. docs/diagnostics.md documents each
 * with examples (ROBOTARM_DIAGNOSTICS).
 */
export const RobotArmCodes = {
    InputInEmbedded: 'robotarm/input-in-embedded',
    MoveNotNumeric: 'robotarm/move-not-numeric',
    UnresolvedName: 'robotarm/unresolved-name',
    MoveArity: 'robotarm/move-arity',
    DuplicateName: 'robotarm/duplicate-name',
    ReservedName: 'robotarm/reserved-name',
    InvalidUnit: 'robotarm/invalid-unit',
    UnitMismatch: 'robotarm/unit-mismatch',
    JointLimit: 'robotarm/joint-limit',
    EmptyProgram: 'robotarm/empty-program',
    NamingConvention: 'robotarm/naming-convention',
    MissingCmdPort: 'robotarm/missing-cmd-port',
    CmdPortType: 'robotarm/cmd-port-type',
    MissingStatusPort: 'robotarm/missing-status-port',
    StatusPortType: 'robotarm/status-port-type',
    CommandWithoutProgram: 'robotarm/command-without-program',
    ProgramWithoutCommand: 'robotarm/program-without-command',
    FileNameMismatch: 'robotarm/file-name-mismatch',
    PackageMismatch: 'robotarm/package-mismatch',
} as const;

export type RobotArmCode = (typeof RobotArmCodes)[keyof typeof RobotArmCodes];
