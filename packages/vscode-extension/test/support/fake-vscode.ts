// A minimal stand-in for the `vscode` module, enough for the stream test controller
// (src/testing/controller.ts): the Testing API objects record what a run reports, the workspace
// reads a real folder. Tests install it with `vi.mock('vscode', () => import('./support/fake-vscode.js'))`.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

export class Uri {
    private constructor(
        readonly scheme: string,
        readonly path: string,
    ) {}
    static file(p: string): Uri {
        return new Uri('file', p);
    }
    get fsPath(): string {
        return this.path;
    }
    with(change: { path: string }): Uri {
        return new Uri(this.scheme, change.path);
    }
    toString(): string {
        return pathToFileURL(this.path).toString();
    }
}

export class Position {
    constructor(
        readonly line: number,
        readonly character: number,
    ) {}
}

export class Range {
    readonly start: Position;
    readonly end: Position;
    constructor(startLine: number, startCharacter: number, endLine: number, endCharacter: number) {
        this.start = new Position(startLine, startCharacter);
        this.end = new Position(endLine, endCharacter);
    }
}

export class Location {
    constructor(
        readonly uri: Uri,
        readonly range: Range,
    ) {}
}

export class TestMessage {
    expectedOutput?: string;
    actualOutput?: string;
    location?: Location;
    constructor(readonly message: string) {}
    static diff(message: string, expected: string, actual: string): TestMessage {
        const m = new TestMessage(message);
        m.expectedOutput = expected;
        m.actualOutput = actual;
        return m;
    }
}

export const TestRunProfileKind = { Run: 1, Debug: 2, Coverage: 3 } as const;

export class TestItemCollection {
    private readonly map = new Map<string, TestItem>();
    constructor(private readonly owner: TestItem | undefined) {}
    get size(): number {
        return this.map.size;
    }
    add(item: TestItem): void {
        item.parent = this.owner;
        this.map.set(item.id, item);
    }
    delete(id: string): void {
        this.map.delete(id);
    }
    get(id: string): TestItem | undefined {
        return this.map.get(id);
    }
    replace(items: readonly TestItem[]): void {
        this.map.clear();
        for (const i of items) this.add(i);
    }
    [Symbol.iterator](): IterableIterator<[string, TestItem]> {
        return this.map.entries();
    }
}

export class TestItem {
    parent: TestItem | undefined;
    range: Range | undefined;
    description: string | undefined;
    readonly children: TestItemCollection = new TestItemCollection(this);
    constructor(
        readonly id: string,
        readonly label: string,
        readonly uri: Uri | undefined,
    ) {}
}

/** What a test run was told, in order. */
export interface RunEvent {
    readonly kind: 'enqueued' | 'started' | 'passed' | 'failed' | 'errored' | 'skipped';
    readonly item: TestItem;
    readonly messages: TestMessage[];
    readonly duration?: number;
}

export class TestRun {
    readonly events: RunEvent[] = [];
    output = '';
    ended = false;
    private add(kind: RunEvent['kind'], item: TestItem, messages: TestMessage | TestMessage[] = [], duration?: number): void {
        this.events.push({
            kind,
            item,
            messages: Array.isArray(messages) ? messages : [messages],
            ...(duration === undefined ? {} : { duration }),
        });
    }
    enqueued(item: TestItem): void {
        this.add('enqueued', item);
    }
    started(item: TestItem): void {
        this.add('started', item);
    }
    skipped(item: TestItem): void {
        this.add('skipped', item);
    }
    passed(item: TestItem, duration?: number): void {
        this.add('passed', item, [], duration);
    }
    failed(item: TestItem, messages: TestMessage | TestMessage[], duration?: number): void {
        this.add('failed', item, messages, duration);
    }
    errored(item: TestItem, messages: TestMessage | TestMessage[], duration?: number): void {
        this.add('errored', item, messages, duration);
    }
    appendOutput(text: string): void {
        this.output += text;
    }
    end(): void {
        this.ended = true;
    }
}

export type RunHandler = (request: { include?: TestItem[]; exclude?: TestItem[] }, token: CancellationToken) => Promise<void>;

export interface CancellationToken {
    isCancellationRequested: boolean;
    onCancellationRequested(listener: () => void): { dispose(): void };
}

export class TestController {
    readonly items = new TestItemCollection(undefined);
    readonly runs: TestRun[] = [];
    readonly profiles: Array<{ label: string; kind: number; handler: RunHandler; isDefault: boolean }> = [];
    refreshHandler: (() => Promise<void>) | undefined;
    resolveHandler: ((item: TestItem | undefined) => Promise<void>) | undefined;
    constructor(
        readonly id: string,
        readonly label: string,
    ) {}
    createTestItem(id: string, label: string, uri?: Uri): TestItem {
        return new TestItem(id, label, uri);
    }
    createRunProfile(label: string, kind: number, handler: RunHandler, isDefault = false): object {
        this.profiles.push({ label, kind, handler, isDefault });
        return {};
    }
    createTestRun(): TestRun {
        const run = new TestRun();
        this.runs.push(run);
        return run;
    }
    dispose(): void {}
}

export const controllers: TestController[] = [];
export const tests = {
    createTestController(id: string, label: string): TestController {
        const c = new TestController(id, label);
        controllers.push(c);
        return c;
    },
};

const disposable = { dispose(): void {} };
const event = (): typeof disposable => disposable;

/** The workspace folder the fake workspace reads (set by the test). */
export const state = { root: '/', trusted: true };

function walk(dir: string, out: string[]): void {
    for (const e of readdirSync(dir, { withFileTypes: true })) {
        const full = path.join(dir, e.name);
        if (e.isDirectory() && e.name !== 'node_modules' && e.name !== '.git') walk(full, out);
        else if (e.isFile()) out.push(full);
    }
}

export const workspace = {
    get isTrusted(): boolean {
        return state.trusted;
    },
    get workspaceFolders(): Array<{ uri: Uri }> {
        return [{ uri: Uri.file(state.root) }];
    },
    textDocuments: [] as Array<{ uri: Uri; getText(): string }>,
    async findFiles(glob: string): Promise<Uri[]> {
        const ext = /\*\.(\w+)$/.exec(glob)?.[1];
        const out: string[] = [];
        walk(state.root, out);
        return out.filter((f) => f.endsWith(`.${ext}`)).map((f) => Uri.file(f));
    },
    fs: {
        async readFile(uri: Uri): Promise<Uint8Array> {
            return readFileSync(uri.fsPath);
        },
        async stat(uri: Uri): Promise<object> {
            return statSync(uri.fsPath);
        },
    },
    asRelativePath(uri: Uri): string {
        return path.relative(state.root, uri.fsPath);
    },
    getWorkspaceFolder(): { uri: Uri } {
        return { uri: Uri.file(state.root) };
    },
    createFileSystemWatcher(): object {
        return { onDidCreate: event, onDidChange: event, onDidDelete: event, dispose(): void {} };
    },
    onDidSaveTextDocument: event,
    getConfiguration(): { get(key: string): unknown } {
        return { get: () => undefined };
    },
};
