// Helpers for the diagram tests: the family's language-server services with the diagram
// services beside them, the ToastServiceRobot example loaded as a model root (in memory, under
// its real folder's URI), and a diagram client that records what the server sends.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { EmptyFileSystem, URI, type LangiumDocument } from 'langium';
import { TextDocument } from 'vscode-languageserver-textdocument';
import type { ActionMessage, SModelElement, SModelRoot } from 'sprotty-protocol';
import { builtinDocuments, type HostLspServices } from '@maa/language-adl';
import { createMaaLspServices } from '../src/family.js';
import { allElements, createMaaDiagramServices, type MaaDiagramServices } from '../src/diagram/index.js';

export const EXAMPLE = resolve(dirname(fileURLToPath(import.meta.url)), '../../../examples/toast-service');

export interface DiagramWorkspace {
    family: HostLspServices;
    diagrams: MaaDiagramServices;
    root: URI;
    uri(path: string): string;
    doc(path: string): LangiumDocument;
    /** Replaces a file's text and rebuilds what depends on it (like an editor's didChange). */
    edit(path: string, change: (text: string) => string): Promise<void>;
}

let counter = 0;

/** Loads the files of a folder (or given texts) as one model root, validated. */
export async function diagramWorkspace(files: Readonly<Record<string, string>> = exampleFiles()): Promise<DiagramWorkspace> {
    const family = createMaaLspServices(EmptyFileSystem);
    const diagrams = createMaaDiagramServices(family);
    void diagrams.diagram.DiagramServerManager; // listens to builds from now on
    const shared = family.shared;
    const root = URI.file(`/diagram-test-${++counter}`);
    shared.maa.ModelRoots.setRoots([root]);
    const docs = new Map<string, LangiumDocument>();
    for (const [path, text] of Object.entries(files)) {
        docs.set(path, shared.workspace.LangiumDocuments.createDocument(URI.file(`${root.path}/${path}`), text));
    }
    await shared.workspace.DocumentBuilder.build([...builtinDocuments(shared), ...docs.values()], { validation: true });
    const uri = (path: string): string => URI.file(`${root.path}/${path}`).toString();
    const doc = (path: string): LangiumDocument => {
        const d = shared.workspace.LangiumDocuments.getDocument(URI.parse(uri(path)));
        if (!d) throw new Error(`no document ${path}`);
        return d;
    };
    return {
        family,
        diagrams,
        root,
        uri,
        doc,
        async edit(path, change) {
            const d = doc(path);
            const text = change(d.textDocument.getText());
            // As the editor's copy: the open documents win over the (here empty) file system.
            shared.workspace.TextDocuments!.set(
                TextDocument.create(d.uri.toString(), d.textDocument.languageId, d.textDocument.version + 1, text),
            );
            await shared.workspace.DocumentBuilder.update([d.uri], []);
        },
    };
}

/** The example's model files (path below the example -> text). */
export function exampleFiles(dir = EXAMPLE): Record<string, string> {
    const out: Record<string, string> = {};
    const walk = (d: string): void => {
        for (const name of readdirSync(d).sort()) {
            const p = join(d, name);
            if (statSync(p).isDirectory()) walk(p);
            else if (/\.(arc|cd|ra|arcapp)$/.test(name)) out[relative(dir, p)] = readFileSync(p, 'utf8');
        }
    };
    walk(dir);
    return out;
}

/** A diagram client: sends actions to the server manager and records the answers. */
export class TestClient {
    readonly received: ActionMessage[] = [];
    private waiters: Array<() => void> = [];

    constructor(
        private readonly diagrams: MaaDiagramServices,
        readonly clientId = `client-${++counter}`,
    ) {
        diagrams.diagram.DiagramServerManager.onDidSend((m) => {
            if (m.clientId !== this.clientId) return;
            this.received.push(m);
            for (const w of this.waiters.splice(0)) w();
        });
    }

    async requestModel(options: Record<string, unknown>): Promise<SModelRoot> {
        const before = this.received.length;
        await this.diagrams.diagram.DiagramServerManager.acceptAction({
            clientId: this.clientId,
            action: { kind: 'requestModel', requestId: `req-${before}`, options } as ActionMessage['action'],
        });
        const answer = await this.next(before, (k) => k === 'setModel' || k === 'rejectRequest');
        if (answer.action.kind !== 'setModel') throw new Error(`rejected: ${JSON.stringify(answer.action)}`);
        return (answer.action as unknown as { newRoot: SModelRoot }).newRoot;
    }

    /** The first action after index `from` whose kind (and message) matches. */
    async next(from: number, kind: (k: string, m: ActionMessage) => boolean, timeout = 10_000): Promise<ActionMessage> {
        const deadline = Date.now() + timeout;
        for (;;) {
            const found = this.received.slice(from).find((m) => kind(m.action.kind, m));
            if (found) return found;
            if (Date.now() > deadline) throw new Error(`no matching action; got ${this.received.map((m) => m.action.kind).join(', ')}`);
            await new Promise<void>((r) => {
                this.waiters.push(r);
                setTimeout(r, 100);
            });
        }
    }
}

/** Every element of a model by id. */
export function byId(root: SModelElement): Map<string, SModelElement & Record<string, unknown>> {
    return new Map([...allElements(root)].map((e) => [e.id, e as SModelElement & Record<string, unknown>]));
}
