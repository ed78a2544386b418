/**
 * The breakpoints list's model (docs/simulation.md "Breakpoints"): per automaton instance of the
 * run (the automata table, `automata` of `GET /api/sim/topics`) its states and its transitions,
 * each a possible breakpoint; the checked ones make the request of `/sim/set_breakpoints`
 * (@maa/protocol's SetBreakpoints). A transition breakpoint names its states (`from`, `to`), so
 * transitions between the same two states share one entry. Pure.
 */
import type { Breakpoint } from '@maa/protocol';
import { type AutomatonInfo, instanceLabel } from '../timeline/automata.js';

/** One possible breakpoint of the list. */
export interface BreakpointRow {
    /** Unique in the list: `<instance path>|state|<path>` or `<instance path>|<from>|<to>`. */
    key: string;
    /** What the row shows: a state's path, or `from → to`. */
    text: string;
    /** The transitions' labels (`[guard] / action`), for a transition row. */
    detail: string;
    /** For the test ids: `state-<path>` or `transition-<first index>`. */
    id: string;
    breakpoint: Breakpoint;
}

export interface AutomatonRows {
    instancePath: string;
    component: string;
    node: string;
    states: BreakpointRow[];
    transitions: BreakpointRow[];
}

/** The rows of every automaton of the run, in the table's order. */
export function breakpointRows(automata: readonly AutomatonInfo[]): AutomatonRows[] {
    return automata.map((a) => {
        const states = a.states.map(
            (s): BreakpointRow => ({
                key: `${a.instancePath}|state|${s.path}`,
                text: s.path,
                detail: '',
                id: `state-${s.path}`,
                breakpoint: { node: a.node, state: s.path },
            }),
        );
        const byPair = new Map<string, BreakpointRow>();
        for (const t of a.transitions) {
            const key = `${a.instancePath}|${t.from}|${t.to}`;
            const row = byPair.get(key);
            if (row) {
                row.detail = [row.detail, t.label].filter((x) => x).join('; ');
                continue;
            }
            byPair.set(key, {
                key,
                text: `${t.from} → ${t.to}`,
                detail: t.label,
                id: `transition-${t.index}`,
                breakpoint: { node: a.node, from: t.from, to: t.to },
            });
        }
        return { instancePath: a.instancePath, component: a.component, node: a.node, states, transitions: [...byPair.values()] };
    });
}

/** The request of `/sim/set_breakpoints` for the checked rows (by key), in the list's order. */
export function breakpointsRequest(rows: readonly AutomatonRows[], checked: ReadonlySet<string>): { breakpoints: Breakpoint[] } {
    const all = rows.flatMap((a) => [...a.states, ...a.transitions]);
    return { breakpoints: all.filter((r) => checked.has(r.key)).map((r) => r.breakpoint) };
}

/** The breakpoint a `/sim/get_status` answer names (its `breakpoint`, possibly under `values`/`status`), if any. */
export function breakpointOfStatus(answer: unknown): Breakpoint | undefined {
    const record = (x: unknown): Record<string, unknown> | undefined =>
        typeof x === 'object' && x !== null && !Array.isArray(x) ? (x as Record<string, unknown>) : undefined;
    const outer = record(answer);
    const status = record(outer?.['values']) ?? record(outer?.['status']) ?? outer;
    const bp = record(status?.['breakpoint']);
    if (!bp || typeof bp['node'] !== 'string') return undefined;
    if (typeof bp['state'] === 'string') return { node: bp['node'], state: bp['state'] };
    if (typeof bp['from'] === 'string' && typeof bp['to'] === 'string') return { node: bp['node'], from: bp['from'], to: bp['to'] };
    return undefined;
}

/** The key of the row a breakpoint belongs to (to mark the row the run stopped at). */
export function rowKeyOf(rows: readonly AutomatonRows[], bp: Breakpoint): string | undefined {
    const automaton = rows.find((a) => a.node === bp.node);
    if (!automaton) return undefined;
    return 'state' in bp ? `${automaton.instancePath}|state|${bp.state}` : `${automaton.instancePath}|${bp.from}|${bp.to}`;
}

/** The status text of a breakpoint the run paused at: `Paused at ctrl: Toasting → Serving`. */
export function describeHit(rows: readonly AutomatonRows[], bp: Breakpoint): string {
    const inst = rows.find((a) => a.node === bp.node)?.instancePath;
    const where = inst === undefined ? bp.node : instanceLabel(inst);
    return `Paused at breakpoint ${where}: ${'state' in bp ? bp.state : `${bp.from} → ${bp.to}`}`;
}
