/**
 * Short text forms of ROS messages in rosbridge's JSON form, for the port inspector and the
 * diagram's value labels; numeric views for the live plot. Pure.
 */

/** A number in a few significant digits: integers as they are, others with up to 3 decimals. */
export function formatNumber(n: number): string {
    if (!Number.isFinite(n)) return String(n);
    if (Number.isInteger(n)) return String(n);
    const a = Math.abs(n);
    if (a !== 0 && (a < 1e-3 || a >= 1e7)) return n.toExponential(2);
    return String(Number(n.toFixed(a < 1 ? 4 : 3)));
}

function isTime(v: Record<string, unknown>): boolean {
    const keys = Object.keys(v);
    return keys.length === 2 && typeof v['sec'] === 'number' && (typeof v['nanosec'] === 'number' || typeof v['nsec'] === 'number');
}

/** Seconds of a `builtin_interfaces/Time` (`{sec, nanosec}`), `undefined` if it is none. */
export function timeSeconds(v: unknown): number | undefined {
    if (!v || typeof v !== 'object') return undefined;
    const r = v as Record<string, unknown>;
    if (!isTime(r)) return undefined;
    return (r['sec'] as number) + ((r['nanosec'] ?? r['nsec']) as number) / 1e9;
}

const MAX_ITEMS = 8;

/**
 * Enums travel differently by mode: lock-step sends the literal as `std_msgs/String`
 * (`{"data": "GOLDEN"}`), ROS 2 mode the generated enum message, whose `value` holds the literal's
 * ordinal (`{"value": 1}`, with `uint8 GOLDEN=1` constants in the message definition). With the
 * literals known (`enumLiterals`, in ordinal order) both show as `GOLDEN`; without, the ordinal
 * shows as `#1`.
 */
export interface FormatOptions {
    /** The literals of the message's enum type, in ordinal order (ROS 2 mode). */
    readonly enumLiterals?: readonly string[];
}

/** Whether a message looks like a generated ROS 2 enum message: exactly an integer `value`. */
export function isEnumMessage(v: unknown): v is { value: number } {
    if (!v || typeof v !== 'object' || Array.isArray(v)) return false;
    const keys = Object.keys(v);
    return keys.length === 1 && keys[0] === 'value' && Number.isInteger((v as Record<string, unknown>)['value']);
}

/** The text of an enum ordinal: its literal when known, else `#<ordinal>`. */
export function formatEnumOrdinal(ordinal: number, literals?: readonly string[]): string {
    const name = literals?.[ordinal];
    return name !== undefined ? name : `#${ordinal}`;
}

/**
 * The literals of an enum message from its definition as rosapi's `message_details` describes it
 * (`constnames`/`constvalues` of the message's typedef): the constants ordered by value, if the
 * message has just the `value` field and the constants are the ordinals 0..n-1; else `undefined`.
 */
export function enumLiteralsOf(
    typedef: { fieldnames?: unknown; constnames?: unknown; constvalues?: unknown } | undefined,
): string[] | undefined {
    if (!typedef) return undefined;
    const fields = Array.isArray(typedef.fieldnames) ? typedef.fieldnames : [];
    const names = Array.isArray(typedef.constnames) ? typedef.constnames.map(String) : [];
    const values = Array.isArray(typedef.constvalues) ? typedef.constvalues.map((x) => Number(x)) : [];
    if (fields.length !== 1 || fields[0] !== 'value' || names.length === 0 || names.length !== values.length) return undefined;
    const out: string[] = [];
    names.forEach((n, i) => {
        const v = values[i]!;
        if (Number.isInteger(v) && v >= 0 && v < names.length) out[v] = n;
    });
    for (let i = 0; i < names.length; i++) if (out[i] === undefined) return undefined;
    return out;
}

