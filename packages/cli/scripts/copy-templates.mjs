#!/usr/bin/env node
// Build step of @maa/cli (after tsc): copies the project templates of `maa-gen new` into
// dist/templates/<name>, and writes dist/templates/templates.json (name, description, app).
// The sources are listed in templates/templates.json: `minimal` lives in this package,
// `toast-service` IS the repository's examples/toast-service, copied here so there is no second
// hand-edited copy and a packed @maa/cli (whose `files` holds dist/) carries every template; the
// lab exercises are the starters of examples/lab/<name>/ with their description as README.md (an
// exercise with a `base` in its exercise.json: the base's files without those it omits, with the
// starter folder's over them, as the lab server releases it).
import { copyFileSync, existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { layerStarter } from '@maa/protocol/exercise';

const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const repoDir = path.resolve(packageDir, '..', '..');
const outDir = path.join(packageDir, 'dist', 'templates');

/** Names that are never part of a template: generated output, caches, hidden files. */
export function skipped(name) {
    return name.startsWith('.') || name === 'node_modules' || name === 'generated' || name === '__pycache__';
}

/** Every file below `dir` (relative, `/`-separated, sorted), without the skipped names. */
export function templateFiles(dir) {
    const out = [];
    const visit = (rel) => {
        const entries = readdirSync(path.join(dir, rel), { withFileTypes: true }).sort((a, b) => (a.name < b.name ? -1 : 1));
        for (const entry of entries) {
            if (skipped(entry.name)) continue;
            const child = rel ? `${rel}/${entry.name}` : entry.name;
            if (entry.isDirectory()) visit(child);
            else if (entry.isFile()) out.push(child);
        }
    };
    visit('');
    return out;
}

/**
 * The README of a template copied from a folder of the repository, made true for a project of its
 * own: paths that start with the folder (`examples/toast-service/TR.arcapp`) become relative to
 * the project, and links into the rest of the repository (`../../docs/x.md`) become plain text
 * naming the repository file, since a new project has no docs/ beside it.
 */
export function adaptReadme(text, fromRepoPath, templateName) {
    const escaped = fromRepoPath.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
    const up = '../'.repeat(fromRepoPath.split('/').length);
    const upEscaped = up.replace(/[.]/g, '\\.');
    const adapted = text
        .replace(new RegExp(`${escaped}/`, 'g'), '')
        .replace(new RegExp(`${escaped}(?![\\w-])`, 'g'), '.')
        .replace(new RegExp(`\\[([^\\]]+)\\]\\(${upEscaped}([^)#]+)(#[^)]*)?\\)`, 'g'), (_m, label, target) =>
            label === target ? `\`${target}\` of the repository` : `${label} (\`${target}\` of the repository)`,
        );
    const note =
        `> Created by \`maa-gen new ${templateName}\` from \`${fromRepoPath}\` of the MontiArcAutomaton for the web ` +
        'repository; files named "of the repository" are in that repository, not in this project.\n\n';
    const firstBreak = adapted.indexOf('\n\n');
    return firstBreak < 0 ? `${adapted}\n\n${note}` : `${adapted.slice(0, firstBreak + 2)}${note}${adapted.slice(firstBreak + 2)}`;
}

/**
 * The files of a template: relative path → the file to copy. A lab exercise's starter (`from`,
 * beside its exercise.json) with a `base`: the base's files, without those `omit` names, with the
 * starter's over them.
 */
export function templateSources(from) {
    const own = templateFiles(from);
    const exerciseJson = path.join(path.dirname(from), 'exercise.json');
    const exercise = existsSync(exerciseJson) ? JSON.parse(readFileSync(exerciseJson, 'utf8')) : {};
    if (typeof exercise.base !== 'string') return own.map((rel) => ({ rel, file: path.join(from, rel) }));
    const base = path.resolve(path.dirname(from), ...exercise.base.split('/'));
    const { files, issues } = layerStarter(exercise, templateFiles(base), own);
    if (issues.length > 0) throw new Error(`${exerciseJson}: ${issues.map((i) => `${i.pointer}: ${i.message}`).join('; ')}`);
    return files.map((f) => ({ rel: f.path, file: path.join(f.from === 'base' ? base : from, f.path) }));
}

function copyTemplate(template) {
    const from = path.resolve(packageDir, template.from);
    const to = path.join(outDir, template.name);
    const outsidePackage = path.relative(packageDir, from).startsWith('..');
    const files = templateSources(from);
    for (const { rel, file } of files) {
        const target = path.join(to, ...rel.split('/'));
        mkdirSync(path.dirname(target), { recursive: true });
        if (outsidePackage && rel === 'README.md') {
            const fromRepoPath = path.relative(repoDir, from).split(path.sep).join('/');
            writeFileSync(target, adaptReadme(readFileSync(file, 'utf8'), fromRepoPath, template.name));
        } else {
            copyFileSync(file, target);
        }
    }
    if (template.readme) {
        // A lab exercise (examples/lab/<name>/starter): its description becomes the project's README.
        copyFileSync(path.resolve(packageDir, template.readme), path.join(to, 'README.md'));
        return files.length + 1;
    }
    return files.length;
}

function main() {
    const manifest = JSON.parse(readFileSync(path.join(packageDir, 'templates', 'templates.json'), 'utf8'));
    rmSync(outDir, { recursive: true, force: true });
    mkdirSync(outDir, { recursive: true });
    const counts = manifest.templates.map((t) => `${t.name} (${copyTemplate(t)} files)`);
    const published = manifest.templates.map(({ name, description, app }) => ({ name, description, app }));
    writeFileSync(path.join(outDir, 'templates.json'), `${JSON.stringify({ templates: published }, null, 2)}\n`);
    console.log(`templates: ${counts.join(', ')} -> ${path.relative(packageDir, outDir)}`);
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) main();
