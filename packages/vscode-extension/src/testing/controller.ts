/**
 * The `maa.streamTests` test controller (VS Code's Testing API): one item per `.stream` file of the
 * workspace (watched), one child per case at its range; a run profile that runs what is selected
 * (a case, a file, everything) through a StreamTestRunner, grouped by the application each file
 * belongs to (association.ts), and reports passed / failed (with a diff per failing port at its
 * statement) / errored. Uses only workspace APIs that also exist in the browser (no Node).
 */
import * as vscode from 'vscode';
import { type AppCandidate, appOfStreamFile } from './association.js';
import { caseOutcome, fileOutcome, type Outcome, resultOfCase, type StreamTestResult } from './report.js';
import type { FileRef, StreamTestRunner } from './runner.js';
import { outlineStreamFile, type Span, type StreamCase } from './stream-file.js';

const EXCLUDE = '**/{node_modules,.git}/**';

function toRange(s: Span): vscode.Range {
    return new vscode.Range(s.line, s.character, s.endLine, s.endCharacter);
}

function ref(uri: vscode.Uri): FileRef {
    return { uri: uri.toString(), path: uri.path, fsPath: uri.fsPath };
}

async function readText(uri: vscode.Uri): Promise<string> {
    const open = vscode.workspace.textDocuments.find((d) => d.uri.toString() === uri.toString());
    return open ? open.getText() : new TextDecoder().decode(await vscode.workspace.fs.readFile(uri));
}

async function exists(uri: vscode.Uri): Promise<boolean> {
    try {
        await vscode.workspace.fs.stat(uri);
        return true;
    } catch {
        return false;
    }
}

/** The cases of each file item (what the tree shows), by the item's id. */
type CaseIndex = Map<string, Map<string, StreamCase>>;

/** Creates the controller and its run profile; everything returned is to be disposed with the extension. */
export function registerStreamTests(runner: StreamTestRunner): vscode.Disposable[] {
    const controller = vscode.tests.createTestController('maa.streamTests', 'MontiArc stream tests');
    const cases: CaseIndex = new Map();

    const update = async (uri: vscode.Uri): Promise<void> => {
        let outline: ReturnType<typeof outlineStreamFile>;
        try {
            outline = outlineStreamFile(await readText(uri));
        } catch {
            controller.items.delete(uri.toString());
            return;
        }
        const file =
            controller.items.get(uri.toString()) ?? controller.createTestItem(uri.toString(), vscode.workspace.asRelativePath(uri), uri);
        file.description = outline.component;
        const byId = new Map<string, StreamCase>();
        file.children.replace(
            outline.cases.map((c) => {
                const id = `${uri.toString()}#${c.name}@${c.range.line}`;
                byId.set(id, c);
                const item = controller.createTestItem(id, c.name, uri);
                item.range = toRange(c.range);
                return item;
            }),
        );
        cases.set(file.id, byId);
        controller.items.add(file);
    };
    const remove = (uri: vscode.Uri): void => {
        controller.items.delete(uri.toString());
        cases.delete(uri.toString());
    };
    const discover = async (): Promise<void> => {
        for (const uri of await vscode.workspace.findFiles('**/*.stream', EXCLUDE)) await update(uri);
    };

    const watcher = vscode.workspace.createFileSystemWatcher('**/*.stream');
    controller.refreshHandler = async () => {
        for (const [, item] of controller.items) remove(item.uri!);
        await discover();
    };
    controller.resolveHandler = async (item) => {
        if (!item) await discover();
    };
    // The gutter's run buttons need the cases of open files before the Testing view is opened.
    void discover();
    controller.createRunProfile(
        'Run',
        vscode.TestRunProfileKind.Run,
        (request, token) => runTests(controller, cases, runner, request, token),
        true,
    );
    return [
        controller,
        watcher,
        watcher.onDidCreate(update),
        watcher.onDidChange(update),
        watcher.onDidDelete(remove),
        vscode.workspace.onDidSaveTextDocument((d) => (d.uri.path.endsWith('.stream') ? update(d.uri) : undefined)),
    ];
}

/** What a run covers: per file item, every case or only some. */
function selection(controller: vscode.TestController, request: vscode.TestRunRequest): Map<vscode.TestItem, vscode.TestItem[]> {
    const excluded = new Set((request.exclude ?? []).map((i) => i.id));
    const roots = request.include ?? [...controller.items].map(([, item]) => item);
    const byFile = new Map<vscode.TestItem, vscode.TestItem[]>();
    for (const item of roots) {
        if (excluded.has(item.id)) continue;
        const file = item.parent ?? item;
        const chosen = item.parent ? [item] : [...item.children].map(([, c]) => c).filter((c) => !excluded.has(c.id));
        byFile.set(file, [...new Set([...(byFile.get(file) ?? []), ...chosen])]);
    }
    return byFile;
}

