// The connector checks keep the ports and the instantaneous paths of each component type once
// per build (validation/checks/port-cache.ts, issue 18). These tests pin what must not change:
// findings through cycles of component types (where the paths depend on where the walk began and
// are not kept), through a composed type used in several places, and after relinking (the kept
// facts are dropped when documents are linked again).
import { EmptyFileSystemProvider, URI, type FileSystemNode, type LangiumDocument } from 'langium';
import { describe, expect, test } from 'vitest';
import { builtinDocuments, createAdlServices } from '../src/index.js';
import { hits } from '../src/testing/index.js';
import { validate } from './helpers.js';

const CODES = ['arc/feedback-not-causal', 'arc/unconnected-sub-in-port', 'arc/unconnected-sub-out-port', 'arc/unused-in-port'];

describe('connector checks with the facts of component types kept per build', () => {
    test('a cycle of component types: the same findings whichever file is checked first', async () => {
        const a = 'package p;\ncomponent A {\n  port in int i;\n  port out int o;\n  B b;\n  i -> b.i;\n  b.o -> o;\n}\n';
        const b =
            'package p;\ncomponent B {\n  port in int i;\n  port <<delayed>> out int o;\n  port out int q;\n  A a;\n  i -> a.i;\n  a.o -> o;\n  a.o -> q;\n}\n';
        const top =
            'package p;\ncomponent Top {\n  port in int i;\n  port out int o;\n  A x;\n  B y;\n  A z;\n  x.o -> y.i;\n  y.q -> x.i;\n  y.o -> z.i;\n  z.o -> o;\n}\n';
        const expected = ['arc/unconnected-sub-out-port@b', 'arc/unused-in-port@i'];
        expect(hits(await validate({ 'p/A.arc': a, 'p/B.arc': b, 'p/Top.arc': top }), ...CODES).sort()).toEqual(expected);
        expect(hits(await validate({ 'p/Top.arc': top, 'p/B.arc': b, 'p/A.arc': a }), ...CODES).sort()).toEqual(expected);
    });

    test('a composed type in several places: each loop is judged by the paths through it', async () => {
        const leaf = 'package p;\ncomponent Leaf {\n  port in int i, j;\n  port out int o;\n  port <<delayed>> out int d;\n}\n';
        const mid =
            'package p;\ncomponent Mid {\n  port in int i;\n  port out int o, d;\n  Leaf l;\n  i -> l.i, l.j;\n  l.o -> o;\n  l.d -> d;\n}\n';
        const top =
            'package p;\ncomponent Top {\n  port out int o;\n  Mid m1, m2;\n  Mid m3;\n  m1.o -> m2.i;\n  m2.o -> m1.i;\n  m3.d -> m3.i;\n  m1.d -> o;\n}\n';
        const top2 = 'package p;\ncomponent Top2 {\n  port out int o;\n  Top t;\n  Mid m;\n  m.o -> m.i;\n  t.o -> o;\n}\n';
        const found = await validate({ 'p/Leaf.arc': leaf, 'p/Mid.arc': mid, 'p/Top.arc': top, 'p/Top2.arc': top2 });
        expect(hits(found, ...CODES).sort()).toEqual([
            'arc/feedback-not-causal@m.o -> m.i;',
            'arc/feedback-not-causal@m2.o -> m1.i;',
            'arc/unconnected-sub-out-port@m',
            'arc/unconnected-sub-out-port@m2',
            'arc/unconnected-sub-out-port@m3',
        ]);
    });

    test('after a change of a used component type the checks see its new ports and paths', async () => {
        const files = new Map<string, string>();
        const services = createAdlServices({ fileSystemProvider: () => new MemoryFileSystem(files) });
        const shared = services.shared;
        const root = URI.file('/facts-root');
        shared.maa.ModelRoots.setRoots([root]);
        const put = (path: string, text: string): URI => {
            const uri = URI.file(`${root.path}/${path}`);
            files.set(uri.toString(), text);
            return uri;
        };
        const inner = (delayed: string) =>
            `package p;\ncomponent Inner {\n  port in int i;\n  port ${delayed}out int o;\n  port out int extra;\n}\n`;
        const innerUri = put('p/Inner.arc', inner(''));
        // Mid's document does not change, but the paths through it do (they pass through Inner).
        const midUri = put(
            'p/Mid.arc',
            'package p;\ncomponent Mid {\n  port in int i;\n  port out int o;\n  Inner n;\n  i -> n.i;\n  n.o -> o;\n}\n',
        );
        const outerUri = put(
            'p/Outer.arc',
            'package p;\ncomponent Outer {\n  port out int o;\n  Mid m;\n  Inner n;\n  m.o -> m.i;\n  m.o -> o;\n  n.o -> n.i;\n}\n',
        );
        const docs: LangiumDocument[] = [innerUri, midUri, outerUri].map((u) =>
            shared.workspace.LangiumDocuments.createDocument(u, files.get(u.toString()) ?? ''),
        );
        await shared.workspace.DocumentBuilder.build([...builtinDocuments(shared), ...docs], { validation: true });
        const codesOf = (uri: URI): string[] =>
            (shared.workspace.LangiumDocuments.getDocument(uri)?.diagnostics ?? [])
                .map((d) => `${String(d.code)}@${d.message.split(' ').slice(0, 6).join(' ')}`)
                .sort();
        const before = [
            "arc/feedback-not-causal@The feedback loop through port 'm.o'",
            "arc/feedback-not-causal@The feedback loop through port 'n.o'",
            "arc/unconnected-sub-out-port@Outgoing port 'extra' of subcomponent 'n'",
        ];
        expect(codesOf(outerUri)).toEqual(before);

        // Inner's output becomes delayed and loses `extra`: Outer is relinked and checked again.
        put('p/Inner.arc', 'package p;\ncomponent Inner {\n  port in int i;\n  port <<delayed>> out int o;\n}\n');
        await shared.workspace.DocumentBuilder.update([innerUri], []);
        expect(codesOf(outerUri)).toEqual([]);

        put('p/Inner.arc', inner(''));
        await shared.workspace.DocumentBuilder.update([innerUri], []);
        expect(codesOf(outerUri)).toEqual(before);
    });
});

/** Files in memory (URI string -> text), for documents the builder reads again after a change. */
class MemoryFileSystem extends EmptyFileSystemProvider {
    constructor(private readonly files: ReadonlyMap<string, string>) {
        super();
    }
    private node(uri: URI): FileSystemNode {
        return { uri, isFile: this.files.has(uri.toString()), isDirectory: !this.files.has(uri.toString()) };
    }
    override async stat(uri: URI): Promise<FileSystemNode> {
        return this.node(uri);
    }
    override statSync(uri: URI): FileSystemNode {
        return this.node(uri);
    }
    override async readFile(uri: URI): Promise<string> {
        return this.readFileSync(uri);
    }
    override readFileSync(uri: URI): string {
        const text = this.files.get(uri.toString());
        if (text === undefined) throw new Error(`no file ${uri.toString()}`);
        return text;
    }
}
