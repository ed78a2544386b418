import { readFileSync, type Dirent, type Stats } from 'node:fs';
import { readFile, readdir, stat } from 'node:fs/promises';
import { join, resolve } from 'node:path';
import { DocumentState, URI, isOperationCancelled, type LangiumDocument } from 'langium';
import { builtinDocuments } from '../adl-module.js';
import type { HostLanguageServices } from '../services.js';
import { Codes } from '../validation/codes.js';
import { ReservedNames, type RootConfiguration } from '../validation/reserved-names.js';
import type { Diagnostic } from 'vscode-languageserver-types';

export type Severity = 'error' | 'warning' | 'info' | 'hint';

export interface CheckDiagnostic {
    /** Absolute path of the model root the file was checked in. */
    root: string;
    /** Absolute path of the file. */
    file: string;
    /** 1-based positions. */
    line: number;
    column: number;
    endLine: number;
    endColumn: number;
    severity: Severity;
    code: string;
    message: string;
}

export interface RootSpec {
    /** A model root folder. */
    root: string;
    /** Report only these files (absolute paths); all model files of the root are still loaded. */
    files?: string[];
}

export interface CheckOptions {
    onProgress?: (message: string) => void;
    /** File extensions of model files (default: every language registered in the services). */
    extensions?: readonly string[];
}

/** A problem with the input itself (missing folder, unreadable file): a message for the user. */
export class CheckInputError extends Error {}

const SEVERITIES: readonly Severity[] = ['error', 'warning', 'info', 'hint'];

/**
 * The checking path of `maa-gen check` and the conformance tests: loads every model file of
 * each root (each root an independent scope), builds and validates them in one workspace, and
 * returns the diagnostics sorted by file and position.
 */
export async function checkRoots(
    services: HostLanguageServices,
    specs: readonly RootSpec[],
    options: CheckOptions = {},
): Promise<CheckDiagnostic[]> {
    const shared = services.shared;
    const extensions = options.extensions ?? shared.ServiceRegistry.all.flatMap((s) => s.LanguageMetaData.fileExtensions);
    const reported = reportedFiles(specs);
    const scans = await scanRoots(shared, reported.keys(), extensions);
    const loaded = await loadRoots(shared, scans, options);
    const builtins = builtinDocuments(shared);
    options.onProgress?.(`checking ${loaded.documents.length} files`);
    loaded.failed.push(...(await buildEach(shared, builtins, loaded.documents)));
    return collectDiagnostics(reported, loaded);
}

/** Per model root (absolute), the files to report, or `undefined` for every file of the root. */
type ReportedFiles = Map<string, Set<string> | undefined>;

/** The model files below a root, and the folders below it that are roots of their own. */
interface RootScan {
    files: string[];
    nested: string[];
}

/** The documents created for the model files, with the roots each belongs to. */
interface LoadedFiles {
    readonly documents: LangiumDocument[];
    /** Files whose parsing or building threw. */
    readonly failed: FailedFile[];
    /** Document URI → the model root it lies in (a nested root where there is one). */
    readonly rootOfDoc: Map<string, string>;
    /** Document URI → the root of the spec that named it (which decides whether it is reported). */
    readonly specOfDoc: Map<string, string>;
}

/** Merges the specs by root: a root named without files reports every file, whatever else names it. */
function reportedFiles(specs: readonly RootSpec[]): ReportedFiles {
    const roots: ReportedFiles = new Map();
    for (const spec of specs) {
        const root = resolve(spec.root);
        if (spec.files === undefined) roots.set(root, undefined);
        else if (!roots.has(root) || roots.get(root) !== undefined) {
            const set = roots.get(root) ?? new Set<string>();
            for (const f of spec.files) set.add(resolve(f));
            roots.set(root, set);
        }
    }
    return roots;
}

/**
 * Scans each root and registers the roots with the workspace. Folders below a root that hold a
 * `maa.json` are model roots of their own, as in the editor (so `maa-gen check examples/` checks
 * every example as the project it is).
 */
