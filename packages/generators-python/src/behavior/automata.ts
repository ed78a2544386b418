import type { BehaviorGenerator, BehaviorGeneratorFactory, BehaviorView, RuleViolation, WellFormednessRule } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import {
    allStates,
    allTransitions,
    ast,
    automatonTiming,
    sourceOf,
    startState,
    statePath,
    stateActions,
    substates,
    targetOf,
    triggerOf,
} from '@maa/language-automata';
import { renderLines, renderPython } from '../python/templates.js';
import {
    Imports,
    primitiveDefault,
    behaviorTranslator,
    prologueView,
    modulePath,
    readInputs,
    snake,
    specFrom,
    attr,
    type ClassSpec,
} from './common.js';
import type { AutomatonClassView, TransitionView } from './views.js';

/** The module of a component's behavior class. */
export function behaviorModule(packageName: string, componentName: string): { module: string; file: string } {
    return modulePath(packageName, `${snake(componentName)}_behavior`);
}

const str = (s: string): string => JSON.stringify(s);

type Automaton = ast.Automaton;
type State = ast.State;
const { isAutomaton, isState } = ast;

/** The view of the behavior class of an automaton (templates/behavior/automaton.njk). */
export function automatonClassView(automaton: Automaton, spec: ClassSpec, imports: Imports): AutomatonClassView {
    const tr = behaviorTranslator(spec, imports);
    const states = allStates(automaton);
    if (states.length === 0) throw new GenerationError('an automaton without states cannot be translated', automaton);
    const parent = (s: State): State | undefined => (isState(s.$container) ? s.$container : undefined);
    const initialChain = (level: Automaton | State): State[] => {
        const out: State[] = [];
        for (let s = startState(level); s; s = startState(s)) out.push(s);
        return out;
    };
    const top = initialChain(automaton);
    const descendants = (s: State): State[] => [s, ...substates(s).flatMap(descendants)];
    ClassVarImports(imports);

    const prologue = prologueView(spec, imports, 'Behavior of an automaton (generated).', [
        `self._state: str = ${str(top[top.length - 1].name)}`,
    ]);
    const parents = states.map((s) => {
        const p = parent(s);
        return { key: str(s.name), value: p ? str(p.name) : 'None' };
    });
    // Only the initial action of the top-level initial state runs (MontiArc's simulator).
    const initialAction = top[0].initialAction ? tr.stmt(top[0].initialAction) : [];
    const actionsByKind = (['entry', 'exit', 'do'] as const).map((kind) => ({
        kind,
        cases: states.flatMap((s) => {
            const actions = stateActions(s, kind);
            return actions.length === 0 ? [] : [{ state: s.name, body: actions.flatMap((a) => tr.block(a.action)) }];
        }),
    }));

    // transitions: the first enabled one fires
    const sync = spec.timing === 'sync';
    const transitions: TransitionView[] = [];
    for (const [index, t] of allTransitions(automaton).entries()) {
        const source = sourceOf(t);
        const target = targetOf(t);
        if (!source || !target) throw new GenerationError('a transition with an unresolved state cannot be translated', t);
        const conditions: string[] = [];
        const from = descendants(source).map((s) => str(s.name));
        conditions.push(from.length === 1 ? `state == ${from[0]}` : `state in (${from.join(', ')})`);
        if (!sync) {
            const trig = triggerOf(t);
            if (trig.kind === 'port') conditions.push(`event == ${str(trig.name)}`);
            else conditions.push('event is None');
        }
        if (t.guard) conditions.push(tr.expr(t.guard));
        if (t.$type === 'InternalTransition') {
            transitions.push({
                index,
                conditions,
                internal: true,
                exitUntil: null,
                action: t.action ? tr.stmt(t.action) : [],
                entered: [],
            });
            continue;
        }
        const sp = statePath(source);
        const tp = statePath(target);
        let common = 0;
        while (common < sp.length && common < tp.length && sp[common] === tp[common]) common++;
        common = Math.min(common, sp.length - 1, tp.length - 1);
        const exitUntil = common > 0 ? sp[common - 1].name : null;
        const action = t.action ? tr.stmt(t.action) : [];
        const entered = [...tp.slice(common), ...initialChain(target)].map((s) => s.name);
        transitions.push({ index, conditions, internal: false, exitUntil, action, entered });
    }
    const ins = spec.ports.filter((p) => p.direction === 'in');
    return {
        prologue,
        parents,
        initialAction,
        initialStates: top.map((s) => s.name),
        stateActions: actionsByKind,
        transitions,
        sync,
        readInputs: sync ? readInputs(spec) : [],
        inPorts: ins.map((p) => ({ name: p.name, attr: attr(p.name), default: primitiveDefault(p) })),
    };
}

