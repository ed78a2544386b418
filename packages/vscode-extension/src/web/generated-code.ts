/**
 * **MontiArc: Show Generated Code** and **MontiArc: Show Model Element** in the web entry (the
 * desktop entry's are in ../extension.ts). The generated files are maa-ide's, read over its API as
 * read-only `maa-generated:` documents (generated-files.ts); the lookups are ../trace.ts's, on the
 * trace of the generation Generate ran last in this session, else of the platform the user picks.
 */
import * as vscode from 'vscode';
import { pickPlatform } from '../platform-pick.js';
import { type Generation, onGenerated } from './backend.js';
import {
    appModelRoot,
    GENERATED_SCHEME,
    GeneratedOutput,
    type GeneratedHit,
    type GeneratedRef,
    generatedHits,
    generatedUriParts,
    markerFolders,
    markerOf,
    modelElementOf,
    parseGeneratedUri,
    type WorkspaceTrace,
    workspaceTrace,
} from './generated-files.js';

/** The generated files' documents: their text from `GET /api/generated/file`, refreshed after each generation. */
class GeneratedContent implements vscode.TextDocumentContentProvider {
    private readonly changed = new vscode.EventEmitter<vscode.Uri>();
    readonly onDidChange = this.changed.event;

    constructor(private readonly output: GeneratedOutput) {}

    provideTextDocumentContent(uri: vscode.Uri): Promise<string> {
        const ref = parseGeneratedUri(uri);
        if (!ref) throw new Error(`not a generated file: ${uri.toString()}`);
        return this.output.file(ref);
    }

    /** Re-reads the open documents of a generation. */
    refresh(g: Generation): void {
        for (const doc of vscode.workspace.textDocuments) {
            const ref = parseGeneratedUri(doc.uri);
            if (ref?.app === g.app && ref.platform === g.platform) this.changed.fire(doc.uri);
        }
    }

    dispose(): void {
        this.changed.dispose();
    }
}

/** The commands' state: the backend, the workspace folder, the last generation. */
class GeneratedCode {
    last: Generation | undefined;

    constructor(
        readonly output: GeneratedOutput,
        private readonly root: vscode.Uri,
    ) {}

    /** A workspace path as a URI of the workspace folder's scheme. */
    workspaceUri(path: string): vscode.Uri {
        return this.root.with({ path });
    }

    /** The trace of a generation as the workspace sees it; undefined when it was not generated. */
    async trace(g: Generation): Promise<WorkspaceTrace | undefined> {
        const trace = await this.output.trace(g);
        if (!trace) return undefined;
        const appFile = `${this.root.path.replace(/\/+$/, '')}/${g.app}`;
        const markers = new Set<string>();
        for (const folder of markerFolders(appFile, this.root.path)) {
            const found = await vscode.workspace.fs.stat(this.workspaceUri(markerOf(folder))).then(
                () => true,
                () => false,
            );
            if (found) markers.add(folder);
        }
        return workspaceTrace(g, trace, appModelRoot(appFile, this.root.path, markers));
    }

    /** The generation to look in: the last one of this session, else the platform the user picks. */
    async generation(): Promise<Generation | undefined> {
        if (this.last) return this.last;
        const item = await pickPlatform('Show the generated code of');
        return item && { app: vscode.workspace.asRelativePath(item.appFile, false), platform: item.platform };
    }
}

async function reveal(uri: vscode.Uri, range: vscode.Range): Promise<void> {
    const editor = await vscode.window.showTextDocument(await vscode.workspace.openTextDocument(uri), { preview: true });
    editor.selection = new vscode.Selection(range.start, range.end);
    editor.revealRange(range, vscode.TextEditorRevealType.InCenterIfOutsideViewport);
}

function info(message: string): void {
    void vscode.window.showInformationMessage(`MontiArc: ${message}`);
}

/** The hit to open: the only one, else the user's pick (as on the desktop). */
async function chooseHit(hits: readonly GeneratedHit[]): Promise<GeneratedHit | undefined> {
    if (hits.length === 1) return hits[0];
    const items = hits.map((h) => ({ label: `${h.ref.path}:${h.first + 1}`, description: `${h.ref.platform} · ${h.generator}`, hit: h }));
    return (await vscode.window.showQuickPick(items, { placeHolder: 'Generated code of this element' }))?.hit;
}

async function showGeneratedCode(state: GeneratedCode): Promise<void> {
    const editor = vscode.window.activeTextEditor;
    if (!editor) return;
    const g = await state.generation();
    if (!g) return;
    const trace = await state.trace(g);
    if (!trace) return info(`${g.app} has not been generated for ${g.platform} (run MontiArc: Generate first).`);
    const pos = editor.selection.active;
    const hit = await chooseHit(generatedHits(trace, editor.document.uri.path, { line: pos.line, character: pos.character }));
    if (hit) await reveal(vscode.Uri.from(generatedUriParts(hit.ref)), new vscode.Range(hit.first, 0, hit.last + 1, 0));
    else info(`no generated code of ${g.platform} traced to this element (generate first).`);
}

async function showModelElement(state: GeneratedCode): Promise<void> {
    const editor = vscode.window.activeTextEditor;
    const ref: GeneratedRef | undefined = editor && parseGeneratedUri(editor.document.uri);
    const trace = ref && (await state.trace(ref));
    const element = editor && ref && trace && modelElementOf(trace, ref.path, editor.selection.active.line);
    if (!element) return info('this line is not traced to a model element.');
    const r = element.range;
    await reveal(state.workspaceUri(element.file), new vscode.Range(r.start.line, r.start.character, r.end.line, r.end.character));
}

/** A command that reports its failure (a refused request) instead of failing silently. */
function command(id: string, run: () => Promise<void>): vscode.Disposable {
    return vscode.commands.registerCommand(id, () =>
        run().catch((e: unknown) => {
            void vscode.window.showErrorMessage(`MontiArc: ${e instanceof Error ? e.message : String(e)}`);
        }),
    );
}

/** Registers the content provider and both commands; `apiBase` is backendBase(). */
export function registerGeneratedCode(context: vscode.ExtensionContext, apiBase: string): void {
    const root = vscode.workspace.workspaceFolders?.[0]?.uri ?? vscode.Uri.file('/');
    const output = new GeneratedOutput(apiBase);
    const state = new GeneratedCode(output, root);
    const content = new GeneratedContent(output);
    const stop = onGenerated((g) => {
        state.last = g;
        content.refresh(g);
    });
    context.subscriptions.push(
        content,
        { dispose: stop },
        vscode.workspace.registerTextDocumentContentProvider(GENERATED_SCHEME, content),
        command('maa.showGeneratedCode', () => showGeneratedCode(state)),
        command('maa.showModelElement', () => showModelElement(state)),
    );
}
