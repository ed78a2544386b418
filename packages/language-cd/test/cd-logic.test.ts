import {
    createDefaultCoreModule,
    createDefaultSharedCoreModule,
    EmptyFileSystem,
    inject,
    type LangiumCoreServices,
    type LangiumDocument,
    URI,
} from 'langium';
import { describe, expect, it } from 'vitest';
import { CdGeneratedModule, ClassDiagramGeneratedSharedModule } from '../src/generated/module.js';
import {
    type CdFileLocation,
    CdCodes,
    cdExportedNames,
    cdExportedNamesOf,
    cdModelOf,
    cdPackageOf,
    cdTypeNamed,
    cdTypesOf,
    registerCdChecks,
} from '../src/index.js';

// Class diagrams on their own: a service container of the `ClassDiagram` project alone (no host
// language), with the checks of this package installed. The family installs the same checks into
// its `.cd` services (see @maa/language-adl's createHostServices).

/** Models under `memory:/root/`; the package of a file is its folder below the root; `builtin:` files are the library. */
const location: CdFileLocation = {
    isBuiltin: (uri) => uri.scheme === 'builtin',
    expectedPackage: (uri) =>
        uri.path
            .replace(/^\/root\//, '')
            .split('/')
            .slice(0, -1)
            .join('.'),
};

function cdServices(): LangiumCoreServices {
    const shared = inject(createDefaultSharedCoreModule(EmptyFileSystem), ClassDiagramGeneratedSharedModule);
    const cd = inject(createDefaultCoreModule({ shared }), CdGeneratedModule);
    shared.ServiceRegistry.register(cd);
    registerCdChecks(cd.validation.ValidationRegistry, location);
    return cd;
}

async function check(path: string, text: string): Promise<{ doc: LangiumDocument; findings: string[] }> {
    const services = cdServices();
    const uri = URI.parse(path.startsWith('builtin:') ? path : `memory:/root/${path}`);
    const doc = services.shared.workspace.LangiumDocumentFactory.fromString(text, uri);
    services.shared.workspace.LangiumDocuments.addDocument(doc);
    await services.shared.workspace.DocumentBuilder.build([doc], { validation: true });
    expect(doc.parseResult.parserErrors).toEqual([]);
    const findings = (doc.diagnostics ?? [])
        .filter((d) => d.severity === 1)
        .map((d) => `${String(d.code)}@${doc.textDocument.getText(d.range)}`);
    return { doc, findings };
}

describe('class-diagram checks (language-cd on its own)', () => {
    it('accepts a diagram named like its file in the package of its folder', async () => {
        const { findings } = await check(
            't/Types.cd',
            'package t;\nclassdiagram Types {\n  enum Color { RED, GREEN; }\n  class Point { int x; }\n}',
        );
        expect(findings).toEqual([]);
    });

    it('reports a diagram named unlike its file', async () => {
        const { findings } = await check('t/Types.cd', 'package t;\nclassdiagram Other { }');
        expect(findings).toEqual([`${CdCodes.FileNameMismatch}@Other`]);
    });

    it('reports a package that is not the folder, on the package or, without one, on the name', async () => {
        expect((await check('t/Types.cd', 'package x;\nclassdiagram Types { }')).findings).toEqual([`${CdCodes.PackageMismatch}@x`]);
        expect((await check('t/Types.cd', 'classdiagram Types { }')).findings).toEqual([`${CdCodes.PackageMismatch}@Types`]);
    });

    it('reports a type declared twice and an enum constant declared twice, once each', async () => {
        const { findings } = await check(
            't/Types.cd',
            'package t;\nclassdiagram Types {\n  class A;\n  class A;\n  class A;\n  enum Color { RED, RED; }\n}',
        );
        expect(findings).toEqual([`${CdCodes.DuplicateName}@A`, `${CdCodes.DuplicateName}@RED`]);
    });

    it('does not check the location of built-in files', async () => {
        const { findings } = await check('builtin:/java/lang/Lang.cd', 'package java.lang;\nclassdiagram Library { }');
        expect(findings).toEqual([]);
    });
});

describe('class-diagram declarations', () => {
    it('lists the named types, finds one by name and gives both exported names', async () => {
        const { doc } = await check(
            't/Types.cd',
            'package t;\nclassdiagram Types {\n  class A;\n  enum E { X; }\n  association link A -> A;\n}',
        );
        const model = cdModelOf(doc.parseResult.value);
        expect(model).toBeDefined();
        if (!model) return;
        expect(cdTypesOf(model).map((t) => t.name)).toEqual(['A', 'E']);
        const e = cdTypeNamed(doc.parseResult.value, 'E');
        expect(e?.$type).toBe('CDEnum');
        expect(cdTypeNamed(doc.parseResult.value, 'Missing')).toBeUndefined();
        if (!e) return;
        expect(cdExportedNames(model, e)).toEqual(['t.Types.E', 't.E']);
        expect(cdExportedNamesOf(e)).toEqual(['t.Types.E', 't.E']);
        expect(cdExportedNamesOf(model)).toEqual([]);
        expect(cdPackageOf(e)).toBe('t');
    });

    it('gives names without a package when the diagram has none', async () => {
        const { doc } = await check('Types.cd', 'classdiagram Types {\n  class A;\n}');
        const a = cdTypeNamed(doc.parseResult.value, 'A');
        expect(a?.name).toBe('A');
        if (!a) return;
        expect(cdExportedNamesOf(a)).toEqual(['Types.A', 'A']);
        expect(cdPackageOf(a)).toBeUndefined();
    });
});
