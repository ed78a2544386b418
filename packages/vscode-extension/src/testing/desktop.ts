/**
 * The stream tests in VS Code desktop: the test controller with the CLI runner, which resolves
 * `maa-gen` as **MontiArc: Generate** does (`maa.generate.command`, else the workspace's
 * `node_modules/.bin/maa-gen`, else the PATH's) and passes `maa.test.python` as `--python`.
 */
import { existsSync } from 'node:fs';
import * as vscode from 'vscode';
import { generateCommand, readSettings } from '../settings.js';
import { CliStreamTestRunner } from './cli-runner.js';
import { registerStreamTests } from './controller.js';
import { testPython } from './test-settings.js';

export function registerDesktopStreamTests(): vscode.Disposable[] {
    const get = (key: string): unknown => vscode.workspace.getConfiguration().get(key);
    const runner = new CliStreamTestRunner(
        () =>
            generateCommand(
                readSettings(get),
                (vscode.workspace.workspaceFolders ?? []).map((f) => f.uri.fsPath),
                existsSync,
            ),
        () => testPython(get),
    );
    return registerStreamTests(runner);
}
