import type { ComponentView, ConnectorView, DataTypeResult } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import { type Imports, primitiveDefault, typeBySimpleName, typeRef } from '../behavior/common.js';
import { renderLines } from '../python/templates.js';
import type { ModeTransitionView, ModesView } from './views.js';
import { PythonTranslator, isTypeDecl, pyName, type Node } from '../python/expressions.js';

const str = (s: string): string => JSON.stringify(s);

function tuple(xs: readonly string[]): string {
    return xs.length === 0 ? '()' : `(${xs.join(', ')}${xs.length === 1 ? ',' : ''})`;
}

/** An expression in parentheses (once: ruff rejects doubled ones), so that `and` binds it whole. */
function parenthesized(e: string): string {
    if (e.startsWith('(')) {
        let depth = 0;
        for (let i = 0; i < e.length; i++) {
            if (e[i] === '(') depth++;
            else if (e[i] === ')' && --depth === 0) return i === e.length - 1 ? e : `(${e})`;
        }
    }
    return `(${e})`;
}

/** A connector as maa_timesync's `Connector` tuple. */
export function connectorTuple(k: ConnectorView): string {
    const targets = k.targets.map((t) => `(${str(t.subcomponent ?? '')}, ${str(t.port)})`);
    return `(${str(k.source.subcomponent ?? '')}, ${str(k.source.port)}, ${tuple(targets)})`;
}

/**
 * Guards of mode transitions: in ports are the slice's (or the message's) values, Java's default
 * for a primitive port without message (as atomic sync behaviors read them); parameters the
 * instance's.
 */
function guardTranslator(c: ComponentView, datatypes: DataTypeResult, imports: Imports, rte: string): PythonTranslator {
    return new PythonTranslator({
        name(target, ref) {
            if (target.$type === 'Port') {
                const port = c.ports.find((p) => p.name === target.name);
                const def = port ? primitiveDefault(port) : 'None';
                if (def === 'None') return `inputs.get(${str(target.name)})`;
                imports.add(rte, 'port_value');
                return `port_value(inputs, ${str(target.name)}, ${def})`;
            }
            if (target.$type === 'Parameter') return `params[${str(target.name)}]`;
            if (target.$type === 'CDEnumConstant')
                return `${typeRef(datatypes, imports, target.$container as Node)}.${pyName(target.name)}`;
            if (isTypeDecl(target)) return typeRef(datatypes, imports, target);
            throw new GenerationError(
                `'${target.name}' cannot be used in the guard of a mode transition (only in ports, parameters and constants)`,
                ref,
            );
        },
        type: (decl) => typeRef(datatypes, imports, decl),
        typeBySimpleName: (name) => typeBySimpleName(datatypes, imports, name),
    });
}

/** The view of a mode component's mode automaton (templates/timesync/modes.njk); undefined for components without one. */
export function modesView(c: ComponentView, datatypes: DataTypeResult, imports: Imports): ModesView | undefined {
    const m = c.modes;
    if (!m) return undefined;
    imports.add('maa_timesync.modes', 'ModeComponent');
    imports.add('maa_timesync.runtime', 'Connector');
    return {
        modes: m.modes.map((x) => x.name),
        initial: m.initial,
        timing: m.timing,
        perMode: m.modes.map((x) => ({ name: x.name, subcomponents: x.subcomponents, connectors: x.connectors.map(connectorTuple) })),
        body: modeTransitionBody(c, datatypes, imports, 'maa_timesync.modes'),
    };
}

/**
 * The body of `mode_transition(mode, trigger, inputs, params)`: the transitions in declaration
 * order, returning the index and target of the first enabled one (or None); the index is the
 * transition's in the automata table (behavior/automata-table.ts). `rte` is the module with
 * `port_value` (maa_timesync.modes, maa_ros2.modes).
 */
export function modeTransitionBody(c: ComponentView, datatypes: DataTypeResult, imports: Imports, rte: string): string[] {
    return renderLines('timesync/mode-transition.njk', modeTransitionView(c, datatypes, imports, rte));
}

/** The view of `mode_transition`'s body (templates/timesync/mode-transition.njk). */
export function modeTransitionView(c: ComponentView, datatypes: DataTypeResult, imports: Imports, rte: string): ModeTransitionView {
    const m = c.modes;
    if (!m) return { unused: ['mode', 'trigger', 'inputs', 'params'], transitions: [] };
    const tr = guardTranslator(c, datatypes, imports, rte);
    const transitions = m.transitions.map((t, index) => {
        const conditions = [`mode == ${str(t.source)}`];
        if (m.timing !== 'sync') {
            // Event-based: a message triggers the transitions of its port; a tick those with `Tick` or no event.
            conditions.push(t.trigger.kind === 'port' ? `trigger == ${str(t.trigger.port)}` : 'trigger == ""');
        }
        if (t.guard) conditions.push(parenthesized(tr.expr(t.guard)));
        return { index, conditions, target: t.target };
    });
    // (the names in the statements as written, `return "<target>"` included)
    const used = transitions.map((t) => `if ${t.conditions.join(' and ')}:\n    return ${t.index}, ${str(t.target)}`).join('\n');
    const unused = ['mode', 'trigger', 'inputs', 'params'].filter((v) => !new RegExp(`\\b${v}\\b`).test(used));
    return { unused, transitions };
}
