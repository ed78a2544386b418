import { readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { AstUtils, EmptyFileSystem, URI, type ReferenceInfo } from 'langium';
import { describe, expect, test } from 'vitest';
import { createAdlServices } from '../src/index.js';
import { astNodesOf, forEachReference } from '../src/workspace/ast-walk.js';

// The checker's linking, reference index and validation walk the AST with src/workspace/ast-walk.ts
// instead of Langium's streams: the same nodes and references in the same order, or diagnostics
// (and the first of several equal ones) could change.

const examples = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'examples');

function arcFiles(dir: string): string[] {
    return readdirSync(dir).flatMap((name) => {
        const p = path.join(dir, name);
        if (statSync(p).isDirectory()) return name === 'node_modules' || name.startsWith('.') ? [] : arcFiles(p);
        return name.endsWith('.arc') ? [p] : [];
    });
}

const refKey = (r: ReferenceInfo): string => `${r.container.$type}.${r.property}[${r.index ?? ''}]=${r.reference.$refText}`;

describe('the AST walks of the checker', () => {
    const services = createAdlServices(EmptyFileSystem);
    const files = arcFiles(examples);

    test('visit every node of every example, in the order of AstUtils.streamAst', () => {
        expect(files.length).toBeGreaterThan(10);
        let nodes = 0;
        for (const file of files) {
            const doc = services.shared.workspace.LangiumDocumentFactory.fromString(readFileSync(file, 'utf8'), URI.file(file));
            const root = doc.parseResult.value;
            const expected = AstUtils.streamAst(root).toArray();
            expect(astNodesOf(root), file).toEqual(expected);
            nodes += expected.length;
        }
        expect(nodes).toBeGreaterThan(300);
    });

    test('give every reference, in the order of AstUtils.streamReferences', () => {
        let refs = 0;
        for (const file of files) {
            const doc = services.shared.workspace.LangiumDocumentFactory.fromString(readFileSync(file, 'utf8'), URI.file(file));
            for (const node of AstUtils.streamAst(doc.parseResult.value)) {
                const expected = AstUtils.streamReferences(node).map(refKey).toArray();
                const found: string[] = [];
                forEachReference(node, (r) => found.push(refKey(r)));
                expect(found, `${file} ${node.$type}`).toEqual(expected);
                refs += expected.length;
            }
        }
        expect(refs).toBeGreaterThan(100);
    });

    test('differ from a wrong order (the comparison can fail)', () => {
        const file = files[0]!;
        const doc = services.shared.workspace.LangiumDocumentFactory.fromString(readFileSync(file, 'utf8'), URI.file(file));
        const nodes = astNodesOf(doc.parseResult.value);
        expect([...nodes].reverse()).not.toEqual(AstUtils.streamAst(doc.parseResult.value).toArray());
    });
});
