// The dashboard's checker thread (docs/lab.md "The instructor's dashboard"): receives one
// workspace's files at a time, checks a temporary copy of them with the language family's checker
// (`maa-gen check`'s checkModelRoots) and answers their diagnostics, so the lab server's event loop
// stays free for the students' requests while the heavy language services work here, at a lower
// CPU priority than the server's main thread (thread-priority.ts).
import { mkdir, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { parentPort } from 'node:worker_threads';
import { lowerThreadPriority } from '../thread-priority.js';
import type { CheckRequest, CheckResponse, FileDiagnostic, WorkspaceFile } from './checker.js';

async function checkFiles(files: readonly WorkspaceFile[]): Promise<FileDiagnostic[]> {
    const root = await mkdtemp(path.join(tmpdir(), 'maa-lab-check-'));
    try {
        for (const f of files) {
            const target = path.join(root, ...f.path.split('/'));
            await mkdir(path.dirname(target), { recursive: true });
            await writeFile(target, f.content);
        }
        const { checkModelRoots } = await import('@maa/language-server');
        const found = await checkModelRoots([{ root }]);
        return found.map((d) => ({
            file: path.relative(root, d.file).split(path.sep).join('/'),
            line: d.line,
            column: d.column,
            severity: d.severity,
            code: d.code,
            message: d.message,
        }));
    } finally {
        await rm(root, { recursive: true, force: true });
    }
}

const port = parentPort;
if (port) {
    lowerThreadPriority();
    port.on('message', (request: CheckRequest) => {
        void checkFiles(request.files).then(
            (diagnostics) => port.postMessage({ id: request.id, diagnostics } satisfies CheckResponse),
            (e: unknown) => port.postMessage({ id: request.id, error: e instanceof Error ? e.message : String(e) } satisfies CheckResponse),
        );
    });
}
