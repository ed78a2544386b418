/**
 * Mutated and pathological models for robustness tests: from well-formed model files, models
 * truncated at many points, with tokens deleted, duplicated or swapped, random bytes, and deep
 * nesting. Deterministic for a seed, so a failing case is reproduced from its seed and index.
 */

export interface FuzzCase {
    /** What was done, e.g. `truncate@120 of toast/Controller.arc` (print it when a case fails). */
    readonly name: string;
    /** The model file's path relative to its root (the extension selects the language). */
    readonly path: string;
    readonly text: string;
}

export interface CorpusOptions {
    readonly seed: number;
    /** Cases per source file and mutation kind. */
    readonly perKind?: number;
}

/** A small, seedable pseudo-random generator (mulberry32): the same seed gives the same corpus. */
export function random(seed: number): () => number {
    let a = seed >>> 0;
    return () => {
        a = (a + 0x6d2b79f5) >>> 0;
        let t = a;
        t = Math.imul(t ^ (t >>> 15), t | 1);
        t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
        return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
}

/** Splits a text into tokens (words, numbers, strings, single symbols) and the spaces between. */
function tokens(text: string): string[] {
    return text.match(/"(?:[^"\\\n]|\\.)*"|[A-Za-z_]\w*|\d+(?:\.\d+)?|\s+|./g) ?? [];
}

/** The mutated cases of one model file. */
export function mutations(path: string, text: string, options: CorpusOptions): FuzzCase[] {
    const rnd = random(options.seed);
    const n = options.perKind ?? 8;
    const pick = (k: number): number => Math.floor(rnd() * k);
    const toks = tokens(text);
    const words = toks
        .map((t, i) => [t, i] as const)
        .filter(([t]) => !/^\s+$/.test(t))
        .map(([, i]) => i);
    const cases: FuzzCase[] = [];
    const add = (what: string, t: string): void => {
        cases.push({ name: `${what} of ${path} (seed ${options.seed})`, path, text: t });
    };
    for (let k = 1; k <= n; k++) {
        const at = Math.floor((text.length * k) / (n + 1));
        add(`truncate@${at}`, text.substring(0, at));
    }
    if (words.length > 1) {
        for (let k = 0; k < n; k++) {
            const i = words[pick(words.length)]!;
            add(`delete token ${i}`, toks.filter((_, j) => j !== i).join(''));
            const d = words[pick(words.length)]!;
            add(`duplicate token ${d}`, toks.flatMap((t, j) => (j === d ? [t, ' ', t] : [t])).join(''));
            const a = words[pick(words.length)]!;
            const b = words[pick(words.length)]!;
            const swapped = [...toks];
            [swapped[a], swapped[b]] = [swapped[b]!, swapped[a]!];
            add(`swap tokens ${a},${b}`, swapped.join(''));
        }
    }
    for (let k = 0; k < n / 2; k++) {
        const at = pick(text.length + 1);
        const bytes = Array.from({ length: 1 + pick(16) }, () => String.fromCharCode(pick(256))).join('');
        add(`random bytes@${at}`, text.substring(0, at) + bytes + text.substring(at));
    }
    return cases;
}

/** Pathological inputs of one language: deep nesting of every kind, noise, empty files. */
export function pathological(path: string, depth: number, rnd: () => number): FuzzCase[] {
    const r = (s: string, k = depth): string => s.repeat(k);
    const noise = Array.from({ length: 2000 }, () => String.fromCharCode(Math.floor(rnd() * 256))).join('');
    const texts: Record<string, string> = {
        empty: '',
        noise: noise,
        'open braces': r('{'),
        'open parentheses': r('('),
        'mixed brackets': r('( [ { '),
        'closing brackets': r(') ] } '),
    };
    if (path.endsWith('.arc')) {
        const body = (s: string): string => `component ${baseName(path)} {\n  port in int i;\n  port out int o;\n${s}\n}\n`;
        texts['nested parentheses'] = body(`  compute { o = ${r('(')}i${r(')')}; }`);
        texts['unary minus'] = body(`  compute { o = ${r('- ')}i; }`);
        texts['nested blocks'] = body(`  compute { ${r('{')}${r('}')} }`);
        texts['nested ifs'] = body(`  compute { ${r('if (i > 0) ')}o = 1; }`);
        texts['else-if chain'] = body(`  compute { ${r('if (i > 0) o = 1; else ')}o = 2; }`);
        texts['binary chain'] = body(`  compute { o = i${r(' + i', depth * 4)}; }`);
        texts['nested states'] = body(
            `  automaton {\n    initial ${Array.from({ length: depth }, (_, k) => `state S${k} {`).join(' ')}${r('}')}\n  }`,
        );
        texts['guard parentheses'] = body(`  automaton {\n    initial state A;\n    A -> A [${r('(')}i > 0${r(')')}] / o = 1;\n  }`);
        texts['generic types'] = body(`  port in ${r('List<')}int${r('>')} g;`);
        texts['robotarm moves'] = body(`  robotarm {\n    location L 10 deg 5 cm;\n    program P { move ${r('L ')}; }\n  }`);
    }
    return Object.entries(texts).map(([what, text]) => ({ name: `${what} (depth ${depth}) in ${path}`, path, text }));
}

function baseName(path: string): string {
    return path.substring(path.lastIndexOf('/') + 1).replace(/\.\w+$/, '');
}
