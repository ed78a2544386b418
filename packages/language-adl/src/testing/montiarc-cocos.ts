// MontiArc's context-condition cases (the workplace's shared/conformance/montiarc/*.json, read at
// test time and never copied into this repository): loading, the files of a case, and the scoring
// of that folder's README, in one place for every runner (the family's full check in
// language-server, the automaton and mode cases in language-automata).
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';

/** One case of cocos.json / cocos-extended.json (the fields the runners use). */
export interface CocosCase {
    cls: string;
    kind: 'valid' | 'invalid';
    comment: string;
    model: string;
    helpers: string[];
    expected: string[];
}

/** `<repo>/../shared/conformance/montiarc/<name>`, found from any folder inside the repository. */
export function cocosSuiteFile(fromDir: string, name: 'cocos.json' | 'cocos-extended.json'): string {
    let dir = path.resolve(fromDir);
    for (;;) {
        if (existsSync(path.join(dir, '.git')) || existsSync(path.join(dir, 'package-lock.json'))) break;
        const parent = path.dirname(dir);
        if (parent === dir) break;
        dir = parent;
    }
    return path.resolve(dir, '..', 'shared', 'conformance', 'montiarc', name);
}

/** The cases of a suite file, or undefined when the file is absent (a user's clone has no ../shared). */
export function loadCocosCases(file: string): CocosCase[] | undefined {
    if (!existsSync(file)) return undefined;
    return (JSON.parse(readFileSync(file, 'utf8')) as { cases: CocosCase[] }).cases;
}

/**
 * The files of a case, relative to its model root: the model at the root (it has no package),
 * each helper at `<package path>/<Name>.arc`.
 */
export function cocosCaseFiles(c: CocosCase): Record<string, string> {
    const out: Record<string, string> = {};
    for (const text of [c.model, ...c.helpers]) {
        const pkg = /^\s*package\s+([\w.]+)\s*;/m.exec(text)?.[1];
        const name = /component\s+(\w+)/.exec(text)?.[1] ?? 'Model';
        out[`${pkg ? `${pkg.replace(/\./g, '/')}/` : ''}${name}.arc`] = text;
    }
    return out;
}

/** Per test class, every code its invalid cases expect: what its valid cases must not report. */
export function forbiddenCodesByClass(cases: readonly CocosCase[]): Map<string, Set<string>> {
    const byClass = new Map<string, Set<string>>();
    for (const c of cases) {
        if (c.kind !== 'invalid') continue;
        const set = byClass.get(c.cls) ?? new Set<string>();
        for (const e of c.expected) set.add(e);
        byClass.set(c.cls, set);
    }
    return byClass;
}

/**
 * Why a case fails, or undefined when it passes (the README's scoring): an invalid case must
 * report every expected code (a code expected twice, twice); a valid case no `syntax/` or `link/`
 * code and none of the codes its class's invalid cases expect.
 */
export function cocosFailure(c: CocosCase, codes: readonly string[], forbidden: Map<string, Set<string>>): string | undefined {
    if (c.kind === 'invalid') {
        const missing = [...new Set(c.expected)].filter(
            (e) => codes.filter((x) => x === e).length < c.expected.filter((x) => x === e).length,
        );
        return missing.length === 0 ? undefined : `missing [${missing.join(', ')}], got [${codes.join(', ')}]`;
    }
    const wrong = codes.filter((x) => x.startsWith('syntax/') || x.startsWith('link/') || forbidden.get(c.cls)?.has(x));
    return wrong.length === 0 ? undefined : `valid, but reported [${wrong.join(', ')}]`;
}

/** A suite's score: passed/total per class and one line per failing case. */
export interface CocosScore {
    passed: number;
    total: number;
    perClass: Map<string, { passed: number; total: number }>;
    failures: string[];
}

/** Scores every case, given the codes reported for each (same order as `cases`). */
export function scoreCocos(cases: readonly CocosCase[], codesOfCase: readonly (readonly string[])[]): CocosScore {
    const forbidden = forbiddenCodesByClass(cases);
    const perClass = new Map<string, { passed: number; total: number }>();
    const failures: string[] = [];
    let passed = 0;
    cases.forEach((c, i) => {
        const failure = cocosFailure(c, codesOfCase[i] ?? [], forbidden);
        const s = perClass.get(c.cls) ?? { passed: 0, total: 0 };
        s.total++;
        if (failure === undefined) {
            s.passed++;
            passed++;
        } else {
            failures.push(`${c.cls} ${c.kind} (${c.comment}): ${failure}: ${c.model.replace(/\s+/g, ' ')}`);
        }
        perClass.set(c.cls, s);
    });
    return { passed, total: cases.length, perClass, failures };
}

/** The score as a table for the test log. */
export function formatCocosScore(title: string, score: CocosScore): string {
    const rows = [...score.perClass.entries()]
        .sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))
        .map(
            ([cls, s]) =>
                `${((100 * s.passed) / s.total).toFixed(0).padStart(4)}%  ${String(s.passed).padStart(3)}/${String(s.total).padEnd(3)} ${cls}`,
        );
    const failing = score.failures.length ? `\nfailing cases:\n  ${score.failures.join('\n  ')}` : '';
    return `${title}: ${score.passed}/${score.total} (${((100 * score.passed) / Math.max(1, score.total)).toFixed(1)}%)\n${rows.join('\n')}${failing}`;
}
