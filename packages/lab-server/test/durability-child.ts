// The process durability.test.ts kills with SIGKILL: opens the store given as JSON StorageOptions
// in argv[2], makes a student's workspace, prints `ready`, then saves DurableFile.arc again and
// again and prints `ack N` after each save has returned (the acknowledgement a client would get).
// It keeps saving after the 100th, so the kill lands in the middle of a save. It stops by itself
// when its parent closes stdin or after MAX_SAVES, so it never outlives a failed test.
import { openLabStore, type StorageOptions } from '../src/storage/index.js';
import { DURABLE_LOGIN, DURABLE_PATH, durableContent } from './durability-shared.js';
import './liftoff.js';

const MAX_SAVES = 5000;

async function main(): Promise<void> {
    process.stdin.on('end', () => process.exit(2));
    process.stdin.resume();
    const store = await openLabStore(JSON.parse(process.argv[2]!) as StorageOptions);
    const student = await store.createUser({ login: DURABLE_LOGIN, name: 'Durable', role: 'student' });
    const course = await store.createCourse({ name: 'durability', title: 'Durability' });
    const exercise = await store.createExercise({ courseId: course.id, name: 'saves', spec: {} });
    const workspace = await store.workspace(student.id, exercise.id);
    process.stdout.write('ready\n');
    for (let i = 1; i <= MAX_SAVES; i++) {
        const saved = await store.saveFile({
            workspaceId: workspace.id,
            path: DURABLE_PATH,
            content: durableContent(i),
            authorId: student.id,
        });
        // stdout to a pipe is written synchronously on Linux: the line is out before the next save starts.
        process.stdout.write(`ack ${saved.revision}\n`);
    }
    await store.close();
}

main().catch((error: unknown) => {
    process.stderr.write(`durability-child: ${error instanceof Error ? error.stack : String(error)}\n`);
    process.exit(1);
});
