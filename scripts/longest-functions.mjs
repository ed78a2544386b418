#!/usr/bin/env node
// Lists the longest functions of packages/*/src (TypeScript) and sim-server/src (Python), by lines
// from the declaration to its closing brace. A review aid for issue 13's "ten longest functions"
// list: a function that stays long should read best whole.
// Usage: node scripts/longest-functions.mjs [--top N] [--json]
import { execFileSync } from 'node:child_process';
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

function parseArgs(argv) {
    const options = { top: 10, json: false };
    for (let i = 0; i < argv.length; i++) {
        const arg = argv[i];
        if (arg === '--top') options.top = Number(argv[++i]);
        else if (arg === '--json') options.json = true;
        else if (arg === '--help' || arg === '-h') {
            console.log('usage: node scripts/longest-functions.mjs [--top N] [--json]');
            process.exit(0);
        } else {
            console.error(`longest-functions: unknown argument ${arg}`);
            process.exit(2);
        }
    }
    if (!Number.isInteger(options.top) || options.top < 1) {
        console.error('longest-functions: --top needs a positive whole number');
        process.exit(2);
    }
    return options;
}

/** Hand-written TypeScript files under `dir` (generated code, declarations and tests left out). */
function sourceFiles(dir) {
    const files = [];
    for (const entry of readdirSync(dir)) {
        const full = path.join(dir, entry);
        if (statSync(full).isDirectory()) {
            if (entry !== 'generated' && entry !== 'node_modules') files.push(...sourceFiles(full));
        } else if (/\.tsx?$/.test(entry) && !entry.endsWith('.d.ts')) {
            files.push(full);
        }
    }
    return files;
}

function functionName(node, source) {
    if (node.name) return node.name.getText(source);
    const parent = node.parent;
    if (parent && ts.isVariableDeclaration(parent)) return parent.name.getText(source);
    if (parent && ts.isPropertyAssignment(parent)) return parent.name.getText(source);
    return '(anonymous)';
}

function typescriptFunctions(file) {
    const text = readFileSync(file, 'utf8');
    const source = ts.createSourceFile(file, text, ts.ScriptTarget.Latest, true);
    const found = [];
    const visit = (node) => {
        if (ts.isFunctionLike(node) && 'body' in node && node.body) {
            const start = source.getLineAndCharacterOfPosition(node.getStart(source)).line + 1;
            const end = source.getLineAndCharacterOfPosition(node.getEnd()).line + 1;
            found.push({ file: path.relative(repo, file), line: start, name: functionName(node, source), lines: end - start + 1 });
        }
        ts.forEachChild(node, visit);
    };
    visit(source);
    return found;
}

// Python's own parser, in the simulator's venv (or any python3): every def with its span.
const PYTHON_LISTER = `
import ast, json, pathlib, sys
out = []
for f in sorted(pathlib.Path(sys.argv[1]).rglob("*.py")):
    tree = ast.parse(f.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            out.append({"file": str(f), "line": node.lineno, "name": node.name, "lines": node.end_lineno - node.lineno + 1})
print(json.dumps(out))
`;

function pythonFunctions(dir) {
    const venv = path.join(repo, 'sim-server', '.venv', 'bin', 'python');
    const python = existsSync(venv) ? venv : 'python3';
    const output = execFileSync(python, ['-c', PYTHON_LISTER, dir], { encoding: 'utf8' });
    return JSON.parse(output).map((f) => ({ ...f, file: path.relative(repo, f.file) }));
}

const options = parseArgs(process.argv.slice(2));
const functions = [];
for (const pkg of readdirSync(path.join(repo, 'packages'))) {
    const src = path.join(repo, 'packages', pkg, 'src');
    if (existsSync(src)) for (const file of sourceFiles(src)) functions.push(...typescriptFunctions(file));
}
functions.push(...pythonFunctions(path.join(repo, 'sim-server', 'src')));
functions.sort((a, b) => b.lines - a.lines || a.file.localeCompare(b.file));
const top = functions.slice(0, options.top);
if (options.json) {
    console.log(JSON.stringify(top, null, 1));
} else {
    console.log(`the ${top.length} longest of ${functions.length} functions (lines, name, file:line):`);
    for (const f of top) console.log(`${String(f.lines).padStart(5)}  ${f.name}  ${f.file}:${f.line}`);
}
