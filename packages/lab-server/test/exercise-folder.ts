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

/** An exercise folder `dir/name` with exercise.json, description.md, starter/ and solution/. */
export function writeExercise(
    dir: string,
    name: string,
    files: Record<string, string>,
    manifest: Record<string, unknown> = MANIFEST,
): string {
    const folder = path.join(dir, name);
    const write = (rel: string, content: string) => {
        const file = path.join(folder, ...rel.split('/'));
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, content);
    };
    write('exercise.json', JSON.stringify(manifest, null, 2));
    write('description.md', `# ${name}\n`);
    write('solution/hello/Lamp.arc', 'the solution, never released\n');
    for (const [rel, content] of Object.entries(files)) write(`starter/${rel}`, content);
    return folder;
}

export const STARTER: Record<string, string> = {
    'App.arcapp': 'application App for hello.Lamp { platform timesync { timesync.Components; } }\n',
    'hello/Lamp.arc': 'package hello;\ncomponent Lamp {\n  port in boolean button;\n\n  // TODO\n}\n',
    'hello/Lamp.stream': 'component hello.Lamp;\n',
    'lib/Toggle.arc': 'package lib;\ncomponent Toggle {\n}\n',
};
