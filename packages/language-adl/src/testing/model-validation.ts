import { URI, type LangiumDocument } from 'langium';
import { builtinDocuments } from '../adl-module.js';
import type { HostLanguageServices } from '../services.js';

/** A diagnostic as tests look at it: with the source text it covers. */
export interface Finding {
    file: string;
    code: string;
    severity: 'error' | 'warning' | 'info' | 'hint';
    text: string;
    message: string;
    line: number;
}

const SEVERITIES = ['error', 'warning', 'info', 'hint'] as const;

/**
 * Builds model roots given as files (path relative to the root -> text) with real services,
 * for the tests of every language package. One bench per test file: building the parser is the
 * expensive part, so the services are created once and each call gets a fresh root.
 */
export class ModelTestBench {
    private services: HostLanguageServices | undefined;
    private counter = 0;

    constructor(
        private readonly create: () => HostLanguageServices,
        private readonly name = 'test',
    ) {}

    get host(): HostLanguageServices {
        return (this.services ??= this.create());
    }

    async build(files: Readonly<Record<string, string>>): Promise<{ root: URI; docs: LangiumDocument[] }> {
        const s = this.host;
        const root = URI.file(`/${this.name}-root-${++this.counter}`);
        s.shared.maa.ModelRoots.setRoots([root]);
        const docs = Object.entries(files).map(([path, text]) =>
            s.shared.workspace.LangiumDocuments.createDocument(URI.file(`${root.path}/${path}`), text),
        );
        await s.shared.workspace.DocumentBuilder.build([...builtinDocuments(s.shared), ...docs], { validation: true });
        return { root, docs };
    }

    async validate(files: Readonly<Record<string, string>>): Promise<Finding[]> {
        const { root, docs } = await this.build(files);
        return docs.flatMap((doc) =>
            (doc.diagnostics ?? []).map((d) => ({
                file: doc.uri.path.substring(root.path.length + 1),
                code: String(d.code),
                severity: SEVERITIES[(d.severity ?? 1) - 1]!,
                text: doc.textDocument.getText(d.range),
                message: d.message,
                line: d.range.start.line + 1,
            })),
        );
    }
}

/** The findings with one of the given codes, as `code@text` strings. */
export function hits(found: readonly Finding[], ...codes: string[]): string[] {
    return found.filter((f) => codes.includes(f.code)).map((f) => `${f.code}@${f.text}`);
}

export function dump(found: readonly Finding[]): string {
    return JSON.stringify(found, null, 1);
}