async function scanRoots(
    shared: HostLanguageServices['shared'],
    roots: Iterable<string>,
    extensions: readonly string[],
): Promise<Map<string, RootScan>> {
    const scans = new Map<string, RootScan>();
    for (const root of roots) scans.set(root, await scanRoot(root, extensions));
    const allRoots = [...scans.keys(), ...[...scans.values()].flatMap((x) => x.nested)];
    shared.maa.ModelRoots.setRoots(allRoots.map((r) => URI.file(r)));
    return scans;
}

/** Configures every root from its `maa.json` and creates a document for each model file. */
async function loadRoots(
    shared: HostLanguageServices['shared'],
    scans: ReadonlyMap<string, RootScan>,
    options: CheckOptions,
): Promise<LoadedFiles> {
    const loaded: LoadedFiles = { documents: [], failed: [], rootOfDoc: new Map(), specOfDoc: new Map() };
    let index = 0;
    for (const [specRoot, scan] of scans) {
        index++;
        options.onProgress?.(`loading ${specRoot} (${index}/${scans.size})`);
        for (const root of [specRoot, ...scan.nested]) {
            const config = await readConfiguration(root);
            if (config) shared.maa.ReservedNames.configure(URI.file(root), config);
        }
        for (const file of scan.files) loadFile(shared, file, specRoot, loaded);
    }
    return loaded;
}

/**
 * Creates the document of one model file (replacing an earlier one), or records why parsing threw.
 * The file is read synchronously: parsing it right after blocks far longer than reading, and one
 * awaited read per file (open, stat, read, close on the thread pool) cost more than the reads
 * themselves for a thousand small files (issue 18).
 */
function loadFile(shared: HostLanguageServices['shared'], file: string, specRoot: string, loaded: LoadedFiles): void {
    let text: string;
    try {
        text = readFileSync(file, 'utf8');
    } catch (e) {
        throw new CheckInputError(`cannot read ${file}: ${(e as NodeJS.ErrnoException).code ?? (e as Error).message}`);
    }
    const uri = URI.file(file);
    const langiumDocuments = shared.workspace.LangiumDocuments;
    if (langiumDocuments.hasDocument(uri)) langiumDocuments.deleteDocument(uri);
    loaded.rootOfDoc.set(uri.toString(), ownRoot(shared, file));
    loaded.specOfDoc.set(uri.toString(), specRoot);
    try {
        loaded.documents.push(langiumDocuments.createDocument(uri, text));
    } catch (e) {
        // Parsing threw (a bug, or input beyond every guard): report the file, check the others.
        loaded.failed.push({ uri, reason: e });
    }
}

/** The model root a file lies in, as the workspace decides it (the nearest registered root). */
function ownRoot(shared: HostLanguageServices['shared'], file: string): string {
    const r = shared.maa.ModelRoots.rootOf(URI.file(file));
    return URI.parse(r).fsPath.replace(/[\\/]$/, '');
}

/** The diagnostics of the reported files (an error for each file that could not be checked), sorted by file and position. */
function collectDiagnostics(reported: ReportedFiles, loaded: LoadedFiles): CheckDiagnostic[] {
    const isReported = (uri: URI): boolean => {
        const only = reported.get(loaded.specOfDoc.get(uri.toString())!);
        return !only || only.has(uri.fsPath);
    };
    const result: CheckDiagnostic[] = [];
    for (const { uri, reason } of loaded.failed) {
        if (isReported(uri)) result.push(notChecked(loaded.rootOfDoc.get(uri.toString())!, uri.fsPath, reason));
    }
    const failedUris = new Set(loaded.failed.map((f) => f.uri.toString()));
    for (const doc of loaded.documents) {
        if (failedUris.has(doc.uri.toString()) || !isReported(doc.uri)) continue;
        const root = loaded.rootOfDoc.get(doc.uri.toString())!;
        for (const d of doc.diagnostics ?? []) result.push(checkDiagnostic(root, doc.uri.fsPath, d));
    }
    result.sort((a, b) => a.file.localeCompare(b.file) || a.line - b.line || a.column - b.column || a.code.localeCompare(b.code));
    return result;
}

