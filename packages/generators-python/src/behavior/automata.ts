import type { BehaviorGeneratorFactory, BehaviorView, RuleViolation, WellFormednessRule } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import {
    allStates, allTransitions, automatonTiming, enclosingAutomaton, sourceOf, startState, statePath, stateActions, substates, targetOf, triggerOf
} from '@maa/language-automata';
import type { Node } from '../python/expressions.js';
import { Imports, primitiveDefault, behaviorTranslator, classPrologue, indent, modulePath, readInputs, snake, specFrom, attr, type ClassSpec } from './common.js';

/** The module of a component's behavior class. */
export function behaviorModule(packageName: string, componentName: string): { module: string; file: string } {
    return modulePath(packageName, `${snake(componentName)}_behavior`);
}

const str = (s: string): string => JSON.stringify(s);

/** Python source of the behavior class of an automaton. */
export function automatonClass(automaton: Node, spec: ClassSpec, imports: Imports): string[] {
    const tr = behaviorTranslator(spec, imports);
    const states = allStates(automaton as never) as unknown as Node[];
    if (states.length === 0) throw new GenerationError('an automaton without states cannot be translated', automaton);
    const parent = (s: Node): Node | undefined => (s.$container?.$type === 'State' ? s.$container as Node : undefined);
    const initialChain = (level: Node): Node[] => {
        const out: Node[] = [];
        for (let s = startState(level as never) as unknown as Node | undefined; s; s = startState(s as never) as unknown as Node | undefined) out.push(s);
        return out;
    };
    const top = initialChain(automaton);
    const descendants = (s: Node): Node[] => [s, ...(substates(s as never) as unknown as Node[]).flatMap(descendants)];
    ClassVarImports(imports);

    const lines = classPrologue(spec, imports, 'Behavior of an automaton (generated).', [`self._state: str = ${str(top[top.length - 1].name)}`]);
    lines.push(
        '',
        `    _PARENT: ClassVar[dict[str, str | None]] = {${states.map((s) => `${str(s.name)}: ${parent(s) ? str(parent(s)!.name) : 'None'}`).join(', ')}}`,
        '',
        '    def current_state(self) -> str | None:',
        '        return self._state'
    );

    // init(): initial actions, delay point, entry actions of the initial states
    lines.push('', '    def init(self) -> None:');
    const initBody: string[] = [];
    // Only the initial action of the top-level initial state runs (MontiArc's simulator).
    if (top[0].initialAction) initBody.push(...tr.stmt(top[0].initialAction));
    initBody.push('self._delay_point()');
    for (const s of top) initBody.push(`self._entry(${str(s.name)})`);
    initBody.push(`self._state = ${str(top[top.length - 1].name)}`);
    lines.push(...indent(initBody, 8));

    // state actions
    for (const kind of ['entry', 'exit', 'do'] as const) {
        lines.push('', `    def _${kind}(self, state: str) -> None:`);
        const body: string[] = [];
        for (const s of states) {
            const actions = stateActions(s as never, kind) as unknown as Node[];
            if (actions.length === 0) continue;
            body.push(`${body.length ? 'elif' : 'if'} state == ${str(s.name)}:`);
            body.push(...indent(actions.flatMap((a) => tr.block(a.action)), 4));
        }
        lines.push(...indent(body.length ? body : ['pass'], 8));
    }
    lines.push(
        '',
        '    def _exit_until(self, stop: str | None) -> None:',
        '        state: str | None = self._state',
        '        while state is not None and state != stop:',
        '            self._exit(state)',
        '            state = self._PARENT[state]'
    );

    // transitions: the first enabled one fires
    const sync = spec.timing === 'sync';
    lines.push('', '    def _fire(self, event: str | None) -> bool:', '        state = self._state');
    const body: string[] = [];
    for (const t of allTransitions(automaton as never) as unknown as Node[]) {
        const source = sourceOf(t as never) as unknown as Node | undefined;
        const target = targetOf(t as never) as unknown as Node | undefined;
        if (!source || !target) throw new GenerationError('a transition with an unresolved state cannot be translated', t);
        const conds: string[] = [];
        const from = descendants(source).map((s) => str(s.name));
        conds.push(from.length === 1 ? `state == ${from[0]}` : `state in (${from.join(', ')})`);
        if (!sync) {
            const trig = triggerOf(t as never);
            if (trig.kind === 'port') conds.push(`event == ${str(trig.name)}`);
            else conds.push('event is None');
        }
        if (t.guard) conds.push(tr.expr(t.guard));
        const fire: string[] = [];
        if (t.$type === 'InternalTransition') {
            fire.push(...(t.action ? tr.stmt(t.action) : []));
        } else {
            const sp = statePath(source as never) as unknown as Node[];
            const tp = statePath(target as never) as unknown as Node[];
            let common = 0;
            while (common < sp.length && common < tp.length && sp[common] === tp[common]) common++;
            common = Math.min(common, sp.length - 1, tp.length - 1);
            const stop = common > 0 ? str(sp[common - 1].name) : 'None';
            fire.push(`self._exit_until(${stop})`);
            if (t.action) fire.push(...tr.stmt(t.action));
            const entered = [...tp.slice(common), ...initialChain(target)];
            for (const s of entered) fire.push(`self._entry(${str(s.name)})`);
            fire.push(`self._state = ${str(entered[entered.length - 1].name)}`);
        }
        fire.push('return True');
        body.push(`if ${conds.join(' and ')}:`, ...indent(fire, 4));
    }
    body.push('return False');
    lines.push(...indent(body, 8));

    if (sync) {
        lines.push('', '    def step(self, inputs: Mapping[str, object]) -> None:');
        lines.push(...indent([...readInputs(spec), 'self._fire(None)', 'self._do(self._state)'], 8));
    } else {
        const ins = spec.ports.filter((p) => p.direction === 'in');
        lines.push('', '    def on_message(self, port: str, value: object) -> None:');
        lines.push(...indent([...ins.map((p) => `self.${attr(p.name)} = value if port == ${str(p.name)} else ${primitiveDefault(p)}  # type: ignore[assignment]`), 'self._fire(port)'], 8));
        lines.push('', '    def on_tick(self) -> None:');
        lines.push(...indent([...ins.map((p) => `self.${attr(p.name)} = ${primitiveDefault(p)}`), 'self._fire(None)', 'self._do(self._state)'], 8));
    }
    return lines;
}

