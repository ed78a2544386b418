// The corpus of the language server's fuzz test (lsp-fuzz.test.ts): pathological models (deep
// nesting, a file of a few MB), random bytes, and mutations of the example's files (truncations,
// token swaps, deletions, duplications, splices), all drawn from one seeded generator so a
// failure can be replayed from its seed.

/** A small seeded generator (mulberry32): the same seed gives the same corpus and requests. */
export class Random {
    private state: number;

    constructor(seed: number) {
        this.state = seed >>> 0;
    }

    /** A float in [0, 1). */
    next(): number {
        this.state = (this.state + 0x6d2b79f5) >>> 0;
        let t = this.state;
        t = Math.imul(t ^ (t >>> 15), t | 1);
        t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
        return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    }

    /** An integer in [0, n). */
    int(n: number): number {
        return Math.floor(this.next() * n);
    }

    pick<T>(items: readonly T[]): T {
        if (items.length === 0) throw new Error('pick from nothing');
        return items[this.int(items.length)]!;
    }
}

export interface FuzzCase {
    /** What the case is, enough to understand a failure without the text. */
    readonly description: string;
    /** File extension, which decides the language: arc, cd, ra or arcapp. */
    readonly ext: string;
    readonly text: string;
}

export interface SourceFile {
    /** Path relative to the example's root (forward slashes). */
    readonly path: string;
    readonly text: string;
}

const DEPTH = 10_000;

/** A component with an automaton whose guard, action or state nesting is `DEPTH` levels deep. */
function automaton(body: string): string {
    return `package toast;\n\ncomponent Deep {\n  port in int distance,\n       out int out1;\n\n  <<sync>> automaton {\n${body}\n  }\n}\n`;
}