/** A document's diagnostic as `maa-gen check` reports it: 1-based positions, a severity name, a string code. */
function checkDiagnostic(root: string, file: string, d: Diagnostic): CheckDiagnostic {
    return {
        root,
        file,
        line: d.range.start.line + 1,
        column: d.range.start.character + 1,
        endLine: d.range.end.line + 1,
        endColumn: d.range.end.character + 1,
        severity: SEVERITIES[(d.severity ?? 1) - 1] ?? 'error',
        code: typeof d.code === 'string' ? d.code : d.code !== undefined ? String(d.code) : 'internal/unclassified',
        message: d.message,
    };
}

/** A file that could not be checked, and why. */
interface FailedFile {
    readonly uri: URI;
    readonly reason: unknown;
}

/**
 * Builds and validates the documents together; if that throws, builds each document that is not
 * yet validated on its own, so one file that breaks the build is reported and the others are
 * still checked. Returns the documents that could not be checked.
 */
async function buildEach(
    shared: HostLanguageServices['shared'],
    builtins: LangiumDocument[],
    documents: LangiumDocument[],
): Promise<FailedFile[]> {
    const builder = shared.workspace.DocumentBuilder;
    try {
        await builder.build([...builtins, ...documents], { validation: true });
        return [];
    } catch (e) {
        if (isOperationCancelled(e)) throw e;
    }
    const failed: FailedFile[] = [];
    for (const doc of documents) {
        if (doc.state >= DocumentState.Validated) continue;
        try {
            await builder.build([doc], { validation: true });
        } catch (e) {
            if (isOperationCancelled(e)) throw e;
            failed.push({ uri: doc.uri, reason: e });
        }
    }
    return failed;
}

/** The diagnostic of a file that could not be checked: an error at its start, with the reason. */
function notChecked(root: string, file: string, reason: unknown): CheckDiagnostic {
    const why =
        reason instanceof RangeError
            ? 'the model is nested too deeply for the parser'
            : reason instanceof Error
              ? reason.message
              : String(reason);
    return {
        root,
        file,
        line: 1,
        column: 1,
        endLine: 1,
        endColumn: 1,
        severity: 'error',
        code: Codes.InternalError,
        message: `This file could not be checked (${why}); the other files were checked. Please report this with the file.`,
    };
}

/** The model files below a root and the folders below it that are roots of their own (`maa.json`). */
async function scanRoot(root: string, extensions: readonly string[]): Promise<RootScan> {
    let info: Stats;
    try {
        info = await stat(root);
    } catch {
        throw new CheckInputError(`no such folder: ${root}`);
    }
    if (!info.isDirectory()) throw new CheckInputError(`not a folder: ${root}`);
    const files: string[] = [];
    const nested: string[] = [];
    const walk = async (dir: string): Promise<void> => {
        let entries: Dirent[];
        try {
            entries = await readdir(dir, { withFileTypes: true });
        } catch (e) {
            throw new CheckInputError(`cannot read folder ${dir}: ${(e as NodeJS.ErrnoException).code ?? (e as Error).message}`);
        }
        entries.sort((a, b) => a.name.localeCompare(b.name));
        if (dir !== root && entries.some((e) => e.isFile() && e.name === ReservedNames.CONFIG_FILE)) nested.push(dir);
        for (const e of entries) {
            if (e.name.startsWith('.') || e.name === 'node_modules') continue;
            const p = join(dir, e.name);
            if (e.isDirectory()) await walk(p);
            else if (extensions.some((x) => e.name.endsWith(x))) files.push(p);
        }
    };
    await walk(root);
    return { files, nested };
}

async function readConfiguration(root: string): Promise<RootConfiguration | undefined> {
    const file = join(root, ReservedNames.CONFIG_FILE);
    let text: string;
    try {
        text = await readFile(file, 'utf8');
    } catch {
        return undefined;
    }
    try {
        return JSON.parse(text) as RootConfiguration;
    } catch (e) {
        throw new CheckInputError(`${file}: invalid JSON (${(e as Error).message})`);
    }
}
