import { URI, type LangiumDocument } from 'langium';
import { builtinDocuments, type HostLanguageServices } from '@maa/language-adl';
import { createRobotArmServices } from '../src/index.js';

export interface Finding {
    file: string;
    code: string;
    severity: 'error' | 'warning' | 'info' | 'hint';
    /** The source text the diagnostic covers. */
    text: string;
    message: string;
    line: number;
}

let shared: HostLanguageServices | undefined;

/** One set of services for a test file (building the parser is the expensive part). */
export function services(): HostLanguageServices {
    return (shared ??= createRobotArmServices());
}

let counter = 0;

/** Builds a model root given as files (path relative to the root -> text) and returns its documents. */
export async function build(files: Readonly<Record<string, string>>): Promise<{ root: URI; docs: LangiumDocument[] }> {
    const s = services();
    const root = URI.file(`/robotarm-test-${++counter}`);
    s.shared.maa.ModelRoots.setRoots([root]);
    const docs = Object.entries(files).map(([path, text]) =>
        s.shared.workspace.LangiumDocuments.createDocument(URI.file(`${root.path}/${path}`), text));
    await s.shared.workspace.DocumentBuilder.build([...builtinDocuments(s.shared), ...docs], { validation: true });
    return { root, docs };
}

/** Validates a model root and returns every diagnostic with the text it covers. */
export async function validate(files: Readonly<Record<string, string>>): Promise<Finding[]> {
    const { root, docs } = await build(files);
    const severities = ['error', 'warning', 'info', 'hint'] as const;
    return docs.flatMap((doc) => (doc.diagnostics ?? []).map((d) => ({
        file: doc.uri.path.substring(root.path.length + 1),
        code: String(d.code),
        severity: severities[(d.severity ?? 1) - 1]!,
        text: doc.textDocument.getText(d.range),
        message: d.message,
        line: d.range.start.line + 1
    })));
}

/** The findings with one of the given codes, as `code@text` strings. */
export function hits(found: Finding[], ...codes: string[]): string[] {
    return found.filter((f) => codes.includes(f.code)).map((f) => `${f.code}@${f.text}`);
}

export function dump(found: Finding[]): string {
    return JSON.stringify(found, null, 1);
}
