#!/usr/bin/env node
// @ts-check
/**
 * Composes the grammars of a language family into one Langium project.
 *
 * Langium generates all grammars of one service container as one project (one AstReflection),
 * and a grammar cannot leave a rule open for others to fill. So each language package declares
 * its grammar files in `package.json` under `maa.language`, and this tool copies the grammars
 * of the named packages into one build folder, writes the two "slot" grammars that close the
 * extension points, and runs `langium generate` there:
 *   - `names.langium`: `Name`, the identifier rule, admitting every language's soft keywords;
 *   - `slot.langium`:  `Behavior`, the union of the host's behaviors and every registered
 *                      behavior language's entry rule.
 *
 * Usage: maa-compose-grammar --project NAME --out DIR [--build DIR] [--registry FILE.ts] [--family] [PACKAGE...]
 * Each PACKAGE is a package name resolvable from the current directory, or `.`. With --family
 * the packages are read from the current package.json's `maa.family` list (a language family's
 * one registration entry per language). With --registry the tool also writes a TypeScript module
 * exporting `BEHAVIOR_LANGUAGES`, the run-time registration objects (`maa.language.behavior.export`)
 * of the composed behavior languages.
 *
 * The tool also writes the family's language facts next to the generated sources:
 * `language-facts.json` and `language-facts.ts` (`LANGUAGE_FACTS`): each language's id, file
 * extensions, aliases, keywords read from the composed grammar (hard and soft) and scope names
 * (see ../lib/language-facts.mjs). The IDE's highlighting and the CLI's file discovery read them.
 */
