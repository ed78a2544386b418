// A generator thread of the lab server (generate-pool.ts): receives one GenerateJob at a time,
// runs it with the IDE backend's runGenerateJob (the files go to the workspace's output folder on
// disk) and answers the result, so the server's event loop stays free for the students' requests.
// It runs at a lower CPU priority than the server's main thread (thread-priority.ts).
import { parentPort } from 'node:worker_threads';
import { type GenerateJob, runGenerateJob } from '@maa/ide-server';
import { lowerThreadPriority } from '../thread-priority.js';
import type { GenerateThreadAnswer } from './generate-pool.js';

const port = parentPort;
if (port) {
    lowerThreadPriority();
    port.on('message', (job: GenerateJob) => {
        void runGenerateJob(job).then(
            (result) => port.postMessage({ result } satisfies GenerateThreadAnswer),
            (e: unknown) => port.postMessage({ error: e instanceof Error ? e.message : String(e) } satisfies GenerateThreadAnswer),
        );
    });
}