/** The application of each file of the selection (found afresh per run: the .arcapp files may have changed). */
async function appsOf(files: readonly vscode.TestItem[]): Promise<Map<vscode.TestItem, vscode.Uri | undefined>> {
    const appUris = await vscode.workspace.findFiles('**/*.arcapp', EXCLUDE);
    const candidates: AppCandidate[] = await Promise.all(appUris.map(async (u) => ({ path: u.path, text: await readText(u) })));
    const markers = new Map<string, boolean>();
    const answer = new Map<vscode.TestItem, vscode.Uri | undefined>();
    for (const file of files) {
        const uri = file.uri!;
        const folder = vscode.workspace.getWorkspaceFolder(uri)?.uri;
        for (const c of candidates) {
            // resolveModelRoot asks synchronously: look the markers up first.
            for (let dir = c.path.slice(0, c.path.lastIndexOf('/')); dir.length > 0; dir = dir.slice(0, dir.lastIndexOf('/'))) {
                if (!markers.has(dir)) markers.set(dir, await exists(uri.with({ path: `${dir}/maa.json` })));
                if (folder && dir === folder.path) break;
            }
        }
        const app = appOfStreamFile(uri.path, candidates, (dir) => markers.get(dir) ?? false, folder?.path);
        answer.set(file, app === undefined ? undefined : uri.with({ path: app }));
    }
    return answer;
}

function report(run: vscode.TestRun, item: vscode.TestItem, outcome: Outcome, duration?: number): void {
    if (outcome.state === 'passed') {
        run.passed(item, duration);
        return;
    }
    const messages = outcome.messages.map((m) => {
        const message =
            m.expected !== undefined && m.actual !== undefined
                ? vscode.TestMessage.diff(m.text, m.expected, m.actual)
                : new vscode.TestMessage(m.text);
        if (item.uri)
            message.location = new vscode.Location(item.uri, m.span ? toRange(m.span) : (item.range ?? new vscode.Range(0, 0, 0, 0)));
        return message;
    });
    if (outcome.state === 'failed') run.failed(item, messages, duration);
    else run.errored(item, messages, duration);
}

async function runTests(
    controller: vscode.TestController,
    cases: CaseIndex,
    runner: StreamTestRunner,
    request: vscode.TestRunRequest,
    token: vscode.CancellationToken,
): Promise<void> {
    const run = controller.createTestRun(request);
    const abort = new AbortController();
    const cancel = token.onCancellationRequested(() => abort.abort());
    try {
        const chosen = selection(controller, request);
        for (const items of chosen.values()) for (const item of items) run.enqueued(item);
        if (!vscode.workspace.isTrusted) {
            const why = new vscode.TestMessage('Stream tests run maa-gen and are available in trusted workspaces only.');
            for (const items of chosen.values()) for (const item of items) run.errored(item, why);
            return;
        }
        const apps = await appsOf([...chosen.keys()]);
        const groups = new Map<string, { app: vscode.Uri; files: Array<[vscode.TestItem, vscode.TestItem[]]> }>();
        for (const [file, items] of chosen) {
            const app = apps.get(file);
            if (!app) {
                const why = new vscode.TestMessage(
                    'No application configuration (.arcapp) with a timesync platform has this file below its model root (the files maa-gen test runs).',
                );
                for (const item of items) run.errored(item, why);
                continue;
            }
            const group = groups.get(app.toString()) ?? { app, files: [] };
            group.files.push([file, items]);
            groups.set(app.toString(), group);
        }
        for (const group of groups.values()) {
            if (token.isCancellationRequested) break;
            await runGroup(run, cases, runner, group, abort.signal);
        }
    } finally {
        cancel.dispose();
        run.end();
    }
}

/** One runner call for the files of one application. */
async function runGroup(
    run: vscode.TestRun,
    cases: CaseIndex,
    runner: StreamTestRunner,
    group: { app: vscode.Uri; files: Array<[vscode.TestItem, vscode.TestItem[]]> },
    signal: AbortSignal,
): Promise<void> {
    const items = group.files.flatMap(([, list]) => list);
    const whole = group.files.every(([file, list]) => list.length === file.children.size);
    const caseOf = (item: vscode.TestItem): StreamCase | undefined => cases.get(item.parent?.id ?? '')?.get(item.id);
    const names = whole ? [] : [...new Set(items.map((i) => caseOf(i)?.name ?? i.label))];
    for (const item of items) run.started(item);
    const started = Date.now();
    let results: readonly StreamTestResult[];
    try {
        const answer = await runner.run({ app: ref(group.app), files: group.files.map(([f]) => ref(f.uri!)), cases: names }, signal);
        results = answer.results;
    } catch (e) {
        const text = signal.aborted ? 'cancelled' : e instanceof Error ? e.message : String(e);
        for (const item of items) signal.aborted ? run.skipped(item) : run.errored(item, new vscode.TestMessage(text));
        if (!signal.aborted) run.appendOutput(`${text.replace(/\r?\n/g, '\r\n')}\r\n`);
        return;
    }
    // The runner times the whole run (generation included), not each case: a lone case gets that time.
    const duration = items.length === 1 ? Date.now() - started : undefined;
    for (const [file, list] of group.files) {
        const mine = results.filter((r) => r.file === file.uri!.toString());
        const broken = mine.find((r) => r.test === null);
        for (const item of list) {
            const kase = caseOf(item);
            const result = kase ? resultOfCase(mine, kase) : undefined;
            if (result) report(run, item, caseOutcome(result, kase), duration);
            else if (broken) report(run, item, fileOutcome(broken));
            else run.errored(item, new vscode.TestMessage('maa-gen test reported no result for this case (is the file saved?)'));
        }
    }
}
