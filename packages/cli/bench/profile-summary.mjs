// Where the time of a benchmark phase goes, from a V8 CPU profile (`node --cpu-prof`): every
// sample is given to the innermost function on its stack that names a stage of checking (below),
// else to "other". check-bench.mjs prints it with --profile: the profile that shows what bounds
// issue 18's goals 1 and 2 (docs/performance.md).
import { readFileSync } from 'node:fs';

/** Stages by the names of the functions that do them (Langium's and the family's). */
const STAGES = [
    ['garbage collection', ['(garbage collector)']],
    ['parser construction (grammar analysis)', ['performSelfAnalysis', 'createParser', 'createAdlParser']],
    ['lexing', ['tokenize']],
    ['parsing (rules, CST, AST)', ['parse']],
    ['exported names (index)', ['collectExportedSymbols']],
    ['linking (scopes, name lookups)', ['link']],
    ['reference index', ['createDescriptions']],
    ['validation (checks)', ['validateAstNodes', 'validateAstBefore', 'validateAstAfter', 'validateDocument']],
    ['loading the code', ['compileSourceTextModule', 'compileFunction']],
    ['reading files', ['readFileUtf8', 'readFile', 'readdirSync', 'readdir']],
];
const stageOf = new Map(STAGES.flatMap(([stage, names]) => names.map((n) => [n, stage])));

/** [stage, ms, share] rows of one profile file, the costliest first; idle time left out. */
export function profileStages(file) {
    const profile = JSON.parse(readFileSync(file, 'utf8'));
    const nodes = new Map(profile.nodes.map((n) => [n.id, n]));
    const stage = new Map();
    const assign = (id, inherited) => {
        const node = nodes.get(id);
        const own = stageOf.get(node.callFrame.functionName) ?? inherited;
        stage.set(id, own);
        for (const child of node.children ?? []) assign(child, own);
    };
    assign(profile.nodes[0].id, 'other');
    const ms = new Map();
    let total = 0;
    profile.samples.forEach((id, i) => {
        if (nodes.get(id).callFrame.functionName === '(idle)') return;
        const dt = (profile.timeDeltas[i] ?? 0) / 1000;
        total += dt;
        ms.set(stage.get(id), (ms.get(stage.get(id)) ?? 0) + dt);
    });
    return [...ms].sort((a, b) => b[1] - a[1]).map(([name, t]) => [name, t, t / total]);
}
