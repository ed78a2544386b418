import { AstUtils, type LangiumSharedCoreServices } from 'langium';
import type { Application } from '../generated/ast.js';
import type { ArchitectureModel } from '../model/architecture.js';
import type { GeneratorRegistry } from '../registry/registry.js';
import type { GeneratorRegistryService } from '../registry/registry-service.js';
import { applicationArchitecture, checkApplication, type AppFinding } from './app-checks.js';
import { applicationVariant, type ApplicationVariant } from './app-variant.js';

/**
 * What the `app/*` checks found on one application configuration, with what they were computed
 * from: the registry, the feature configuration and the architecture model. Computed once per
 * configuration and workspace build, by the document validator (the editor's check) or by
 * generation, whichever comes first; generation reuses it instead of checking again.
 */
export interface ApplicationAnalysis {
    readonly registry: GeneratorRegistry;
    readonly variant: ApplicationVariant;
    /** Undefined while the application's component does not resolve. */
    readonly architecture: ArchitectureModel | undefined;
    /** The findings of checkApplication on every platform with the standard rules (variant findings first). */
    readonly findings: readonly AppFinding[];
}

/**
 * The analysis of the family's application configurations (`services.generators.Applications`):
 * memoized per Application node until the workspace changes or the registry does.
 */
export class ApplicationAnalyzer {
    private analyses = new WeakMap<Application, ApplicationAnalysis>();

    constructor(
        shared: LangiumSharedCoreServices,
        private readonly registries: GeneratorRegistryService,
    ) {
        // A change elsewhere relinks an unchanged configuration (same nodes, other targets).
        shared.workspace.DocumentBuilder.onUpdate(() => {
            this.analyses = new WeakMap();
        });
    }

    analyze(app: Application): ApplicationAnalysis {
        const registry = this.registries.registryFor(AstUtils.getDocument(app).uri);
        const known = this.analyses.get(app);
        if (known && known.registry === registry) return known;
        const variant = applicationVariant(app);
        const architecture = applicationArchitecture(app, variant);
        const findings = checkApplication(app, registry, { variant, ...(architecture ? { architecture } : {}) });
        const analysis: ApplicationAnalysis = { registry, variant, architecture, findings };
        this.analyses.set(app, analysis);
        return analysis;
    }
}