import { spawnSync } from 'node:child_process';
import { copyFileSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { basename, dirname, join, relative, resolve } from 'node:path';
import { computeLanguageFacts, languageFactsModule } from '../lib/language-facts.mjs';

/**
 * @typedef {{ id: string, grammar: string, fileExtensions: string[], aliases?: string[], export?: string }} LanguageEntry
 * @typedef {{ grammars: string[], languages?: LanguageEntry[], hostBehaviors?: string[],
 *             behavior?: { rule: string, keyword: string, export?: string, id?: string, aliases?: string[] },
 *             softKeywords?: string[],
 *             hostBehaviorGrammars?: string[] }} LanguageManifest
 */

/** @param {string[]} argv */
function parseArgs(argv) {
    /** @type {{ project?: string, out?: string, build: string, registry?: string, packages: string[] }} */
    const opts = { build: 'build/grammar', packages: [] };
    for (let i = 0; i < argv.length; i++) {
        const a = argv[i];
        if (a === '--project') opts.project = argv[++i];
        else if (a === '--out') opts.out = argv[++i];
        else if (a === '--build') opts.build = argv[++i];
        else if (a === '--registry') opts.registry = argv[++i];
        else if (a === '--family') {
            const own = JSON.parse(readFileSync(join(process.cwd(), 'package.json'), 'utf8'));
            opts.packages.push(...(own.maa?.family ?? []));
        } else if (a === '--help' || a === '-h') {
            console.log('Usage: maa-compose-grammar --project NAME --out DIR [--build DIR] [--registry FILE.ts] [--family] [PACKAGE...]');
            process.exit(0);
        } else opts.packages.push(a);
    }
    if (!opts.project || !opts.out || opts.packages.length === 0) {
        console.error('maa-compose-grammar: --project, --out and at least one package are required (see --help)');
        process.exit(2);
    }
    return /** @type {{ project: string, out: string, build: string, registry?: string, packages: string[] }} */ (opts);
}

/** @param {string} spec */
function packageDir(spec) {
    if (spec === '.') return process.cwd();
    const require = createRequire(join(process.cwd(), 'package.json'));
    return dirname(require.resolve(`${spec}/package.json`));
}

async function main() {
    const opts = parseArgs(process.argv.slice(2));
    const buildDir = resolve(opts.build);
    rmSync(buildDir, { recursive: true, force: true });
    mkdirSync(buildDir, { recursive: true });

    /** @type {LanguageEntry[]} */
    const languages = [];
    /** @type {string[]} */
    const behaviorRules = [];
    /** @type {string[]} */
    const behaviorFiles = [];
    /** @type {Set<string>} */
    const softKeywords = new Set();
    /** @type {Array<{ pkg: string, name: string }>} */
    const registrations = [];
    /** @type {Array<{ pkg: string, name: string, module: string }>} */
    const languageRegistrations = [];
    /** @type {import('../lib/language-facts.mjs').ComposedPackage[]} */
    const composed = [];

    for (const spec of opts.packages) {
        const dir = packageDir(spec);
        const pkg = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8'));
        /** @type {LanguageManifest | undefined} */
        const manifest = pkg.maa?.language;
        if (!manifest) {
            console.error(`maa-compose-grammar: package ${pkg.name} declares no "maa.language" in its package.json`);
            process.exit(2);
        }
        for (const g of manifest.grammars) {
            copyFileSync(join(dir, g), join(buildDir, basename(g)));
        }
        for (const kw of manifest.softKeywords ?? []) softKeywords.add(kw);
        composed.push({
            package: pkg.name,
            languages: manifest.languages ?? [],
            behavior: manifest.behavior,
            softKeywords: manifest.softKeywords ?? [],
        });
        for (const rule of manifest.hostBehaviors ?? []) behaviorRules.push(rule);
        if (manifest.behavior) {
            if (!manifest.behavior.export) {
                console.error(
                    `maa-compose-grammar: package ${pkg.name} declares a behavior language without "export" (the name of its BehaviorLanguage object)`,
                );
                process.exit(2);
            }
            registrations.push({ pkg: pkg.name, name: manifest.behavior.export });
            behaviorRules.push(manifest.behavior.rule);
            behaviorFiles.push(basename(manifest.grammars[manifest.grammars.length - 1]));
        }
        // Every language of every composed package is an entry point of the project, so the
        // generated services serve all of them with one shared AST reflection.
        languages.push(...(manifest.languages ?? []));
        // Languages other than the host's (e.g. standalone `.ra` files) bring a registration
        // object; the family creates a service container for each.
        for (const l of manifest.languages ?? []) {
            if (!l.export) continue;
            const text = readFileSync(join(dir, manifest.grammars.find((g) => basename(g) === basename(l.grammar)) ?? l.grammar), 'utf8');
            const grammarName = /^\s*grammar\s+(\w+)/m.exec(text)?.[1];
            if (!grammarName) {
                console.error(`maa-compose-grammar: ${pkg.name}: ${l.grammar} declares no grammar name`);
                process.exit(2);
            }
            languageRegistrations.push({ pkg: pkg.name, name: l.export, module: `${grammarName}GeneratedModule` });
        }
        if (manifest.hostBehaviors) behaviorFiles.push(...(manifest.hostBehaviorGrammars ?? []));
    }

    const nameAlternatives = ['ID', ...[...softKeywords].sort().map((k) => `'${k}'`)];
    writeFileSync(
        join(buildDir, 'names.langium'),
        '// Generated by maa-compose-grammar: identifiers, admitting the soft keywords of the family.\n' +
            "import './terminals'\n\n" +
            `Name returns string:\n    ${nameAlternatives.join(' | ')};\n`,
    );
    if (behaviorRules.length > 0) {
        const imports = [...new Set(behaviorFiles)].map((f) => `import './${f.replace(/\.langium$/, '')}'`).join('\n');
        writeFileSync(
            join(buildDir, 'slot.langium'),
            '// Generated by maa-compose-grammar: the behavior extension point of the host language.\n' +
                `${imports}\n\nBehavior:\n    ${behaviorRules.join(' | ')};\n`,
        );
    }

    const outDir = resolve(opts.out);
    // The output folder holds generated files only; start it afresh so langium-cli never finds
    // "unexpected files" (it would ask to delete them and, without a terminal, write nothing).
    rmSync(outDir, { recursive: true, force: true });
    const config = {
        projectName: opts.project,
        // Production mode: the parser must not print its ambiguity reports (Tick as a soft
        // keyword is one, resolved as intended) into the output of tools such as `maa-gen --format json`.
        mode: 'production',
        // `export` and `aliases` are ours (the registration object, the language facts), not
        // langium-cli's: its schema rejects them.
        languages: languages.map(({ export: _export, aliases: _aliases, ...l }) => ({ ...l, grammar: basename(l.grammar) })),
        out: relative(buildDir, outDir),
    };
    writeFileSync(join(buildDir, 'langium-config.json'), JSON.stringify(config, null, 2) + '\n');

    // langium-cli is ESM-only without a resolvable bin path; npm scripts put its `langium`
    // command on PATH.
    const result = spawnSync('langium', ['generate', '--file', join(buildDir, 'langium-config.json')], { stdio: 'inherit', cwd: buildDir });
    if (result.error) {
        console.error(`maa-compose-grammar: cannot run langium-cli (${result.error.message}); run me through an npm script`);
        process.exit(2);
    }
    // Written after langium-cli, which treats unknown files in its output folder as stale.
    if (result.status === 0 && opts.registry) {
        let moduleImport = relative(dirname(resolve(opts.registry)), join(resolve(opts.out), 'module.js'));
        if (!moduleImport.startsWith('.')) moduleImport = `./${moduleImport}`;
        const lines = [
            '// Generated by maa-compose-grammar from the family list: the composed languages.',
            "import type { BehaviorLanguage, FamilyLanguage } from '@maa/language-adl';",
            ...registrations.map((r) => `import { ${r.name} } from '${r.pkg}';`),
            ...languageRegistrations.map((r) => `import { ${r.name} } from '${r.pkg}';`),
            ...(languageRegistrations.length
                ? [`import { ${languageRegistrations.map((r) => r.module).join(', ')} } from '${moduleImport}';`]
                : []),
            '',
            `export const BEHAVIOR_LANGUAGES: readonly BehaviorLanguage[] = [${registrations.map((r) => r.name).join(', ')}];`,
            '',
            '/** Further languages of the family with their generated modules (one service container each). */',
            `export const FAMILY_LANGUAGES: readonly FamilyLanguage[] = [${languageRegistrations.map((r) => `{ ...${r.name}, generated: ${r.module} }`).join(', ')}];`,
            '',
        ];
        mkdirSync(dirname(resolve(opts.registry)), { recursive: true });
        writeFileSync(resolve(opts.registry), lines.join('\n'));
    }

    if (result.status === 0) {
        const facts = await computeLanguageFacts(buildDir, composed);
        mkdirSync(outDir, { recursive: true });
        writeFileSync(join(outDir, 'language-facts.json'), JSON.stringify(facts, null, 2) + '\n');
        writeFileSync(join(outDir, 'language-facts.ts'), languageFactsModule(facts));
    }

    process.exit(result.status ?? 1);
}

main().catch((e) => {
    console.error(`maa-compose-grammar: ${e instanceof Error ? e.message : String(e)}`);
    process.exit(1);
});
