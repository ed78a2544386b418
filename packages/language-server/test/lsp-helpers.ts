// Helpers for the LSP feature tests: the family's language-server services (one instance per
// test file; building the parser is the expensive part), model roots given as files, and
// cursor markers in model text.
import { EmptyFileSystem, URI, type LangiumDocument } from 'langium';
import { TextDocument } from 'vscode-languageserver-textdocument';
import type { Position, Range, TextEdit, WorkspaceEdit } from 'vscode-languageserver-types';
import { builtinDocuments, type AdlLspServices, type HostLspServices } from '@maa/language-adl';
import { createMaaLspServices } from '../src/family.js';

let shared: HostLspServices | undefined;

export function lspServices(): HostLspServices {
    return (shared ??= createMaaLspServices(EmptyFileSystem));
}

/** The services of the language a document belongs to. */
export function servicesOf(doc: LangiumDocument): AdlLspServices {
    return lspServices().shared.ServiceRegistry.getServices(doc.uri) as AdlLspServices;
}

export const CURSOR = '<|>';

/** Text without its cursor marker and the marker's offset. */
export function cursor(text: string): { text: string; offset: number } {
    const offset = text.indexOf(CURSOR);
    if (offset < 0) throw new Error('no cursor marker in the text');
    return { text: text.replace(CURSOR, ''), offset };
}

let counter = 0;

export interface Workspace {
    root: URI;
    docs: Map<string, LangiumDocument>;
    doc(path: string): LangiumDocument;
    /** The position of the cursor marker that was in a file's text. */
    position(path: string): Position;
}

/**
 * Builds a model root from files (path relative to the root -> text; one file may contain the
 * cursor marker `<|>`) and validates it, in a folder of its own (roots never see each other).
 */
export async function workspace(files: Readonly<Record<string, string>>): Promise<Workspace> {
    const s = lspServices();
    const root = URI.file(`/lsp-test-${++counter}`);
    s.shared.maa.ModelRoots.setRoots([...s.shared.maa.ModelRoots.all().map((r) => URI.parse(r)), root]);
    const docs = new Map<string, LangiumDocument>();
    const cursors = new Map<string, number>();
    for (const [path, raw] of Object.entries(files)) {
        let text = raw;
        if (raw.includes(CURSOR)) {
            const c = cursor(raw);
            text = c.text;
            cursors.set(path, c.offset);
        }
        docs.set(path, s.shared.workspace.LangiumDocuments.createDocument(URI.file(`${root.path}/${path}`), text));
    }
    await s.shared.workspace.DocumentBuilder.build([...builtinDocuments(s.shared), ...docs.values()], { validation: true });
    const doc = (path: string): LangiumDocument => {
        const d = docs.get(path);
        if (!d) throw new Error(`no file ${path}`);
        return d;
    };
    return {
        root,
        docs,
        doc,
        position(path) {
            const offset = cursors.get(path);
            if (offset === undefined) throw new Error(`no cursor in ${path}`);
            return doc(path).textDocument.positionAt(offset);
        },
    };
}

/** The text of a document after applying edits. */
export function applyEdits(doc: LangiumDocument, edits: readonly TextEdit[]): string {
    return TextDocument.applyEdits(doc.textDocument, [...edits]);
}

/** The text of every document a workspace edit changes, after the edit (by path below the root). */
export function applyWorkspaceEdit(ws: Workspace, edit: WorkspaceEdit | undefined): Record<string, string> {
    const out: Record<string, string> = {};
    if (!edit) return out;
    const byUri = new Map<string, TextEdit[]>();
    for (const [uri, edits] of Object.entries(edit.changes ?? {})) byUri.set(uri, [...edits]);
    for (const change of edit.documentChanges ?? []) {
        if ('textDocument' in change)
            byUri.set(change.textDocument.uri, [...(byUri.get(change.textDocument.uri) ?? []), ...(change.edits as TextEdit[])]);
    }
    for (const [path, doc] of ws.docs) {
        const edits = byUri.get(doc.uri.toString());
        if (edits) out[path] = applyEdits(doc, edits);
    }
    return out;
}

/** The text a range covers. */
export function textAt(doc: LangiumDocument, range: Range): string {
    return doc.textDocument.getText(range);
}

/** Class diagram used by several tests (`toast.types`). */
export const TYPES_CD = `package toast.types;

classdiagram Types {
  enum ToastColor { WHITE, GOLDEN, BURNT; }
  enum ToasterCmd { START, STOP; }
  class JointTarget {
    double speed;
  }
}
`;

/** A decoded semantic token: its line, its text, its type and its modifiers (sorted). */
export interface SemanticToken {
    line: number;
    text: string;
    type: string;
    modifiers: string[];
}

/** The semantic tokens of a document as the editor would read them (LSP's relative encoding decoded). */
export async function semanticTokensOf(doc: LangiumDocument): Promise<SemanticToken[]> {
    const provider = servicesOf(doc).lsp.SemanticTokenProvider!;
    const result = await provider.semanticHighlight(doc, { textDocument: { uri: doc.uri.toString() } });
    const types = Object.entries(provider.tokenTypes as Record<string, number>);
    const modifiers = Object.entries(provider.tokenModifiers as Record<string, number>);
    const out: SemanticToken[] = [];
    let line = 0;
    let char = 0;
    for (let i = 0; i < result.data.length; i += 5) {
        const [dl, dc, length, type, mods] = result.data.slice(i, i + 5) as [number, number, number, number, number];
        line += dl;
        char = dl === 0 ? char + dc : dc;
        out.push({
            line,
            text: doc.textDocument.getText({ start: { line, character: char }, end: { line, character: char + length } }),
            type: types.find(([, v]) => v === type)?.[0] ?? '?',
            modifiers: modifiers
                .filter(([, v]) => (mods & v) !== 0)
                .map(([k]) => k)
                .sort(),
        });
    }
    return out;
}
