import type { ValidationAcceptor, ValidationChecks } from 'langium';
import {
    Codes,
    ExpressionChecks,
    isErroneous,
    printType,
    subcomponentsOf,
    type AdlServices,
    type ast as adl,
    type TypeRelations,
} from '@maa/language-adl';
import type { AutomataAstType, Automaton, ComponentType, Mode, ModeAutomaton, ModeTransition, State } from '../generated/ast.js';
import { isMode, isState } from '../generated/ast.js';
import { AutomatonCodes } from '../codes.js';
import {
    initialModes,
    isDecomposedWithModes,
    modeAutomataOf,
    modeAutomatonTiming,
    modesOf,
    modeSubcomponents,
    enclosingModeAutomaton,
} from './mode-model.js';
import { ModeCodes } from './mode-codes.js';
import { ModeConnectorChecks } from './mode-connector-checks.js';

/**
 * The context conditions of mode automata, after MontiArc's ArcMode cocos: at most one mode
 * automaton, only in decomposed components; no states in mode automata and no modes in
 * automata; no port declarations in modes; exactly one initial mode; unique mode names; mode
 * transitions typed like automaton transitions. Also MontiArc's UnsupportedAutomatonElements:
 * `final` states are parsed but have no meaning for the generators (a warning).
 */
export class ModeChecks {
    private readonly expressions: ExpressionChecks;
    private readonly rel: TypeRelations;
    private readonly connectors: ModeConnectorChecks;

    constructor(services: AdlServices) {
        this.expressions = new ExpressionChecks(services);
        this.rel = services.maa.TypeRelations;
        this.connectors = new ModeConnectorChecks(this.rel);
    }

    readonly checks: ValidationChecks<AutomataAstType> = {
        ComponentType: (c, accept) => this.checkComponent(c, accept),
        ModeAutomaton: (a, accept) => this.checkModeAutomaton(a, accept),
        Mode: (m, accept) => {
            this.checkMode(m, accept);
            this.connectors.check(m, accept);
        },
        ModeTransition: (t, accept) => this.checkTransition(t, accept),
        Automaton: (a, accept) => this.checkAutomaton(a, accept),
        State: (s, accept) => this.checkFinal(s, accept),
    };

    private checkComponent(c: ComponentType, accept: ValidationAcceptor): void {
        const automata = modeAutomataOf(c);
        if (automata.length === 0) return;
        if (!isDecomposedWithModes(c)) {
            for (const a of automata) {
                accept(
                    'error',
                    `Component '${c.name}' is atomic: a mode automaton switches between configurations of subcomponents and connectors, so only a decomposed component (one with subcomponents) may declare one.`,
                    { node: a, keyword: 'mode', code: ModeCodes.ModeAutomatonInAtomic },
                );
            }
            return;
        }
        for (const extra of automata.slice(1)) {
            accept(
                'error',
                `Component '${c.name}' declares more than one mode automaton: at most one is allowed; put all modes into one.`,
                { node: extra, keyword: 'mode', code: ModeCodes.MultipleModeAutomata },
            );
        }
        // All subcomponents exist at once (modes switch their connectors): one namespace.
        const seen = new Set(subcomponentsOf(c as adl.ComponentType).map((x) => x.name));
        for (const m of automata.flatMap(modesOf)) {
            for (const sub of modeSubcomponents(m)) {
                if (!sub.name) continue;
                if (seen.has(sub.name)) {
                    accept(
                        'error',
                        `Component '${c.name}' declares the subcomponent name '${sub.name}' more than once (in mode '${m.name}' here): the subcomponents of the component and of all its modes exist at the same time, so their names are unique.`,
                        { node: sub, property: 'name', code: Codes.DuplicateName },
                    );
                } else seen.add(sub.name);
            }
        }
    }

