import { AstUtils, CstUtils, type AstNode, type ValidationAcceptor, type ValidationChecks } from 'langium';
import type { Range } from 'vscode-languageserver-types';
import {
    Codes,
    ExpressionChecks,
    isErroneous,
    printType,
    type AdlServices,
    type ReservedNames,
    type TypeRelations,
} from '@maa/language-adl';
import type { Automaton, AutomataAstType, Expression, State } from './generated/ast.js';
import { isNameExpression } from './generated/ast.js';
import {
    allStates,
    allTransitions,
    automatonTiming,
    describeTransition,
    enclosingAutomaton,
    initialStates,
    isHierarchical,
    isIncomingPort,
    sourceOf,
    substates,
    transitionHead,
    triggerOf,
    type AnyTransition,
} from './automaton-model.js';
import { AutomatonCodes } from './codes.js';

/**
 * The context conditions of embedded automata (ARCHITECTURE.md section 5, `automaton/*`).
 * Statements inside actions are checked by the host (its checks run on every statement node);
 * guards are plain expressions the host does not see, so they are typed here.
 */
export class AutomatonChecks {
    private readonly expressions: ExpressionChecks;
    private readonly rel: TypeRelations;
    private readonly reserved: ReservedNames;

    constructor(services: AdlServices) {
        this.expressions = new ExpressionChecks(services);
        this.rel = services.maa.TypeRelations;
        this.reserved = services.shared.maa.ReservedNames;
    }

    readonly checks: ValidationChecks<AutomataAstType> = {
        Automaton: (a, accept) => {
            this.checkTopLevelInitial(a, accept);
            this.checkUniqueStates(a, accept);
            this.checkDeterminism(a, accept);
        },
        State: (s, accept) => {
            this.checkReservedName(s, accept);
            this.checkNestedInitial(s, accept);
            this.checkInitialAction(s, accept);
        },
        Transition: (t, accept) => this.checkTransition(t, accept),
        InternalTransition: (t, accept) => this.checkTransition(t, accept),
    };

    // ---- states ----

    private checkTopLevelInitial(a: Automaton, accept: ValidationAcceptor): void {
        const initial = initialStates(a);
        if (initial.length === 0) {
            const states = substates(a);
            const hint =
                states.length === 0
                    ? "declare one, e.g. 'initial state Idle;'"
                    : `mark one of its top-level states 'initial' (e.g. 'initial state ${states[0]!.name};')`;
            accept('error', `The automaton has no initial state: ${hint}.`, {
                node: a,
                keyword: 'automaton',
                code: AutomatonCodes.NoInitialState,
            });
        }
        for (const extra of initial.slice(1)) {
            accept(
                'error',
                `The automaton has more than one initial state ('${initial.map((s) => s.name).join("', '")}'): exactly one top-level state may be initial.`,
                { node: extra, keyword: 'initial', code: AutomatonCodes.MultipleInitialStates },
            );
        }
    }

    /**
     * Inside a hierarchical state these are warnings: MontiArc accepts such models (its simulator
     * enters the first substate, or the first initial one), and its own example models use them.
     */
    private checkNestedInitial(s: State, accept: ValidationAcceptor): void {
        if (!isHierarchical(s)) return;
        const initial = initialStates(s);
        if (initial.length === 0) {
            accept(
                'warning',
                `Hierarchical state '${s.name}' has no initial substate: entering it enters its first substate '${substates(s)[0]!.name}'. Mark one substate 'initial'.`,
                { node: s, property: 'name', code: AutomatonCodes.NoInitialState },
            );
        }
        for (const extra of initial.slice(1)) {
            accept(
                'warning',
                `Hierarchical state '${s.name}' has more than one initial substate ('${initial.map((i) => i.name).join("', '")}'): entering it enters '${initial[0]!.name}'.`,
                { node: extra, keyword: 'initial', code: AutomatonCodes.MultipleInitialStates },
            );
        }
    }

    private checkUniqueStates(a: Automaton, accept: ValidationAcceptor): void {
        const seen = new Map<string, State>();
        for (const s of allStates(a)) {
            if (!s.name) continue;
            const first = seen.get(s.name);
            if (first) {
                accept(
                    'error',
                    `State '${s.name}' is already declared in this automaton (line ${line(first)}): state names are unique in the whole automaton, substates included.`,
                    { node: s, property: 'name', code: AutomatonCodes.DuplicateState },
                );
            } else seen.set(s.name, s);
        }
    }

    private checkReservedName(s: State, accept: ValidationAcceptor): void {
        if (!s.name) return;
        const reason = this.reserved.reason('state', s.name, AstUtils.getDocument(s).uri);
        if (reason)
            accept('error', `The state name '${s.name}' is reserved: ${reason}.`, { node: s, property: 'name', code: Codes.ReservedName });
    }

    /** The initial action runs before any input arrives: it may write outgoing ports, never read incoming ones. */
    private checkInitialAction(s: State, accept: ValidationAcceptor): void {
        if (!s.initialAction) return;
        for (const n of AstUtils.streamAllContents(s.initialAction)) {
            if (isNameExpression(n) && isIncomingPort(n.ref?.ref)) {
                accept(
                    'error',
                    `Incoming port '${n.ref?.$refText ?? ''}' cannot be read in the initial action of state '${s.name}': it runs before the first input arrives (outgoing ports may be written there).`,
                    { node: n, code: AutomatonCodes.InputInInitial },
                );
            }
        }
    }

    // ---- transitions ----

