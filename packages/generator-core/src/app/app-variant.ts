import { allFeatures, configurationSpace, isVariable, type VariantEnv, type ast } from '@maa/language-adl';
import type { Application } from '../generated/ast.js';
import type { AppFinding } from './app-checks.js';
import { AppCodes } from './codes.js';

/** The feature configuration an application selects, and what is wrong with it. */
export interface ApplicationVariant {
    readonly env?: VariantEnv;
    readonly findings: AppFinding[];
}

/**
 * The feature configuration an application generates (`application A for C(f = true) { ... }`):
 * the configuration of the root component's constraints that binds the listed features as
 * given, the others (and the features of subcomponents the constraints leave open) taking the
 * first admitted values, `false` before `true`. Undefined without variability. The configuration
 * is per instance: two instances of one type may be configured differently (`Lamp a(dimmable =
 * true); Lamp b(dimmable = false);`), and generation then emits one variant of the type per
 * configuration (model/architecture.ts, `variantName`).
 */
export function applicationVariant(app: Application): ApplicationVariant {
    const root = app.component?.ref as unknown as ast.ComponentType | undefined;
    const findings: AppFinding[] = [];
    if (!root) return { findings };
    const features = new Set(allFeatures(root).map((f) => f.name));
    for (const b of app.features) {
        if (!features.has(b.feature)) {
            findings.push({
                code: AppCodes.UnknownFeature,
                severity: 'error',
                node: b,
                property: 'feature',
                message: `Component '${root.name}' has no feature '${b.feature}'${features.size > 0 ? `; its features are ${[...features].map((f) => `'${f}'`).join(', ')}` : ''}.`,
            });
        }
    }
    if (findings.length > 0 || (app.features.length === 0 && !isVariable(root, new Map()))) return { findings };
    const space = configurationSpace(root);
    if (space.tooLarge) {
        findings.push({
            code: AppCodes.FeatureConfigurationExcluded,
            severity: 'error',
            node: app,
            property: 'component',
            message: `The configurations of component '${root.name}' are too many to enumerate (variability/too-many-features); it cannot be generated.`,
        });
        return { findings };
    }
    const chosen = space.configurations.find((a) => app.features.every((b) => space.value(a, b.feature) === (b.value === 'true')));
    if (chosen === undefined) {
        const node = app.features[0] ?? app;
        findings.push({
            code: AppCodes.FeatureConfigurationExcluded,
            severity: 'error',
            node,
            ...(app.features[0] ? {} : { property: 'component' }),
            message:
                app.features.length > 0
                    ? `The constraints of component '${root.name}' admit no configuration with ${app.features.map((b) => `${b.feature} = ${b.value}`).join(', ')}.`
                    : `The constraints of component '${root.name}' admit no configuration.`,
        });
        return { findings };
    }
    // Instances of one type may differ: each configuration of a type becomes a variant of it (buildArchitecture).
    return { env: space.generationEnv(chosen), findings };
}
