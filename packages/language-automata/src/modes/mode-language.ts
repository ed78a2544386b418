import type { AstNode, ReferenceInfo, Scope } from 'langium';
import {
    allPorts,
    enclosingComponent,
    subcomponentsOf,
    type AdlDocumentValidator,
    type AdlScopeProvider,
    type AdlServices,
} from '@maa/language-adl';
import { AutomatonCodes } from '../codes.js';
import { ModeChecks } from './mode-checks.js';
import { enclosingMode, enclosingModeAutomaton, modesOf, modeSubcomponents } from './mode-model.js';

/**
 * Installs mode automata into the host's services (called by AutomataLanguage.register):
 * - scopes: a mode transition's source and target are modes of its mode automaton; its event is
 *   an incoming port of the component; a connector inside a mode sees the component's
 *   subcomponents and those of its own mode (not those of other modes);
 * - codes for unresolved modes and events;
 * - the `mode/*` checks.
 */
export function registerModes(services: AdlServices): void {
    const scopes = services.references.ScopeProvider as AdlScopeProvider;
    const modes = (ctx: ReferenceInfo): Scope =>
        scopes.nodes(() => {
            const a = enclosingModeAutomaton(ctx.container);
            return a ? modesOf(a) : [];
        });
    scopes.contributions.set('ModeTransition.source', modes);
    scopes.contributions.set('ModeTransition.target', modes);
    scopes.contributions.set('ModeTransition.event', (ctx) => scopes.nodes(() => incomingPorts(ctx.container)));
    // Outside modes this is the host's own scope (the component's subcomponents).
    scopes.contributions.set('PortAccess.subcomponent', (ctx) =>
        scopes.nodes(() => {
            const comp = enclosingComponent(ctx.container);
            const own = comp ? subcomponentsOf(comp) : [];
            const mode = enclosingMode(ctx.container);
            return mode ? [...modeSubcomponents(mode), ...own] : own;
        }),
    );

    const validator = services.validation.DocumentValidator as AdlDocumentValidator;
    const missingMode = {
        code: AutomatonCodes.MissingState,
        message: (name: string) => `Mode '${name}' does not exist in this mode automaton.`,
    };
    validator.linkCodes.set('ModeTransition.source', missingMode);
    validator.linkCodes.set('ModeTransition.target', missingMode);
    validator.linkCodes.set('ModeTransition.event', {
        code: AutomatonCodes.MissingEvent,
        message: (name: string) =>
            `'${name}' is not an incoming port of the component: a mode transition is triggered by an incoming port or by 'Tick'.`,
    });

    const checks = new ModeChecks(services);
    services.validation.ValidationRegistry.register(checks.checks, checks);
}

/** The incoming ports of the component that encloses a node, inherited ones included. */
function incomingPorts(node: AstNode): AstNode[] {
    const component = enclosingComponent(node);
    return component
        ? allPorts(component)
              .filter((p) => p.direction === 'in')
              .map((p) => p.port)
        : [];
}
