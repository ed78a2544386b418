import type { AstNode, ReferenceInfo, Scope } from 'langium';
import {
    allPorts,
    enclosingComponent,
    type AdlDocumentValidator,
    type AdlScopeProvider,
    type AdlServices,
    type BehaviorLanguage,
} from '@maa/language-adl';
import { allStates, enclosingAutomaton } from './automaton-model.js';
import { AutomatonChecks } from './automaton-checks.js';
import { registerModes } from './modes/mode-language.js';
import { registerModeLsp } from './modes/mode-lsp.js';
import { AutomatonCodes } from './codes.js';
import { AUTOMATON_DIAGNOSTICS } from './diagnostic-catalog/automaton-diagnostics.js';
import { registerAutomatonLsp } from './lsp/automaton-lsp.js';

/**
 * The automaton language as registered in a language family: the `automaton { }` block
 * (grammar rule `Automaton`, see package.json `maa.language.behavior`) plus the run-time parts,
 * installed into the host language's services:
 * - scopes: a transition's source and target are states of its automaton (one flat namespace,
 *   substates included, as in MontiArc); its event is an incoming port of the enclosing
 *   component, inherited ports included (`Tick` is a keyword, not a reference);
 * - codes for unresolved states and events;
 * - the `automaton/*` checks.
 */
export const AutomataLanguage: BehaviorLanguage = {
    name: 'automaton',
    keyword: 'automaton',
    astType: 'Automaton',
    diagnostics: AUTOMATON_DIAGNOSTICS,
    register(services: AdlServices): void {
        const scopes = services.references.ScopeProvider as AdlScopeProvider;
        const states = (ctx: ReferenceInfo): Scope =>
            scopes.nodes(() => {
                const a = enclosingAutomaton(ctx.container);
                return a ? allStates(a) : [];
            });
        const events = (ctx: ReferenceInfo): Scope => scopes.nodes(() => incomingPorts(ctx.container));
        scopes.contributions.set('Transition.source', states);
        scopes.contributions.set('Transition.target', states);
        scopes.contributions.set('Transition.event', events);
        scopes.contributions.set('InternalTransition.event', events);

        const validator = services.validation.DocumentValidator as AdlDocumentValidator;
        const missingState = {
            code: AutomatonCodes.MissingState,
            message: (name: string) => `State '${name}' does not exist in this automaton.`,
        };
        const missingEvent = {
            code: AutomatonCodes.MissingEvent,
            message: (name: string) =>
                `'${name}' is not an incoming port of the component: a transition is triggered by an incoming port or by 'Tick'.`,
        };
        validator.linkCodes.set('Transition.source', missingState);
        validator.linkCodes.set('Transition.target', missingState);
        validator.linkCodes.set('Transition.event', missingEvent);
        validator.linkCodes.set('InternalTransition.event', missingEvent);

        const checks = new AutomatonChecks(services);
        services.validation.ValidationRegistry.register(checks.checks, checks);
        registerModes(services);
    },
    registerLsp(services) {
        registerAutomatonLsp(services);
        registerModeLsp(services);
    },
};

/** The incoming ports of the component that encloses a node, inherited ones included. */
function incomingPorts(node: AstNode): AstNode[] {
    const component = enclosingComponent(node);
    return component
        ? allPorts(component)
              .filter((p) => p.direction === 'in')
              .map((p) => p.port)
        : [];
}
