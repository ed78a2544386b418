import type { ComponentView, ConnectorView, DataTypeResult } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import { Imports, indent, primitiveDefault, typeBySimpleName, typeRef } from '../behavior/common.js';
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
            if (target.$type === 'CDEnumConstant') return `${typeRef(datatypes, imports, target.$container as Node)}.${pyName(target.name)}`;
            if (isTypeDecl(target as Node)) return typeRef(datatypes, imports, target as Node);
            throw new GenerationError(`'${target.name}' cannot be used in the guard of a mode transition (only in ports, parameters and constants)`, ref);
        },
        type: (decl) => typeRef(datatypes, imports, decl),
        typeBySimpleName: (name) => typeBySimpleName(datatypes, imports, name)
    });
}

/**
 * The class body of a mode component (maa_timesync.ModeComponent): its modes, the
 * subcomponents and connectors of each, and `mode_transition`, the transitions in declaration
 * order. Undefined for components without a mode automaton.
 */
export function modeClassLines(c: ComponentView, datatypes: DataTypeResult, imports: Imports): string[] | undefined {
    const m = c.modes;
    if (!m) return undefined;
    imports.add('maa_timesync.modes', 'ModeComponent');
    const lines = [
        `    MODES = ${tuple(m.modes.map((x) => str(x.name)))}`,
        `    INITIAL_MODE = ${str(m.initial)}`,
        `    MODE_TIMING = ${str(m.timing)}`,
        '    MODE_SUBCOMPONENTS: ClassVar[Mapping[str, tuple[str, ...]]] = {',
        ...indent(m.modes.map((x) => `${str(x.name)}: ${tuple(x.subcomponents.map(str))},`), 8),
        '    }',
        '    MODE_CONNECTORS: ClassVar[Mapping[str, tuple[Connector, ...]]] = {',
        ...indent(m.modes.map((x) => `${str(x.name)}: ${tuple(x.connectors.map(connectorTuple))},`), 8),
        '    }',
        '',
        '    @classmethod',
        '    def mode_transition(cls, mode: str, trigger: str | None, inputs: Mapping[str, object], params: Mapping[str, object]) -> str | None:'
    ];
    imports.add('maa_timesync.runtime', 'Connector');
    const body = modeTransitionBody(c, datatypes, imports, 'maa_timesync.modes');
    lines.push(...indent(body, 8));
    return lines;
}

/**
 * The body of `mode_transition(mode, trigger, inputs, params)`: the transitions in declaration
 * order, returning the target of the first enabled one (or None). `rte` is the module with
 * `port_value` (maa_timesync.modes, maa_ros2.modes).
 */
export function modeTransitionBody(c: ComponentView, datatypes: DataTypeResult, imports: Imports, rte: string): string[] {
    const m = c.modes;
    if (!m) return ['del mode, trigger, inputs, params', 'return None'];
    const tr = guardTranslator(c, datatypes, imports, rte);
    const body: string[] = [];
    for (const t of m.transitions) {
        const conds = [`mode == ${str(t.source)}`];
        if (m.timing !== 'sync') {
            // Event-based: a message triggers the transitions of its port; a tick those with `Tick` or no event.
            conds.push(t.trigger.kind === 'port' ? `trigger == ${str(t.trigger.port)}` : 'trigger == ""');
        }
        if (t.guard) conds.push(parenthesized(tr.expr(t.guard as Node)));
        body.push(`if ${conds.join(' and ')}:`, `    return ${str(t.target)}`);
    }
    const used = body.join('\n');
    const unused = ['mode', 'trigger', 'inputs', 'params'].filter((v) => !new RegExp(`\\b${v}\\b`).test(used));
    if (unused.length > 0) body.unshift(`del ${unused.join(', ')}`);
    body.push('return None');
    return body;
}