/** The pathological inputs of the issue: deep nesting of several kinds, and a file of a few MB. */
export function pathologicalCases(): FuzzCase[] {
    const open = '('.repeat(DEPTH);
    const close = ')'.repeat(DEPTH);
    const states = (n: number): string => `${Array.from({ length: n }, (_, i) => `state S${i} {`).join(' ')} ${'}'.repeat(n)}`;
    const ports = Array.from({ length: 10_000 }, (_, i) => `       in int p${i}`).join(',\n');
    const comment = `/*${' the toaster toasts the toast;'.repeat(50_000)} */\n`;
    const components = Array.from({ length: 40_000 }, (_, i) => `component C${i} { port in int a, out int b; }\n`).join('');
    return [
        {
            description: `guard with ${DEPTH} nested parentheses`,
            ext: 'arc',
            text: automaton(`    initial state Idle;\n    Idle -> Idle [${open}distance < 1${close}];`),
        },
        {
            description: `guard with ${DEPTH} unclosed parentheses`,
            ext: 'arc',
            text: automaton(`    initial state Idle;\n    Idle -> Idle [${open}distance < 1];`),
        },
        {
            description: `guard with ${DEPTH} unary minus signs`,
            ext: 'arc',
            text: automaton(`    initial state Idle;\n    Idle -> Idle [distance < ${'-'.repeat(DEPTH)}1];`),
        },
        {
            description: `action with ${DEPTH} logical negations`,
            ext: 'arc',
            text: automaton(`    initial state Idle;\n    Idle -> Idle / { out1 = ${'!'.repeat(DEPTH)}true ? 1 : 0; };`),
        },
        { description: `${DEPTH} nested states`, ext: 'arc', text: automaton(`    ${states(DEPTH)}\n    initial state Idle;`) },
        {
            description: `${DEPTH} nested blocks in an action`,
            ext: 'arc',
            text: automaton(`    initial state Idle;\n    Idle -> Idle / ${'{ '.repeat(DEPTH)}out1 = 1;${' }'.repeat(DEPTH)};`),
        },
        {
            description: `${DEPTH} nested type arguments in a class diagram`,
            ext: 'cd',
            text: `package toast.types;\n\nclassdiagram D {\n  class C {\n    ${'List<'.repeat(DEPTH)}int${'>'.repeat(DEPTH)} x;\n  }\n}\n`,
        },
        {
            description: 'a component with 10,000 ports after a comment of 1.5 MB',
            ext: 'arc',
            text: `package toast;\n\n${comment}component Huge {\n  port\n${ports};\n}\n`,
        },
        { description: '40,000 components in one file of 1.8 MB, twice', ext: 'arc', text: `package toast;\n\n${components}${components}` },
    ];
}

/** Rough tokens of a model: words, numbers, runs of blanks, single other characters. */
function tokens(text: string): string[] {
    return text.match(/[A-Za-z_$][\w$]*|\d+(?:\.\d+)?|\s+|[^\s\w$]/g) ?? [];
}

const INSERTS = [
    '{',
    '}',
    '(',
    ')',
    '[',
    ']',
    ';',
    ',',
    '.',
    '->',
    '<<',
    '>>',
    '/',
    'state',
    'initial',
    'component',
    'port',
    'in',
    'out',
    'automaton',
    'package',
    'import',
    'enum',
    'class',
    'move',
    'location',
    'program',
    'robotarm',
    'platform',
    'application',
    '"',
    "'",
    '/*',
    '//',
    '\n',
];

/** One random mutation of a model file. */
export function mutation(random: Random, source: SourceFile): FuzzCase {
    const ext = source.path.substring(source.path.lastIndexOf('.') + 1);
    const kind = random.int(5);
    if (kind === 0) {
        const at = random.int(source.text.length + 1);
        return { description: `${source.path} truncated at offset ${at}`, ext, text: source.text.substring(0, at) };
    }
    const toks = tokens(source.text);
    const steps = 1 + random.int(6);
    const done: string[] = [];
    for (let s = 0; s < steps && toks.length > 1; s++) {
        const i = random.int(toks.length);
        const j = random.int(toks.length);
        switch (kind) {
            case 1:
                [toks[i], toks[j]] = [toks[j]!, toks[i]!];
                done.push(`swap ${i}<->${j}`);
                break;
            case 2:
                done.push(`delete ${i} '${toks[i]!.trim()}'`);
                toks.splice(i, 1);
                break;
            case 3:
                toks.splice(i, 0, toks[j]!);
                done.push(`duplicate ${j} at ${i}`);
                break;
            default: {
                const ins = random.pick(INSERTS);
                toks.splice(i, 0, ins);
                done.push(`insert '${ins.trim() || '\\n'}' at ${i}`);
            }
        }
    }
    return { description: `${source.path} tokens: ${done.join(', ')}`, ext, text: toks.join('') };
}

/** Random characters: bytes as Latin-1, control characters, and a few characters outside it. */
export function randomText(random: Random): FuzzCase {
    const length = 1 + random.int(3000);
    let text = '';
    for (let i = 0; i < length; i++) {
        const r = random.next();
        text +=
            r < 0.8
                ? String.fromCharCode(random.int(256))
                : r < 0.95
                  ? random.pick(INSERTS)
                  : String.fromCodePoint(0x100 + random.int(0x1_0000 - 0x100));
    }
    const ext = random.pick(['arc', 'cd', 'ra', 'arcapp']);
    return { description: `${length} random characters as .${ext}`, ext, text };
}

/** A splice of two files: the start of one, the end of another. */
export function splice(random: Random, a: SourceFile, b: SourceFile): FuzzCase {
    const ext = a.path.substring(a.path.lastIndexOf('.') + 1);
    const i = random.int(a.text.length + 1);
    const j = random.int(b.text.length + 1);
    return { description: `${a.path}[0:${i}] + ${b.path}[${j}:]`, ext, text: a.text.substring(0, i) + b.text.substring(j) };
}

/** The corpus: the pathological cases first, then `count` random ones. */
export function corpus(random: Random, sources: readonly SourceFile[], count: number): FuzzCase[] {
    const out = pathologicalCases();
    for (let i = 0; i < count; i++) {
        const r = random.next();
        out.push(
            r < 0.15
                ? randomText(random)
                : r < 0.25
                  ? splice(random, random.pick(sources), random.pick(sources))
                  : mutation(random, random.pick(sources)),
        );
    }
    return out;
}