    private checkTransition(t: AnyTransition, accept: ValidationAcceptor): void {
        if (t.guard) this.checkGuard(t, t.guard, accept);
        const a = enclosingAutomaton(t);
        if (!a) return;
        const timing = automatonTiming(a);
        const trigger = triggerOf(t);
        if (timing === 'sync' && trigger.kind !== 'none') {
            const what = trigger.kind === 'tick' ? "'Tick'" : `port '${trigger.name}'`;
            accept(
                'error',
                `The ${describeTransition(t)} of a <<sync>> automaton cannot have an event (${what}): a sync automaton fires once per time slice on all inputs; test inputs in the guard instead.`,
                trigger.kind === 'tick'
                    ? { node: t, keyword: 'Tick', code: AutomatonCodes.EventInSync }
                    : { node: t, property: 'event', code: AutomatonCodes.EventInSync },
            );
        }
        if (timing === 'untimed' && trigger.kind === 'tick') {
            accept(
                'error',
                `The ${describeTransition(t)} of an <<untimed>> automaton cannot be triggered by 'Tick': untimed automata do not observe time; use an incoming port as event.`,
                { node: t, keyword: 'Tick', code: AutomatonCodes.TickInUntimed },
            );
        }
        if (timing === 'untimed' && trigger.kind === 'none') {
            accept(
                'error',
                `The ${describeTransition(t)} of an <<untimed>> automaton needs an event: untimed automata react to messages only, so name the incoming port that triggers it.`,
                { node: t, range: headRange(t), code: AutomatonCodes.UntimedNoEvent },
            );
        }
    }

    private checkGuard(t: AnyTransition, guard: Expression, accept: ValidationAcceptor): void {
        const type = this.expressions.checkExpression(guard as Parameters<ExpressionChecks['checkExpression']>[0], accept);
        if (!isErroneous(type) && !this.rel.isBoolean(type)) {
            accept(
                'error',
                `The guard of the ${describeTransition(t)} must be of type boolean, but '${text(guard)}' is of type ${printType(type)}.`,
                { node: guard, code: AutomatonCodes.GuardNotBoolean },
            );
        }
    }

    /**
     * Warns about two transitions that may be enabled at once, conservatively: they start in the
     * same state, have the same trigger (the same incoming port; or, in a timed automaton, both
     * the tick: `Tick` or no event; or, in a sync automaton, any), and either at most one of them
     * has a guard or their guards are the same expression (token by token). Guards that differ
     * in any other way are assumed to exclude each other; transitions of a superstate and of its
     * substates are not compared.
     */
    private checkDeterminism(a: Automaton, accept: ValidationAcceptor): void {
        const timing = automatonTiming(a);
        const groups = new Map<string, AnyTransition[]>();
        const ids = new Map<State, number>();
        for (const t of allTransitions(a)) {
            const source = sourceOf(t);
            if (!source) continue;
            const key = triggerKey(t, timing);
            if (key === undefined) continue;
            if (!ids.has(source)) ids.set(source, ids.size);
            const groupKey = `${ids.get(source)}|${key}`;
            const group = groups.get(groupKey) ?? [];
            group.push(t);
            groups.set(groupKey, group);
        }
        for (const group of groups.values()) {
            for (let j = 1; j < group.length; j++) {
                const later = group[j]!;
                for (let i = 0; i < j; i++) {
                    const earlier = group[i]!;
                    const reason = overlapReason(earlier, later);
                    if (!reason) continue;
                    const source = sourceOf(later)!;
                    const uri = AstUtils.getDocument(a).uri.toString();
                    const earlierRange = headRange(earlier);
                    accept(
                        'warning',
                        `The ${describeTransition(later)} may be enabled together with the ${describeTransition(earlier)} (line ${line(earlier)}): both start in state '${source.name}' on ${triggerText(later, timing)} and ${reason}. The first declared transition takes precedence.`,
                        {
                            node: later,
                            range: headRange(later),
                            code: AutomatonCodes.Nondeterministic,
                            relatedInformation: earlierRange
                                ? [{ location: { uri, range: earlierRange }, message: `the ${describeTransition(earlier)}` }]
                                : undefined,
                        },
                    );
                    break;
                }
            }
        }
    }
}

function triggerKey(t: AnyTransition, timing: string): string | undefined {
    if (timing === 'sync') return 'slice';
    const trigger = triggerOf(t);
    switch (trigger.kind) {
        case 'port':
            return trigger.port ? `port:${trigger.name}` : undefined;
        case 'tick':
        case 'none':
            // In an untimed automaton these are errors already.
            return timing === 'untimed' ? undefined : 'tick';
    }
}

function triggerText(t: AnyTransition, timing: string): string {
    if (timing === 'sync') return 'every time slice';
    const trigger = triggerOf(t);
    return trigger.kind === 'port' ? `a message on '${trigger.name}'` : 'the tick';
}

function overlapReason(earlier: AnyTransition, later: AnyTransition): string | undefined {
    if (!earlier.guard && !later.guard) return 'neither has a guard';
    if (!earlier.guard) return `the ${describeTransition(earlier)} has no guard`;
    if (!later.guard) return `the ${describeTransition(later)} has no guard`;
    return tokens(earlier.guard) === tokens(later.guard) ? `their guards are the same ('${text(later.guard)}')` : undefined;
}

/** An expression's tokens without whitespace and comments, for syntactic comparison. */
function tokens(e: AstNode): string {
    const cst = e.$cstNode;
    return cst
        ? CstUtils.flattenCst(cst)
              .filter((l) => !l.hidden)
              .map((l) => l.text)
              .join(' ')
        : '';
}

function text(e: AstNode): string {
    return e.$cstNode?.text ?? '';
}

function line(n: AstNode): number {
    return (n.$cstNode?.range.start.line ?? 0) + 1;
}

function headRange(t: AnyTransition): Range | undefined {
    const head = transitionHead(t);
    return head ? { start: head.start.range.start, end: head.end.range.end } : t.$cstNode?.range;
}
