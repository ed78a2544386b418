// Generates a synthetic model root for the benchmark (see check-bench.mjs):
// N components in package folders robot/pNN, mixed atomic (80%) and composed (20%), 10 ports
// each, port types from a class diagram (enums and classes) in types/Types.cd.
// The models are meant to be free of errors, so that the benchmark measures a realistic
// "everything resolves and every rule runs" workload.
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';

export const PACKAGES = 20;
/** Port type families: packages p and p + FAMILIES share port types, so they can be wired. */
const FAMILIES = 5;
const ENUMS = 10;
const CLASSES = 10;

const pad = (n) => String(n).padStart(2, '0');
const pkgName = (p) => `robot.p${pad(p)}`;
const pkgDir = (p) => path.join('robot', `p${pad(p)}`);
const atomicName = (p, k) => `A${pad(p)}_${pad(k)}`;
const composedName = (p, k) => `C${pad(p)}_${pad(k)}`;

function portTypes(p) {
    const f = p % FAMILIES;
    return ['int', 'double', 'boolean', `Mode${f}`, `Data${f}`];
}

function ports(p) {
    const types = portTypes(p);
    return [...types.map((t, i) => `  port in ${t} i${i};`), ...types.map((t, i) => `  port out ${t} o${i};`)];
}

function classDiagram() {
    const lines = ['package types;', '', 'classdiagram Types {'];
    for (let e = 0; e < ENUMS; e++) {
        lines.push(`  enum Mode${e} { M0, M1, M2, M3, M4; }`);
    }
    for (let c = 0; c < CLASSES; c++) {
        lines.push(`  class Data${c} {`, '    int id;', '    double value;', `    Mode${c % ENUMS} mode;`);
        if (c > 0) lines.push(`    Data${c - 1} previous;`);
        lines.push('  }');
    }
    lines.push('  class Pair<A, B> {', '    A first;', '    B second;', '  }', '}', '');
    return lines.join('\n');
}

/** The line of every atomic component that the incremental benchmark edits. */
export const EDITABLE_LINE = '    o1 = i1 / 2.0;';

function atomic(p, k) {
    const f = p % FAMILIES;
    return [
        `package ${pkgName(p)};`,
        '',
        'import types.Types.*;',
        '',
        `component ${atomicName(p, k)}(int gain = 1) {`,
        ...ports(p),
        '',
        '  int count = 0;',
        '',
        '  compute {',
        '    count++;',
        '    o0 = i0 * gain + count;',
        EDITABLE_LINE,
        '    o2 = !i2 && i0 > 0;',
        `    o3 = i2 ? Mode${f}.M1 : i3;`,
        '    o4 = i4;',
        '  }',
        '}',
        '',
    ].join('\n');
}

function composed(p, k, atomics) {
    // a and c from this package, b from another package of the same port type family; c is the
    // previous composed component of the package (hierarchy), or an atomic one for the first.
    const remote = (p + FAMILIES) % PACKAGES;
    const a = atomicName(p, (2 * k) % atomics);
    const b = `${pkgName(remote)}.${atomicName(remote, k % atomics)}`;
    const c = k > 0 ? composedName(p, k - 1) : atomicName(p, (2 * k + 1) % atomics);
    const lines = [
        `package ${pkgName(p)};`,
        '',
        'import types.Types.*;',
        '',
        `component ${composedName(p, k)} {`,
        ...ports(p),
        '',
        `  ${a} a(${k + 2});`,
        `  ${b} b;`,
        `  ${c} c;`,
        '',
    ];
    // parent inputs -> a -> b -> c -> parent outputs
    for (let i = 0; i < 5; i++) lines.push(`  i${i} -> a.i${i};`);
    for (let i = 0; i < 5; i++) lines.push(`  a.o${i} -> b.i${i};`);
    for (let i = 0; i < 5; i++) lines.push(`  b.o${i} -> c.i${i};`);
    for (let i = 0; i < 5; i++) lines.push(`  c.o${i} -> o${i};`);
    lines.push('}', '');
    return lines.join('\n');
}

/**
 * Writes the model root into `root` and returns what was generated.
 * @param {string} root
 * @param {number} components total number of components (a multiple of PACKAGES works best)
 */
export function generateModels(root, components) {
    const perPackage = Math.max(1, Math.ceil(components / PACKAGES));
    const composedPerPackage = Math.max(0, Math.floor(perPackage / 5));
    const atomicPerPackage = perPackage - composedPerPackage;
    const files = [];
    let lines = 0;
    const write = (rel, text) => {
        const file = path.join(root, rel);
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, text);
        files.push(file);
        lines += text.split('\n').length - 1;
    };

    write(path.join('types', 'Types.cd'), classDiagram());
    let atomicCount = 0;
    let composedCount = 0;
    const editable = [];
    for (let p = 0; p < PACKAGES && atomicCount + composedCount < components; p++) {
        for (let k = 0; k < atomicPerPackage && atomicCount + composedCount < components; k++) {
            const rel = path.join(pkgDir(p), `${atomicName(p, k)}.arc`);
            write(rel, atomic(p, k));
            editable.push(path.join(root, rel));
            atomicCount++;
        }
        for (let k = 0; k < composedPerPackage && atomicCount + composedCount < components; k++) {
            write(path.join(pkgDir(p), `${composedName(p, k)}.arc`), composed(p, k, atomicPerPackage));
            composedCount++;
        }
    }
    return { root, files, lines, atomic: atomicCount, composed: composedCount, editable };
}

/**
 * A top component `robot.System` instantiating every component type of a generated root, with
 * the subcomponents' inputs fed from its own ports; returns the number of component types.
 */
export function writeSystemComponent(root, gen) {
    const types = gen.files
        .filter((f) => f.endsWith('.arc'))
        .map((f) =>
            path
                .relative(root, f)
                .replace(/\.arc$/, '')
                .split(path.sep)
                .join('.'),
        );
    const lines = ['package robot;', '', 'import types.Types.*;', '', 'component System {'];
    const portTypes = (f) => ['int', 'double', 'boolean', `Mode${f}`, `Data${f}`];
    for (let f = 0; f < 5; f++) for (const [i, t] of portTypes(f).entries()) lines.push(`  port in ${t} i${i}_${f};`);
    const byFamily = [[], [], [], [], []];
    types.forEach((qn, k) => {
        const p = Number(/\.p(\d+)\./.exec(qn)[1]);
        lines.push(`  ${qn} x${k};`);
        byFamily[p % 5].push(`x${k}`);
    });
    for (let f = 0; f < 5; f++) {
        if (byFamily[f].length === 0) continue;
        for (let i = 0; i < 5; i++) lines.push(`  i${i}_${f} -> ${byFamily[f].map((x) => `${x}.i${i}`).join(', ')};`);
    }
    lines.push('}', '');
    writeFileSync(path.join(root, 'robot', 'System.arc'), lines.join('\n'));
    return types.length + 1;
}
