import { EmptyFileSystem, type DefaultSharedCoreModuleContext } from 'langium';
import { createHostServices, type HostLanguageServices } from '@maa/language-adl';
import { ModelTestBench } from '@maa/language-adl/testing';
import { AutomataLanguage } from '@maa/language-automata';
import {
    ArcAppGeneratedModule,
    ArcGeneratedModule,
    CdGeneratedModule,
    TestFamilyGeneratedSharedModule,
} from '../build/test-family/module.js';
import { ArcAppLanguage, configureGeneratorRegistry, DEMO_GENERATOR_MANIFESTS, GeneratorRegistry } from '../src/index.js';

/**
 * A language family for the tests, composed like the real one (package.json `generate:test`):
 * the host languages, automata and the application configuration language.
 */
export function createTestFamily(context: DefaultSharedCoreModuleContext = EmptyFileSystem): HostLanguageServices {
    return createHostServices(
        context,
        { shared: TestFamilyGeneratedSharedModule, arc: ArcGeneratedModule, cd: CdGeneratedModule },
        [AutomataLanguage],
        [{ ...ArcAppLanguage, generated: ArcAppGeneratedModule }],
    );
}

export const DEMO_REGISTRY = GeneratorRegistry.fromManifests(DEMO_GENERATOR_MANIFESTS, 'demo-generators', '/demo');

export interface Finding {
    file: string;
    code: string;
    severity: 'error' | 'warning' | 'info' | 'hint';
    text: string;
    message: string;
    line: number;
    related: string[];
}

const bench = new ModelTestBench(() => createTestFamily(), 'app');

export function services(): HostLanguageServices {
    return bench.host;
}

/** Validates a model root given as files (path -> text) with the given generators installed. */
export async function validate(files: Readonly<Record<string, string>>, registry: GeneratorRegistry = DEMO_REGISTRY): Promise<Finding[]> {
    configureGeneratorRegistry(services().shared, registry);
    const { root, docs } = await bench.build(files);
    const severities = ['error', 'warning', 'info', 'hint'] as const;
    return docs.flatMap((doc) =>
        (doc.diagnostics ?? []).map((d) => ({
            file: doc.uri.path.substring(root.path.length + 1),
            code: String(d.code),
            severity: severities[(d.severity ?? 1) - 1]!,
            text: doc.textDocument.getText(d.range),
            message: d.message,
            line: d.range.start.line + 1,
            related: (d.relatedInformation ?? []).map(
                (r) => `${r.location.uri.substring(r.location.uri.lastIndexOf('/') + 1)}:${r.location.range.start.line + 1} ${r.message}`,
            ),
        })),
    );
}

export function dump(found: unknown): string {
    return JSON.stringify(found, null, 1);
}
