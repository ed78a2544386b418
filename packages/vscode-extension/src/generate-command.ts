/**
 * **MontiArc: Generate** in either host: the platform quick pick from the workspace's `.arcapp`
 * files, the run with a progress notification, the report's diagnostics in a collection and a
 * summary message. What runs the generation is the host's GenerateRunner (generate-runner.ts).
 * Uses only `vscode` (no Node built-ins), so the desktop and the web entry share it.
 */
import * as vscode from 'vscode';
import type { GenerateReport } from './generate-report.js';
import { summaryMessage } from './generate-report.js';
import type { GenerateRunner } from './generate-runner.js';
import { pickPlatform } from './platform-pick.js';
import type { PlatformItem } from './platforms.js';

/** How long the summary of a run stays in the status bar. */
const STATUS_MS = 30_000;

export function toDiagnostics(report: GenerateReport, collection: vscode.DiagnosticCollection): void {
    const severity = {
        error: vscode.DiagnosticSeverity.Error,
        warning: vscode.DiagnosticSeverity.Warning,
        info: vscode.DiagnosticSeverity.Information,
        hint: vscode.DiagnosticSeverity.Hint,
    };
    collection.clear();
    for (const [file, list] of report.byFile) {
        collection.set(
            vscode.Uri.file(file),
            list.map((d) => {
                const range = new vscode.Range(d.line - 1, d.column - 1, d.endLine - 1, d.endColumn - 1);
                const diagnostic = new vscode.Diagnostic(range, d.message, severity[d.severity]);
                diagnostic.code = d.code;
                diagnostic.source = 'maa-gen';
                return diagnostic;
            }),
        );
    }
}

/** The runner under a cancellation token (the progress notification's Cancel aborts it). */
function runCancellable(runner: GenerateRunner, item: PlatformItem, token: vscode.CancellationToken): Promise<GenerateReport> {
    const abort = new AbortController();
    const listener = token.onCancellationRequested(() => abort.abort());
    return runner.run({ appFile: item.appFile, platform: item.platform }, abort.signal).finally(() => listener.dispose());
}

/** **MontiArc: Generate**: platform quick pick, generation with a progress notification, errors as diagnostics. */
export async function generate(runner: GenerateRunner, collection: vscode.DiagnosticCollection): Promise<void> {
    if (!vscode.workspace.isTrusted) {
        void vscode.window.showWarningMessage(
            'MontiArc: Generate runs maa-gen and is available in trusted workspaces only (Workspaces: Manage Workspace Trust).',
        );
        return;
    }
    const item = await pickPlatform('Generate');
    if (!item) return;
    try {
        const report = await vscode.window.withProgress(
            {
                location: vscode.ProgressLocation.Notification,
                title: `MontiArc: generating ${item.application} for ${item.platform}`,
                cancellable: true,
            },
            (_progress, token) => runCancellable(runner, item, token),
        );
        toDiagnostics(report, collection);
        const message = summaryMessage(item.platform, report);
        // Also in the status bar: a host without notifications (the browser IDE's workbench, docs/ide.md) shows it there.
        vscode.window.setStatusBarMessage(`$(${report.ok ? 'check' : 'error'}) ${message}`, STATUS_MS);
        if (report.ok) void vscode.window.showInformationMessage(message);
        else void vscode.window.showErrorMessage(message);
    } catch (e) {
        const message = `MontiArc: ${e instanceof Error ? e.message : String(e)}`;
        vscode.window.setStatusBarMessage(`$(error) ${message}`, STATUS_MS);
        void vscode.window.showErrorMessage(message);
    }
}
