/**
 * The stable diagnostic codes of application configurations (`.arcapp`, ARCHITECTURE.md
 * sections 5 and 6). Codes are released API: never rename one. docs/diagnostics.md documents
 * each with examples (APP_DIAGNOSTICS).
 */
export const AppCodes = {
    UnknownComponent: 'app/unknown-component',
    UnknownGenerator: 'app/unknown-generator',
    DuplicatePlatform: 'app/duplicate-platform',
    RepeatedGenerator: 'app/repeated-generator',
    MissingComponentGenerator: 'app/missing-component-generator',
    DuplicateComponentGenerator: 'app/duplicate-component-generator',
    MissingDataTypeGenerator: 'app/missing-datatype-generator',
    DuplicateDataTypeGenerator: 'app/duplicate-datatype-generator',
    UncoveredBehaviorLanguage: 'app/uncovered-behavior-language',
    DuplicateBehaviorGenerator: 'app/duplicate-behavior-generator',
    GplMismatch: 'app/gpl-mismatch',
    RteMismatch: 'app/rte-mismatch',
    GeneratorRuleViolated: 'app/generator-rule-violated',
    UnknownFeature: 'app/unknown-feature',
    FeatureConfigurationExcluded: 'app/feature-configuration-excluded',
} as const;

export type AppCode = (typeof AppCodes)[keyof typeof AppCodes];