/** Python source of the behavior class of an automaton, as lines. */
export function automatonClass(automaton: Automaton, spec: ClassSpec, imports: Imports): string[] {
    return renderLines('behavior/automaton.njk', automatonClassView(automaton, spec, imports));
}

function ClassVarImports(imports: Imports): void {
    imports.add('typing', 'ClassVar');
}

/** Writes the module of a behavior class. */
export function moduleText(doc: string, imports: Imports, classLines: readonly string[]): string {
    return moduleTextOf(doc, imports, classLines.join('\n'));
}

/** The module of generated classes (templates/behavior/module.py.njk), importing the run-time helpers the classes call. */
export function moduleTextOf(doc: string, imports: Imports, body: string): string {
    for (const helper of ['f32', 'jcall', 'jcast', 'jconcat', 'jdiv', 'jfield', 'jmod', 'jordinal', 'jstatic', 'jstr', 'jushr']) {
        if (new RegExp(`\\b${helper}\\(`).test(body)) imports.add('maa_behavior', helper);
    }
    return renderPython('behavior/module.py.njk', { doc, imports: imports.lines(), body });
}

/** automata.Translatable: what the Python automata generator cannot translate. */
export const translatableRule: WellFormednessRule = {
    name: 'automata.Translatable',
    description:
        'automata have states, and transitions of <<sync>> automata have no events (the Python generators read them as per-slice transitions)',
    *check(scope): Iterable<RuleViolation> {
        for (const b of scope.behaviors) {
            const a = b.node;
            if (b.language !== 'automaton' || !isAutomaton(a)) continue;
            if (allStates(a).length === 0) yield { node: a, message: 'the Python generators cannot translate an automaton without states' };
            if (automatonTiming(a) === 'sync') {
                for (const t of allTransitions(a)) {
                    if (t.event || t.tick)
                        yield {
                            node: t,
                            message: 'a transition of a <<sync>> automaton has no event; the Python generators cannot translate it',
                        };
                }
            }
        }
    },
};

/** The behavior generator; its import lines wrap at `lineLength` (see Imports). */
export function automataGenerator(lineLength?: number): BehaviorGenerator {
    return {
        kind: 'behavior',
        rules: [translatableRule],
        generate(behavior: BehaviorView, ctx) {
            const component = ctx.component;
            if (!component) throw new GenerationError('the automata generator needs the component (requires: component)', behavior.node);
            const automaton = behavior.node;
            if (!isAutomaton(automaton)) throw new GenerationError('not an automaton', automaton);
            const timing = automatonTiming(automaton);
            const spec = specFrom(ctx, component, timing === 'sync' ? 'sync' : timing);
            const imports = new Imports(lineLength);
            const cls = automatonClass(automaton, spec, imports);
            const { module, file } = behaviorModule(component.packageName, component.name);
            const out = ctx.out.file(file);
            out.traced(automaton, () =>
                out.write(
                    moduleText(
                        `Behavior of ${component.qualifiedName}: its automaton (generated by the Python automata generator).`,
                        imports,
                        cls,
                    ),
                ),
            );
            return { module, class: spec.className, timing: spec.timing };
        },
    };
}

const create: BehaviorGeneratorFactory = () => automataGenerator();

export default create;
