// The walk-through of docs/extending.md, proven: a third behavior language (lookup tables, in
// test/fixtures/table-language) is composed with the host by the real `maa-compose-grammar`
// and registered only from this test, through the public API of @maa/language-adl. If adding
// it needed a change to language-adl (its grammar, its code, or anything not exported from
// '@maa/language-adl'), this test fails.
import { execFile } from 'node:child_process';
import { promisify } from 'node:util';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { delimiter, dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { AstUtils, EmptyFileSystem, URI, type AstNode, type LangiumDocument } from 'langium';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import {
    builtinDocuments,
    createHostServices,
    type BehaviorLanguage,
    type GeneratedModules,
    type HostLanguageServices,
    type ast,
} from '@maa/language-adl';
import { TABLE_DIAGNOSTICS } from './fixtures/table-language/table-diagnostics.js';
import { TableCodes, TableLanguage, type Table, type TableAssignment, type TableRow } from './fixtures/table-language/table-language.js';
import { renderDiagnosticsMarkdown } from '../src/index.js';

const here = dirname(fileURLToPath(import.meta.url));
const fixtureDir = join(here, 'fixtures', 'table-language');

/** The monorepo root: the nearest folder above this test whose package.json declares workspaces. */
function repoRoot(): string {
    for (let dir = here; dirname(dir) !== dir; dir = dirname(dir)) {
        const pkg = join(dir, 'package.json');
        if (existsSync(pkg) && JSON.parse(readFileSync(pkg, 'utf8')).workspaces) return dir;
    }
    throw new Error(`no workspace root above ${here}`);
}

let tmp = '';
let services: HostLanguageServices;
let registry: readonly BehaviorLanguage[];

beforeAll(async () => {
    const root = repoRoot();
    // build/ is ignored by git (root .gitignore: **/build/); each run composes into a fresh folder.
    mkdirSync(join(fixtureDir, 'build'), { recursive: true });
    tmp = mkdtempSync(join(fixtureDir, 'build', 'compose-'));
    // Step 4 of the walk-through: the host packages by name, the fixture package as `.`.
    // Asynchronous: a worker blocked in spawnSync cannot answer Vitest's RPC (a minute on a loaded machine fails the run).
    await promisify(execFile)(
        process.execPath,
        [
            join(root, 'packages', 'grammar-composer', 'bin', 'maa-compose-grammar.mjs'),
            '--project',
            'TableFixture',
            '--build',
            join(tmp, 'grammar'),
            '--out',
            join(tmp, 'generated'),
            '--registry',
            join(tmp, 'generated', 'behavior-languages.ts'),
            '@maa/language-cd',
            '@maa/language-adl',
            '.',
        ],
        {
            cwd: fixtureDir,
            encoding: 'utf8',
            // langium-cli's `langium` command, as npm scripts put it on PATH.
            env: { ...process.env, PATH: `${join(root, 'node_modules', '.bin')}${delimiter}${process.env.PATH ?? ''}` },
        },
    ).catch((e: { stdout?: string; stderr?: string; message: string }) => {
        throw new Error(`maa-compose-grammar failed: ${e.message}\n${e.stdout ?? ''}\n${e.stderr ?? ''}`);
    });

    const generated = (await import(pathToFileURL(join(tmp, 'generated', 'module.ts')).href)) as Record<
        string,
        GeneratedModules[keyof GeneratedModules]
    >;
    // The registry module imports `TableLanguage` by package name (the fixture's package.json `exports`).
    ({ BEHAVIOR_LANGUAGES: registry } = (await import(pathToFileURL(join(tmp, 'generated', 'behavior-languages.ts')).href)) as {
        BEHAVIOR_LANGUAGES: readonly BehaviorLanguage[];
    });
    services = createHostServices(
        EmptyFileSystem,
        {
            shared: generated.TableFixtureGeneratedSharedModule as GeneratedModules['shared'],
            arc: generated.ArcGeneratedModule as GeneratedModules['arc'],
            cd: generated.CdGeneratedModule as GeneratedModules['cd'],
        },
        [TableLanguage],
    );
});

afterAll(() => {
    if (tmp) rmSync(tmp, { recursive: true, force: true });
});

// ---- helpers ----

interface Finding {
    file: string;
    code: string;
    severity: 'error' | 'warning' | 'info' | 'hint';
    /** The source text the diagnostic covers. */
    text: string;
    line: number;
    message: string;
}

let counter = 0;

async function build(files: Readonly<Record<string, string>>): Promise<{ root: URI; docs: LangiumDocument[] }> {
    const root = URI.file(`/table-fixture-${++counter}`);
    services.shared.maa.ModelRoots.setRoots([root]);
    const docs = Object.entries(files).map(([path, text]) =>
        services.shared.workspace.LangiumDocuments.createDocument(URI.file(`${root.path}/${path}`), text),
    );
    await services.shared.workspace.DocumentBuilder.build([...builtinDocuments(services.shared), ...docs], { validation: true });
    return { root, docs };
}

async function validate(files: Readonly<Record<string, string>>): Promise<Finding[]> {
    const { root, docs } = await build(files);
    const severities = ['error', 'warning', 'info', 'hint'] as const;
    return docs.flatMap((doc) =>
        (doc.diagnostics ?? []).map((d) => ({
            file: doc.uri.path.substring(root.path.length + 1),
            code: String(d.code),
            severity: severities[(d.severity ?? 1) - 1]!,
            text: doc.textDocument.getText(d.range),
            line: d.range.start.line + 1,
            message: d.message,
        })),
    );
}

/** The findings with one of the given codes, as `code@text@line` strings. */
function hits(found: Finding[], ...codes: string[]): string[] {
    return found.filter((f) => codes.includes(f.code)).map((f) => `${f.code}@${f.text}@${f.line}`);
}

const dump = (found: unknown): string => JSON.stringify(found, null, 1);

function nodes<T extends AstNode>(doc: LangiumDocument, type: T['$type']): T[] {
    return AstUtils.streamAst(doc.parseResult.value)
        .filter((n): n is T => n.$type === type)
        .toArray();
}

/** The running example of docs/extending.md. */
const GAIN = `component Gain {
  port in int level;
  port out double factor;
  port out boolean active;
  table {
    level == 0 => factor = 0.0, active = false;
    level < 3  => factor = 0.5, active = true;
    default    => factor = 1.0, active = true;
  }
}
`;

// ---- the composition ----

describe('composition (maa-compose-grammar)', () => {
    test("fills the host's Behavior slot with the fixture's rule and admits its soft keyword as a name", () => {
        expect(readFileSync(join(tmp, 'grammar', 'slot.langium'), 'utf8')).toMatch(/Behavior:\s*ComputeBlock \| InitBlock \| Table;/);
        // The fixture's soft keyword beside the host's own (`feature`, `type`, ...).
        expect(readFileSync(join(tmp, 'grammar', 'names.langium'), 'utf8')).toMatch(
            /Name returns string:\s*ID(?: \| '\w+')* \| 'table'(?: \| '\w+')*;/,
        );
        // The host's grammars are copied unchanged from the language-adl package.
        const adl = join(repoRoot(), 'packages', 'language-adl', 'src', 'grammar', 'arc.langium');
        expect(readFileSync(join(tmp, 'grammar', 'arc.langium'), 'utf8')).toBe(readFileSync(adl, 'utf8'));
    });

    test("the generated registry lists the fixture's registration object (imported by package name)", () => {
        expect(registry).toEqual([TableLanguage]);
        expect(registry[0]).toBe(TableLanguage);
    });

    test('the language facts list the fixture as a behavior language of the host, with its keywords from the grammar', async () => {
        type Facts = typeof import('../src/generated/language-facts.js').LANGUAGE_FACTS;
        const json = JSON.parse(readFileSync(join(tmp, 'generated', 'language-facts.json'), 'utf8')) as Facts;
        const { LANGUAGE_FACTS } = (await import(pathToFileURL(join(tmp, 'generated', 'language-facts.ts')).href)) as {
            LANGUAGE_FACTS: Facts;
        };
        expect(LANGUAGE_FACTS).toEqual(json);
        const table = json.languages.find((l) => l.id === 'table');
        expect(table).toMatchObject({
            kind: 'behavior',
            package: '@maa-fixtures/table-language',
            blockKeyword: 'table',
            fileExtensions: [],
        });
        // `table` is soft (package.json); `default` comes from DefaultRow, the expression keywords from the host's Expression.
        expect(table?.softKeywords).toContain('table');
        expect(table?.keywords).toEqual(expect.arrayContaining(['default', 'true', 'false']));
        expect(table?.keywords).not.toContain('table');
        // The host's files may hold `table { }` blocks; its own keywords do not include the fixture's.
        const arc = json.languages.find((l) => l.id === 'arc');
        expect(arc?.embeds).toEqual(['table']);
        expect(arc?.fileExtensions).toEqual(['.arc']);
        expect(json.languages.map((l) => l.id)).toEqual(['arc', 'cd', 'table']);
        expect(json.softKeywords).toContain('table');
    });

    test('the fixture uses only the public API of @maa/language-adl (no deep imports)', () => {
        for (const file of readdirSync(fixtureDir).filter((f) => f.endsWith('.ts'))) {
            const text = readFileSync(join(fixtureDir, file), 'utf8');
            const specifiers = [...text.matchAll(/\bfrom\s+'([^']+)'/g)].map((m) => m[1]!);
            for (const s of specifiers) expect(s, `${file} imports ${s}`).toMatch(/^(langium|@maa\/language-adl|\.\/[\w-]+\.js)$/);
        }
    });
});

// ---- syntax ----

describe('parsing', () => {
    test('a component with a table block parses without syntax errors and checks clean', async () => {
        const found = await validate({ 'Gain.arc': GAIN });
        expect(found, dump(found)).toEqual([]);
        const {
            docs: [doc],
        } = await build({ 'Gain.arc': GAIN });
        const [table] = nodes<Table>(doc!, 'Table');
        expect(table).toBeDefined();
        expect(table!.$container?.$type).toBe('BehaviorDeclaration');
        expect(table!.rows.map((r) => r.guard.$cstNode?.text)).toEqual(['level == 0', 'level < 3']);
        expect(table!.rows.map((r) => r.assignments.map((a) => a.target.$refText).join(','))).toEqual(['factor,active', 'factor,active']);
        expect(table!.otherwise?.assignments.map((a) => a.value.$cstNode?.text)).toEqual(['1.0', 'true']);
    });

    test("the timing stereotype of the host's BehaviorDeclaration applies to a table too", async () => {
        const found = await validate({ 'Gain.arc': GAIN.replace('  table {', '  <<sync>> table {') });
        expect(found, dump(found)).toEqual([]);
    });

    test('`table` stays usable as a name (soft keyword in package.json)', async () => {
        const found = await validate({
            'Lookup.arc':
                'component Lookup {\n  port in int table;\n  port out int o;\n  table {\n    table > 0 => o = table;\n    default => o = 0;\n  }\n}',
        });
        expect(found, dump(found)).toEqual([]);
    });

    test('`default` is a hard keyword: in this family no port may be called `default`', async () => {
        const found = await validate({ 'Sink.arc': 'component Sink {\n  port in int default;\n}' });
        expect(
            found.filter((f) => f.code.startsWith('syntax/')).map((f) => `${f.text}@${f.line}`),
            dump(found),
        ).toContain('default@2');
    });

    test('rows after `default` are a syntax error: `default` is the last row', async () => {
        const found = await validate({
            'Gain.arc':
                'component Gain {\n  port in int level;\n  port out double factor;\n  table {\n    default => factor = 1.0;\n    level == 0 => factor = 0.0;\n  }\n}',
        });
        expect(found.filter((f) => f.code.startsWith('syntax/')).map((f) => f.line)).toContain(6);
    });

    test('an automaton block fails to parse: the slot holds only the languages composed here', async () => {
        const {
            docs: [doc],
        } = await build({ 'Blink.arc': 'component Blink {\n  port out boolean light;\n  automaton {\n    initial state Off;\n  }\n}' });
        const syntax = (doc!.diagnostics ?? []).filter((d) => String(d.code).startsWith('syntax/'));
        expect(syntax.length, dump(doc!.diagnostics)).toBeGreaterThan(0);
        expect(syntax[0]!.range.start.line + 1).toBe(3);
        expect(AstUtils.streamAst(doc!.parseResult.value).some((n) => n.$type === 'Automaton')).toBe(false);
    });
});

// ---- symbolic integration ----

describe('names in rows', () => {
    test("targets resolve to the component's ports through the contributed scope; guards and values through the host's", async () => {
        const {
            docs: [doc],
        } = await build({ 'Gain.arc': GAIN });
        const ports = nodes<ast.Port>(doc!, 'Port');
        const port = (name: string): ast.Port => ports.find((p) => p.name === name)!;
        const targets = nodes<TableAssignment>(doc!, 'TableAssignment').map((a) => a.target.ref);
        expect(targets).toEqual([port('factor'), port('active'), port('factor'), port('active'), port('factor'), port('active')]);
        for (const t of targets) expect(t?.$type).toBe('Port');
        const guardNames = nodes<TableRow>(doc!, 'TableRow').flatMap((r) =>
            AstUtils.streamAst(r.guard)
                .filter((n): n is ast.NameExpression => n.$type === 'NameExpression')
                .toArray(),
        );
        expect(guardNames.map((n) => n.ref.ref)).toEqual([port('level'), port('level')]);
    });

    test("the scope of a target holds the component's ports, inherited ones included; values see parameters and fields", async () => {
        const { docs } = await build({
            'Base.arc': 'component Base {\n  port out int fromBase;\n}',
            'Comp.arc':
                'component Comp(int p) extends Base {\n  port in int i;\n  port out int o;\n  int f = 0;\n  table {\n    i > p => fromBase = f, o = p;\n    default => o = 0, fromBase = 0;\n  }\n}',
        });
        const doc = docs.find((d) => d.uri.path.endsWith('/Comp.arc'))!;
        expect(doc.diagnostics, dump(doc.diagnostics)).toEqual([]);
        const [first] = nodes<TableAssignment>(doc, 'TableAssignment');
        const scope = services.Arc.references.ScopeProvider.getScope({ container: first!, property: 'target', reference: first!.target });
        expect(
            scope
                .getAllElements()
                .map((d) => d.name)
                .toArray(),
        ).toEqual(['i', 'o', 'fromBase']);
        expect(AstUtils.getDocument(first!.target.ref!).uri.path).toMatch(/\/Base\.arc$/);
        const values = nodes<ast.NameExpression>(doc, 'NameExpression').map((n) => `${n.ref.$refText}:${n.ref.ref?.$type}`);
        expect(values).toEqual(['i:Port', 'p:Parameter', 'f:Field', 'p:Parameter']);
    });

    test('find references of a port includes its uses as table targets (one shared scope)', async () => {
        const {
            docs: [doc],
        } = await build({ 'Gain.arc': GAIN });
        const factor = nodes<ast.Port>(doc!, 'Port').find((p) => p.name === 'factor')!;
        const refs = services.Arc.references.References.findReferences(factor, { includeDeclaration: false }).toArray();
        expect(refs.map((r) => r.segment.range.start.line + 1)).toEqual([6, 7, 8]);
    });
});

// ---- well-formedness ----

describe('checks', () => {
    test("the fixture's own checks report their codes at the right place", async () => {
        const found = await validate({
            'Gain.arc':
                'component Gain {\n  port in int level;\n  port out double factor;\n  table {\n' +
                '    level - 1 => factor = 0.0;\n' + // line 5: guard not boolean
                '    level == 1 => level = 0;\n' + // line 6: incoming port assigned
                '    level == 2 => gain = 0.0;\n' + // line 7: no such port
                '    level == 3 => factor = "x";\n' + // line 8: value of the wrong type
                '  }\n}',
        });
        expect(hits(found, ...Object.values(TableCodes)).sort(), dump(found)).toEqual([
            'table/guard-not-boolean@level - 1@5',
            'table/no-default@table@4',
            'table/target-not-outgoing@level@6',
            'table/unknown-target@gain@7',
            'table/value-type-mismatch@"x"@8',
        ]);
        expect(found.find((f) => f.code === TableCodes.NoDefault)!.severity).toBe('warning');
        expect(found.find((f) => f.code === TableCodes.ValueTypeMismatch)!.message).toContain('double');
        expect(
            found.filter((f) => !f.code.startsWith('table/')),
            dump(found),
        ).toEqual([]);
    });

    test('host checks still run: a second behavior, a connector in an atomic component, host expression typing', async () => {
        const found = await validate({
            'Gain.arc':
                'component Gain {\n  port in int level;\n  port out double factor;\n  level -> factor;\n' +
                '  compute { factor = 1.0; }\n' +
                '  table {\n    levl == 0 => factor = 0.0;\n    default => factor = 1.0;\n  }\n}',
        });
        expect(hits(found, 'arc/multiple-behaviors', 'arc/connector-in-atomic', 'expr/unresolved-name').sort(), dump(found)).toEqual([
            'arc/connector-in-atomic@level -> factor;@4',
            'arc/multiple-behaviors@table {\n    levl == 0 => factor = 0.0;\n    default => factor = 1.0;\n  }@6',
            'expr/unresolved-name@levl@7',
        ]);
    });
});

// Every documented diagnostic is checked on its invalid and its valid example (as the real
// languages' catalog tests do), so the catalog rendered into docs/diagnostics.md cannot drift.
describe.each(TABLE_DIAGNOSTICS.entries.map((e) => [e.code, e] as const))('catalog: %s', (code, entry) => {
    test('is reported on the invalid example, which shows this one problem only', async () => {
        const found = await validate(entry.invalid.files);
        const mine = found.filter((f) => f.code === code);
        expect(mine, dump(found)).not.toHaveLength(0);
        expect(mine.map((h) => h.severity)).toContain(entry.severity);
        if (entry.invalid.at !== undefined) expect(mine.map((h) => h.text)).toContain(entry.invalid.at);
        expect(
            found.filter((f) => f.code !== code),
            dump(found),
        ).toEqual([]);
    });
    test('is not reported on the valid example, which has no diagnostics at all', async () => {
        const found = await validate(entry.valid.files);
        expect(found, dump(found)).toEqual([]);
    });
});

describe('documentation', () => {
    test("every table code is documented, and the family's renderer turns the catalog into docs/diagnostics.md sections", () => {
        const documented = TABLE_DIAGNOSTICS.entries.map((e) => e.code);
        expect([...documented].sort()).toEqual(Object.values(TableCodes).sort());
        expect(TableLanguage.diagnostics).toBe(TABLE_DIAGNOSTICS);
        const md = renderDiagnosticsMarkdown([TABLE_DIAGNOSTICS]);
        expect(md).toContain('## Lookup tables (test fixture)');
        for (const code of documented) expect(md).toContain(`### ${code}`);
    });
});
