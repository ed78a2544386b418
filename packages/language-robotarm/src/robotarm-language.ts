import type { ReferenceInfo, Scope } from 'langium';
import type { AdlDocumentValidator, AdlScopeProvider, AdlServices, BehaviorLanguage, LanguageRegistration } from '@maa/language-adl';
import { ROBOTARM_DIAGNOSTICS } from './diagnostic-catalog/robotarm-diagnostics.js';
import { RobotArmChecks } from './robotarm-checks.js';
import { enclosingRobotArm, moveTargetsOf } from './robotarm-model.js';
import { RobotArmCodes } from './codes.js';
import { registerRobotArmLsp } from './lsp/robotarm-lsp.js';

/** The reference `move x` of a `MoveArgument` (scope and link-code key: `ContainerType.property`). */
const MOVE_TARGET = 'MoveArgument.target';

/**
 * Installs RobotArm into the services of one language of the family: the scope of the names
 * after `move` (locations of the body, then its inputs in a `.ra` file or, embedded, the incoming
 * ports of the component: the paper's Port2InputAdapter, contributed here by the integration),
 * the code for names that resolve to nothing, and the checks.
 */
function install(services: AdlServices, unresolved: (name: string) => string): void {
    const scopes = services.references.ScopeProvider as AdlScopeProvider;
    scopes.contributions.set(
        MOVE_TARGET,
        (ctx: ReferenceInfo): Scope =>
            scopes.nodes(() => {
                const body = enclosingRobotArm(ctx.container);
                return body ? moveTargetsOf(body) : [];
            }),
    );
    const validator = services.validation.DocumentValidator as AdlDocumentValidator;
    validator.linkCodes.set(MOVE_TARGET, { code: RobotArmCodes.UnresolvedName, message: unresolved });
    const checks = new RobotArmChecks(services);
    services.validation.ValidationRegistry.register(checks.checks, checks);
}

/**
 * The embedded `robotarm { }` block as registered in a language family (grammar rule `RobotArm`,
 * package.json `maa.language.behavior`), installed into the services of the host language `arc`.
 */
export const RobotArmLanguage: BehaviorLanguage = {
    name: 'robotarm',
    keyword: 'robotarm',
    astType: 'RobotArm',
    diagnostics: ROBOTARM_DIAGNOSTICS,
    register(services: AdlServices): void {
        install(
            services,
            (name) =>
                `'${name}' is neither a location of this robotarm block, nor a constant ('top', 'bottom'), nor an incoming port of the component.`,
        );
    },
    registerLsp: registerRobotArmLsp,
};

/**
 * Standalone `.ra` files (language id `ra`, package.json `maa.language.languages`): the family
 * creates a service container for them (with the host's scoping and typing) and calls `register`.
 */
export const RobotArmFileLanguage: LanguageRegistration = {
    languageId: 'ra',
    register(services: AdlServices): void {
        install(services, (name) => `'${name}' is neither a location nor an input of this robot arm, nor a constant ('top', 'bottom').`);
    },
    registerLsp: registerRobotArmLsp,
};