    private checkModeAutomaton(a: ModeAutomaton, accept: ValidationAcceptor): void {
        const modes = modesOf(a);
        const initial = initialModes(a);
        if (initial.length === 0) {
            const hint =
                modes.length === 0
                    ? "declare one, e.g. 'initial mode Normal { }'"
                    : `mark one mode 'initial' (e.g. 'initial mode ${modes[0]!.name} { ... }')`;
            accept('error', `The mode automaton has no initial mode: ${hint}.`, {
                node: a,
                keyword: 'automaton',
                code: AutomatonCodes.NoInitialState,
            });
        }
        for (const extra of initial.slice(1)) {
            accept(
                'error',
                `The mode automaton has more than one initial mode ('${initial.map((m) => m.name).join("', '")}'): exactly one mode may be initial.`,
                { node: extra, keyword: 'initial', code: AutomatonCodes.MultipleInitialStates },
            );
        }
        const seen = new Map<string, Mode>();
        for (const m of modes) {
            if (!m.name) continue;
            if (seen.has(m.name)) {
                accept('error', `Mode '${m.name}' is already declared in this mode automaton: mode names are unique.`, {
                    node: m,
                    property: 'name',
                    code: AutomatonCodes.DuplicateState,
                });
            } else seen.set(m.name, m);
        }
        for (const s of a.elements.filter((e): e is State => isState(e))) {
            accept(
                'error',
                `A mode automaton contains modes, not states: '${s.name}' is a state; declare it as 'mode ${s.name} { ... }' or move it into an automaton.`,
                { node: s, keyword: 'state', code: ModeCodes.StateInModeAutomaton },
            );
        }
    }

    private checkMode(m: Mode, accept: ValidationAcceptor): void {
        for (const e of m.elements) {
            if (e.$type === 'PortDeclaration') {
                accept(
                    'error',
                    `Mode '${m.name}' declares a port: modes switch subcomponents and connectors, while the component's interface stays the same in every mode; declare the port in the component.`,
                    { node: e, code: ModeCodes.PortInMode },
                );
            }
        }
    }

    private checkAutomaton(a: Automaton, accept: ValidationAcceptor): void {
        for (const m of a.elements.filter((e): e is Mode => isMode(e))) {
            accept(
                'error',
                `An automaton (statechart) contains states, not modes: '${m.name}' is a mode; modes belong into a 'mode automaton' of a decomposed component.`,
                { node: m, keyword: 'mode', code: ModeCodes.ModeInStatechart },
            );
        }
    }

    private checkFinal(s: State, accept: ValidationAcceptor): void {
        if (s.final) {
            accept(
                'warning',
                `Final states are not supported: an automaton of a component runs forever, so 'final' on state '${s.name}' has no effect.`,
                { node: s, keyword: 'final', code: AutomatonCodes.UnsupportedElement },
            );
        }
    }

    private checkTransition(t: ModeTransition, accept: ValidationAcceptor): void {
        const what = `mode transition '${t.source?.$refText ?? '?'} -> ${t.target?.$refText ?? '?'}'`;
        if (t.guard) {
            const type = this.expressions.checkExpression(t.guard as Parameters<ExpressionChecks['checkExpression']>[0], accept);
            if (!isErroneous(type) && !this.rel.isBoolean(type)) {
                accept(
                    'error',
                    `The guard of the ${what} must be of type boolean, but '${t.guard.$cstNode?.text ?? ''}' is of type ${printType(type)}.`,
                    { node: t.guard, code: AutomatonCodes.GuardNotBoolean },
                );
            }
        }
        if (t.action) {
            accept(
                'warning',
                `The action of the ${what} is ignored: a decomposed component computes nothing itself (its subcomponents do); switch modes without an action.`,
                { node: t.action, code: AutomatonCodes.UnsupportedElement },
            );
        }
        const a = enclosingModeAutomaton(t);
        if (a && modeAutomatonTiming(a) === 'sync' && (t.tick || t.event)) {
            accept(
                'error',
                `The ${what} of a <<sync>> mode automaton cannot have an event: it is taken once per time slice; test inputs in the guard instead.`,
                t.tick
                    ? { node: t, keyword: 'Tick', code: AutomatonCodes.EventInSync }
                    : { node: t, property: 'event', code: AutomatonCodes.EventInSync },
            );
        }
    }
}