function ClassVarImports(imports: Imports): void {
    imports.add('typing', 'ClassVar');
}

/** Writes the module of a behavior class. */
export function moduleText(doc: string, imports: Imports, classLines: readonly string[]): string {
    const text = classLines.join('\n');
    for (const helper of ['f32', 'jcall', 'jcast', 'jconcat', 'jdiv', 'jfield', 'jmod', 'jordinal', 'jstatic', 'jstr', 'jushr']) {
        if (new RegExp(`\\b${helper}\\(`).test(text)) imports.add('maa_behavior', helper);
    }
    return [`"""${doc}"""`, '', 'from __future__ import annotations', '', ...imports.lines(), '', '', ...classLines, ''].join('\n');
}

/** automata.Translatable: what the Python automata generator cannot translate. */
export const translatableRule: WellFormednessRule = {
    name: 'automata.Translatable',
    description: 'automata have states, and transitions of <<sync>> automata have no events (the Python generators read them as per-slice transitions)',
    *check(scope): Iterable<RuleViolation> {
        for (const b of scope.behaviors) {
            if (b.language !== 'automaton') continue;
            const a = b.node as Node;
            if ((allStates(a as never) as unknown[]).length === 0) yield { node: a, message: 'the Python generators cannot translate an automaton without states' };
            if (automatonTiming(a as never) === 'sync') {
                for (const t of allTransitions(a as never) as unknown as Node[]) {
                    if (t.event || t.tick) yield { node: t, message: 'a transition of a <<sync>> automaton has no event; the Python generators cannot translate it' };
                }
            }
        }
    }
};

const create: BehaviorGeneratorFactory = () => ({
    kind: 'behavior',
    rules: [translatableRule],
    generate(behavior: BehaviorView, ctx) {
        const component = ctx.component;
        if (!component) throw new GenerationError('the automata generator needs the component (requires: component)', behavior.node);
        const automaton = behavior.node as Node;
        if (!enclosingAutomaton(automaton) && automaton.$type !== 'Automaton') throw new GenerationError('not an automaton', automaton);
        const timing = automatonTiming(automaton as never);
        const spec = specFrom(ctx, component, timing === 'sync' ? 'sync' : timing);
        const imports = new Imports();
        const cls = automatonClass(automaton, spec, imports);
        const { module, file } = behaviorModule(component.packageName, component.name);
        const out = ctx.out.file(file);
        out.traced(automaton, () => out.write(moduleText(`Behavior of ${component.qualifiedName}: its automaton (generated by the Python automata generator).`, imports, cls)));
        return { module, class: spec.className, timing: spec.timing };
    }
});

export default create;
