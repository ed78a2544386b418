/**
 * The stable diagnostic codes of the host language (ARCHITECTURE.md section 5). Codes are
 * released API: never rename one. docs/diagnostics.md documents each with examples.
 */
export const Codes = {
    SyntaxToken: 'syntax/unexpected-character',
    SyntaxUnexpected: 'syntax/unexpected-token',
    SyntaxUnexpectedEnd: 'syntax/unexpected-end',
    LinkUnresolved: 'link/unresolved-reference',

    FileNameMismatch: 'arc/file-name-mismatch',
    PackageMismatch: 'arc/package-mismatch',
    UnresolvedType: 'arc/unresolved-type',
    MissingComponentType: 'arc/missing-component-type',
    CircularInheritance: 'arc/circular-inheritance',
    SubcomponentCycle: 'arc/subcomponent-cycle',
    RootInstantiated: 'arc/root-instantiated',
    DuplicateName: 'arc/duplicate-name',
    ReservedName: 'arc/reserved-name',
    MissingPort: 'arc/missing-port',
    MissingSubcomponent: 'arc/missing-subcomponent',
    SourceDirectionMismatch: 'arc/source-direction-mismatch',
    TargetDirectionMismatch: 'arc/target-direction-mismatch',
    ConnectorTypeMismatch: 'arc/connector-type-mismatch',
    TimingMismatch: 'arc/timing-mismatch',
    MultipleTimings: 'arc/multiple-timings',
    MultipleSenders: 'arc/multiple-senders',
    UnconnectedSubInPort: 'arc/unconnected-sub-in-port',
    UnconnectedSubOutPort: 'arc/unconnected-sub-out-port',
    UnusedInPort: 'arc/unused-in-port',
    UnusedOutPort: 'arc/unused-out-port',
    ConnectorInAtomic: 'arc/connector-in-atomic',
    MultipleBehaviors: 'arc/multiple-behaviors',
    DelayedInPort: 'arc/delayed-in-port',
    FeedbackNotCausal: 'arc/feedback-not-causal',
    TooFewArguments: 'arc/too-few-arguments',
    TooManyArguments: 'arc/too-many-arguments',
    ArgumentTypeMismatch: 'arc/argument-type-mismatch',
    UnknownArgumentKey: 'arc/unknown-argument-key',
    ArgumentMultipleValues: 'arc/argument-multiple-values',
    PositionalAfterKey: 'arc/positional-after-key',
    AssignmentInArgument: 'arc/assignment-in-argument',
    OptionalParamsLast: 'arc/optional-params-last',
    PortInStaticContext: 'arc/port-in-static-context',
    FieldInitTypeMismatch: 'arc/field-init-type-mismatch',
    ParamDefaultTypeMismatch: 'arc/param-default-type-mismatch',
    InheritedPortTypeMismatch: 'arc/inherited-port-type-mismatch',
    InheritedPortDirectionMismatch: 'arc/inherited-port-direction-mismatch',
    TypeArgBound: 'arc/type-arg-bound',
    TooFewTypeArgs: 'arc/too-few-type-args',
    TooManyTypeArgs: 'arc/too-many-type-args',
    RawGeneric: 'arc/raw-generic',
    NamingConvention: 'arc/naming-convention',
    UnknownStereotype: 'arc/unknown-stereotype',

    ExprTypeMismatch: 'expr/type-mismatch',
    ExprUnresolvedName: 'expr/unresolved-name',

    CdDuplicateName: 'cd/duplicate-name',
    CdFileNameMismatch: 'cd/file-name-mismatch',
    CdPackageMismatch: 'cd/package-mismatch'
} as const;

export type Code = (typeof Codes)[keyof typeof Codes];
