// Writes small exercise folders for the exercise tests.
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';

export const MANIFEST = {
    format: 'maa-exercise/1',
    title: 'Lamp',
    description: 'description.md',
    app: 'App.arcapp',
    readOnly: ['lib/'],
    tests: ['hello/Lamp.stream'],
    platforms: ['timesync'],
};

/** Writes `files` (relative path → content) below `root`: e.g. the base folder of an exercise. */
export function writeFiles(root: string, files: Record<string, string>): void {
    for (const [rel, content] of Object.entries(files)) {
        const file = path.join(root, ...rel.split('/'));
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, content);
    }
}

/** An exercise folder `dir/name` with exercise.json, description.md, starter/ and solution/. */
export function writeExercise(
    dir: string,
    name: string,
    files: Record<string, string>,
    manifest: Record<string, unknown> = MANIFEST,
): string {
    const folder = path.join(dir, name);
    writeFiles(folder, {
        'exercise.json': JSON.stringify(manifest, null, 2),
        'description.md': `# ${name}\n`,
        'solution/hello/Lamp.arc': 'the solution, never released\n',
    });
    writeFiles(path.join(folder, 'starter'), files);
    return folder;
}

export const STARTER: Record<string, string> = {
    'App.arcapp': 'application App for hello.Lamp { platform timesync { timesync.Components; } }\n',
    'hello/Lamp.arc': 'package hello;\ncomponent Lamp {\n  port in boolean button;\n\n  // TODO\n}\n',
    'hello/Lamp.stream': 'component hello.Lamp;\n',
    'lib/Toggle.arc': 'package lib;\ncomponent Toggle {\n}\n',
};
