import { EmptyFileSystem, URI } from 'langium';
import { builtinDocuments, createAdlServices, type HostLanguageServices } from '../src/index.js';

export interface Finding {
    file: string;
    code: string;
    severity: 'error' | 'warning' | 'info' | 'hint';
    /** The source text the diagnostic covers. */
    text: string;
    message: string;
    line: number;
}

let counter = 0;

/**
 * Validates a model root given as files (path relative to the root -> text) with real services
 * and returns every diagnostic with the text it covers.
 */
export async function validate(files: Readonly<Record<string, string>>, services: HostLanguageServices = createAdlServices(EmptyFileSystem)): Promise<Finding[]> {
    const root = URI.file(`/test-root-${++counter}`);
    services.shared.maa.ModelRoots.setRoots([root]);
    const docs = Object.entries(files).map(([path, text]) =>
        services.shared.workspace.LangiumDocuments.createDocument(URI.file(`${root.fsPath}/${path}`), text));
    await services.shared.workspace.DocumentBuilder.build([...builtinDocuments(services.shared), ...docs], { validation: true });
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