function formatInner(v: unknown, depth: number, options?: FormatOptions): string {
    if (v === null || v === undefined) return '–';
    if (typeof v === 'number') return formatNumber(v);
    if (typeof v === 'boolean') return v ? 'true' : 'false';
    if (typeof v === 'string') return v;
    if (typeof v === 'bigint') return v.toString();
    if (Array.isArray(v)) {
        const items = v.slice(0, MAX_ITEMS).map((x) => formatInner(x, depth + 1));
        if (v.length > MAX_ITEMS) items.push(`…+${v.length - MAX_ITEMS}`);
        return `[${items.join(', ')}]`;
    }
    if (typeof v === 'object') {
        const r = v as Record<string, unknown>;
        const t = timeSeconds(r);
        if (t !== undefined) return `${formatNumber(t)} s`;
        if (isEnumMessage(r)) return formatEnumOrdinal(r.value, options?.enumLiterals);
        const keys = Object.keys(r).filter((k) => k !== 'header');
        // std_msgs wrappers: {data: x}
        if (keys.length === 1 && keys[0] === 'data') return formatInner(r['data'], depth);
        // JointState-like: name[] with position[]
        if (
            Array.isArray(r['name']) &&
            Array.isArray(r['position']) &&
            (r['name'] as unknown[]).length === (r['position'] as unknown[]).length &&
            (r['name'] as unknown[]).length > 0
        ) {
            const names = r['name'] as unknown[];
            const pos = r['position'] as unknown[];
            return names.map((nm, i) => `${String(nm)}=${formatInner(pos[i], depth + 1)}`).join(' ');
        }
        if (depth > 2) return '{…}';
        const parts = keys.slice(0, MAX_ITEMS).map((k) => `${k}: ${formatInner(r[k], depth + 1)}`);
        if (keys.length > MAX_ITEMS) parts.push('…');
        return `{${parts.join(', ')}}`;
    }
    return String(v);
}

/** The text of a message, at most `maxLength` characters (an ellipsis marks a cut). */
export function formatRosValue(message: unknown, maxLength = 80, options?: FormatOptions): string {
    const s = formatInner(message, 0, options);
    return s.length > maxLength ? `${s.slice(0, Math.max(1, maxLength - 1))}…` : s;
}

/**
 * The number a message stands for, for plotting: a number, a boolean (0/1), `{data: number}`,
 * or a message with exactly one numeric field; `undefined` otherwise.
 */
export function numericValue(message: unknown): number | undefined {
    if (typeof message === 'number') return Number.isFinite(message) ? message : undefined;
    if (typeof message === 'boolean') return message ? 1 : 0;
    if (!message || typeof message !== 'object' || Array.isArray(message)) return undefined;
    const r = message as Record<string, unknown>;
    if ('data' in r) return numericValue(r['data']);
    const t = timeSeconds(r);
    if (t !== undefined) return t;
    const numeric = Object.keys(r).filter((k) => k !== 'header' && (typeof r[k] === 'number' || typeof r[k] === 'boolean'));
    const others = Object.keys(r).filter((k) => k !== 'header' && !numeric.includes(k));
    if (numeric.length === 1 && others.length === 0) return numericValue(r[numeric[0]!]);
    return undefined;
}

/** The simulation time of a `rosgraph_msgs/msg/Clock` message in seconds. */
export function clockSeconds(message: unknown): number | undefined {
    if (!message || typeof message !== 'object') return undefined;
    return timeSeconds((message as Record<string, unknown>)['clock']);
}

/**
 * A message for a ROS type from the text of the inject field: `std_msgs/msg/<Prim>` takes the
 * plain value (`42`, `true`, `GOLDEN`) as `{data}`; everything else takes JSON. Throws with a
 * readable message when the text does not fit.
 */
export function parseInjectedValue(rosType: string, text: string): Record<string, unknown> {
    const trimmed = text.trim();
    const prim = /^std_msgs\/(?:msg\/)?(\w+)$/.exec(rosType)?.[1];
    const intTypes = new Set(['Int8', 'Int16', 'Int32', 'Int64', 'UInt8', 'UInt16', 'UInt32', 'UInt64', 'Byte', 'Char']);
    const floatTypes = new Set(['Float32', 'Float64']);
    if (prim && (intTypes.has(prim) || floatTypes.has(prim) || prim === 'Bool' || prim === 'String')) {
        if (trimmed.startsWith('{')) return parseJsonObject(trimmed);
        if (prim === 'String') return { data: text };
        if (prim === 'Bool') {
            if (/^(true|1)$/i.test(trimmed)) return { data: true };
            if (/^(false|0)$/i.test(trimmed)) return { data: false };
            throw new Error(`${rosType} takes true or false, not "${trimmed}"`);
        }
        const n = Number(trimmed);
        if (trimmed === '' || !Number.isFinite(n)) throw new Error(`${rosType} takes a number, not "${trimmed}"`);
        if (intTypes.has(prim) && !Number.isInteger(n)) throw new Error(`${rosType} takes an integer, not ${trimmed}`);
        return { data: n };
    }
    return parseJsonObject(trimmed);
}

function parseJsonObject(text: string): Record<string, unknown> {
    let v: unknown;
    try {
        v = JSON.parse(text);
    } catch (e) {
        throw new Error(`not a JSON message: ${(e as Error).message}`);
    }
    if (!v || typeof v !== 'object' || Array.isArray(v)) throw new Error('a message is a JSON object');
    return v as Record<string, unknown>;
}
