import {
    existsSync,
    lstatSync,
    mkdirSync,
    mkdtempSync,
    readdirSync,
    readFileSync,
    readlinkSync,
    rmSync,
    symlinkSync,
    writeFileSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { OutputWriteError, STATE_DIR } from '../src/output/layout.js';
import { killWhenPaused, type WritePhase } from '../src/output/pause.js';
import { OutputTransaction } from '../src/output/transaction.js';
import { planOutput, type OutputFile } from '../src/output/writer.js';
import { snapshot } from './test-generators.js';

// Generation killed with SIGKILL at every phase of writing, over an existing output of two
// platforms with user edits: each platform folder must be wholly the old or wholly the new tree,
// and the next run must clean up and succeed. A child process runs the built writer
// (fixtures/write-trees.mjs) and stops at a checkpoint (MAA_GEN_PAUSE_AT=<phase>:<n>); the test
// waits for its "paused" line, then kills it. Consecutive trials stop at different checkpoints.

const CHILD = fileURLToPath(new URL('./fixtures/write-trees.mjs', import.meta.url));
const BUILT = fileURLToPath(new URL('../dist/output/writer.js', import.meta.url));
const TRIALS = 20;

type Trees = Record<string, OutputFile[]>;
const file = (p: string, content: string, userFile = false): OutputFile => ({ path: p, content, userFile });
const region = (body: string): string => `# PROTECTED REGION BEGIN body\n${body}\n# PROTECTED REGION END body\n`;

const OLD: Trees = {
    alpha: [
        file('pkg/a.py', `A1\n${region('# your code here')}`),
        file('pkg/b.py', 'B1\n'),
        file('pkg/old/stale.py', 'stale\n'),
        file('user/impl.py', '# implement\n', true),
        file('deployment.json', '{"version": 1}\n'),
    ],
    beta: [file('types.py', 'T1\n'), file('lockstep.json', '{"version": 1}\n')],
};
const NEW: Trees = {
    alpha: [
        file('pkg/a.py', `A2\n${region('# your code here')}`),
        file('pkg/b.py', 'B1\n'),
        ...Array.from({ length: 15 }, (_, i) => file(`pkg/gen/f${String(i).padStart(2, '0')}.py`, `F${i}\n`)),
        file('user/impl.py', '# implement\n', true),
        file('deployment.json', '{"version": 2}\n'),
    ],
    beta: [file('types.py', 'T2\n'), file('lockstep.json', '{"version": 2}\n'), file('extra.py', 'E2\n')],
};

/** What a user does between the generations: protected region, user file, notes, a build folder with a link. */
function editOutput(out: string): void {
    const a = path.join(out, 'alpha/pkg/a.py');
    writeFileSync(a, readFileSync(a, 'utf8').replace('# your code here', 'USER = 1'));
    writeFileSync(path.join(out, 'alpha/user/impl.py'), '# mine\n');
    writeFileSync(path.join(out, 'alpha/NOTES.md'), 'notes\n');
    mkdirSync(path.join(out, 'alpha/build/obj'), { recursive: true });
    writeFileSync(path.join(out, 'alpha/build/obj/x.o'), 'binary\n');
    symlinkSync('obj', path.join(out, 'alpha/build/latest'));
    writeFileSync(path.join(out, 'beta/user-notes.txt'), 'mine\n');
}

function traceOf(files: OutputFile[]): string {
    return `${JSON.stringify({ files: files.map((f) => ({ path: f.path, userFile: f.userFile })) })}\n`;
}

/** In this process, what the child does. */
function writeTrees(out: string, trees: Trees): void {
    const tx = OutputTransaction.open(out);
    try {
        const plans = Object.entries(trees).map(([p, files]) => planOutput(path.join(out, p), files, traceOf(files)));
        for (const plan of plans) tx.stage(plan);
        tx.commit();
    } finally {
        tx.close();
    }
}

const temps: string[] = [];
function temp(): string {
    const d = mkdtempSync(path.join(tmpdir(), 'maa-atomic-'));
    temps.push(d);
    return d;
}
afterAll(() => {
    for (const d of temps) rmSync(d, { recursive: true, force: true });
});

/** An output root after the old generation and the user's edits. */
function existingOutput(): string {
    const out = path.join(temp(), 'out');
    writeTrees(out, OLD);
    editOutput(out);
    return out;
}

let expectedOld: Record<string, Record<string, string>>;
let expectedNew: Record<string, Record<string, string>>;
beforeAll(() => {
    if (!existsSync(BUILT)) throw new Error(`${BUILT} is missing: build generator-core first (npx tsc -b packages/generator-core)`);
    const out = existingOutput();
    expectedOld = { alpha: snapshot(path.join(out, 'alpha')), beta: snapshot(path.join(out, 'beta')) };
    writeTrees(out, NEW);
    expectedNew = { alpha: snapshot(path.join(out, 'alpha')), beta: snapshot(path.join(out, 'beta')) };
    // The new trees are what the rules say, not just what the writer happens to do.
    expect(expectedNew.alpha).toMatchObject({
        'pkg/a.py': `A2\n${region('USER = 1')}`,
        'user/impl.py': '# mine\n',
        'NOTES.md': 'notes\n',
        'build/latest/x.o': 'binary\n',
        'deployment.json': '{"version": 2}\n',
        'pkg/gen/f14.py': 'F14\n',
    });
    expect(Object.keys(expectedNew.alpha).filter((k) => k.startsWith('pkg/old'))).toEqual([]);
    expect(expectedNew.beta).toMatchObject({ 'types.py': 'T2\n', 'user-notes.txt': 'mine\n', 'extra.py': 'E2\n' });
    expect(expectedOld.alpha).toMatchObject({ 'pkg/a.py': `A1\n${region('USER = 1')}`, 'pkg/old/stale.py': 'stale\n' });
});

/** Runs the child until it pauses at the checkpoint, then kills it with SIGKILL. Returns the checkpoint it reached. */
function killAt(out: string, phase: WritePhase, n: number): Promise<string> {
    const spec = path.join(path.dirname(out), `spec-${phase}-${n}.json`);
    writeFileSync(spec, JSON.stringify({ outRoot: out, platforms: NEW }));
    return killWhenPaused(process.execPath, [CHILD, spec], `${phase}:${n}`);
}

function platformState(out: string, platform: 'alpha' | 'beta'): 'old' | 'new' | 'mixed' {
    const now = snapshot(path.join(out, platform));
    if (JSON.stringify(now) === JSON.stringify(expectedOld[platform])) return 'old';
    if (JSON.stringify(now) === JSON.stringify(expectedNew[platform])) return 'new';
    return 'mixed';
}

/** After a successful run: the new trees, and nothing of ours but the two current versions. */
function expectCleanNew(out: string): void {
    expect(platformState(out, 'alpha')).toBe('new');
    expect(platformState(out, 'beta')).toBe('new');
    expect(readdirSync(out).sort()).toEqual([STATE_DIR, 'alpha', 'beta']);
    const versions = ['alpha', 'beta'].map((p) => path.basename(readlinkSync(path.join(out, p))));
    expect(readdirSync(path.join(out, STATE_DIR)).sort()).toEqual(versions.sort());
}

describe('writing is atomic per platform folder under SIGKILL', () => {
    test.each(['staging', 'commit', 'cleanup'] as const)(
        'killed %s phase 20 times: each platform wholly old or wholly new, the next run cleans up',
        async (phase) => {
            const seen: Record<string, number> = {};
            for (let trial = 1; trial <= TRIALS; trial++) {
                const out = existingOutput();
                const where = await killAt(out, phase, trial);
                const states = `${platformState(out, 'alpha')}/${platformState(out, 'beta')}`;
                expect(states, `killed at ${where}`).toMatch(/^(old|new)\/(old|new)$/);
                seen[states] = (seen[states] ?? 0) + 1;
                writeTrees(out, NEW);
                expectCleanNew(out);
            }
            // The kills landed where the phase says: nothing visible changed while staging, everything after the commit.
            if (phase === 'staging') expect(seen).toEqual({ 'old/old': TRIALS });
            if (phase === 'cleanup') expect(seen).toEqual({ 'new/new': TRIALS });
            if (phase === 'commit') expect(Object.keys(seen).sort()).toEqual(['new/new', 'new/old']);
        },
        300_000,
    );

    test('a kill while recovering from a killed run is recovered by the run after it', async () => {
        for (let trial = 1; trial <= 5; trial++) {
            const out = existingOutput();
            await killAt(out, 'staging', 5 + trial);
            await killAt(out, 'recover', trial);
            expect(`${platformState(out, 'alpha')}/${platformState(out, 'beta')}`).toBe('old/old');
            writeTrees(out, NEW);
            expectCleanNew(out);
        }
    }, 120_000);
});

describe('the output layout', () => {
    test('each platform folder is a relative link to its version; an unchanged run makes no new version', () => {
        const out = existingOutput();
        const target = readlinkSync(path.join(out, 'alpha'));
        expect(target).toMatch(new RegExp(`^${STATE_DIR}/alpha\\.v[0-9a-f]{12}$`));
        writeTrees(out, NEW);
        const next = readlinkSync(path.join(out, 'alpha'));
        expect(next).not.toBe(target);
        writeTrees(out, NEW);
        expect(readlinkSync(path.join(out, 'alpha'))).toBe(next);
        expectCleanNew(out);
    });

    test('a plain folder from before (user files included) is converted without losing anything', () => {
        const out = path.join(temp(), 'out');
        // The old writer's layout: plain folders, plus a staging folder of a killed run.
        for (const [p, files] of Object.entries(OLD)) {
            for (const f of files) {
                mkdirSync(path.dirname(path.join(out, p, f.path)), { recursive: true });
                writeFileSync(path.join(out, p, f.path), f.content);
            }
            writeFileSync(path.join(out, p, '.maa-trace.json'), traceOf(files));
        }
        mkdirSync(path.join(out, '.maa-staging-alpha.123.abcdef01/pkg'), { recursive: true });
        mkdirSync(path.join(out, '.maa-backup-alpha.123.abcdef01'), { recursive: true });
        editOutput(out);
        const before = { alpha: snapshot(path.join(out, 'alpha')), beta: snapshot(path.join(out, 'beta')) };
        expect(before).toEqual(expectedOld);
        writeTrees(out, NEW);
        expect(lstatSync(path.join(out, 'alpha')).isSymbolicLink()).toBe(true);
        expect(platformState(out, 'alpha')).toBe('new');
        expect(platformState(out, 'beta')).toBe('new');
        // Ours is deleted, the old writer's backups (possibly the only copy of a file) are not.
        expect(readdirSync(out).sort()).toEqual(['.maa-backup-alpha.123.abcdef01', STATE_DIR, 'alpha', 'beta']);
    });

    test('a conversion killed between its two renames is rolled back by the next run', async () => {
        const out = existingOutput();
        // Turn alpha back into a plain folder (as an older writer left it).
        const real = path.join(out, readlinkSync(path.join(out, 'alpha')));
        rmSync(path.join(out, 'alpha'));
        const plain = path.join(out, 'alpha');
        mkdirSync(plain);
        for (const e of readdirSync(real)) {
            const { cpSync } = await import('node:fs');
            cpSync(path.join(real, e), path.join(plain, e), { recursive: true, verbatimSymlinks: true });
        }
        rmSync(real, { recursive: true });
        expect(platformState(out, 'alpha')).toBe('old');
        await killAt(out, 'commit', 1); // alpha: moved aside, link not yet in place
        expect(existsSync(path.join(out, 'alpha'))).toBe(false);
        const aside = readdirSync(path.join(out, STATE_DIR)).filter((n) => n.startsWith('old.alpha.'));
        expect(aside).toHaveLength(1);
        writeTrees(out, NEW);
        expectCleanNew(out);
        expect(readFileSync(path.join(out, 'alpha/user/impl.py'), 'utf8')).toBe('# mine\n');
    });

    test('names that are not ours are never deleted', () => {
        const out = existingOutput();
        const foreign = ['mine.v123', 'alpha.vXYZ', 'notes.txt', 'link.zz'];
        for (const n of foreign) writeFileSync(path.join(out, STATE_DIR, n), 'x');
        writeFileSync(path.join(out, '.maa-staging-by-hand'), 'x');
        writeTrees(out, NEW);
        for (const n of foreign) expect(existsSync(path.join(out, STATE_DIR, n)), n).toBe(true);
        expect(existsSync(path.join(out, '.maa-staging-by-hand'))).toBe(true);
        expect(platformState(out, 'alpha')).toBe('new');
    });
});

describe('write failures name the path and change nothing', () => {
    function failure(run: () => void): { path: string; reason: string } {
        try {
            run();
        } catch (e) {
            expect(e).toBeInstanceOf(OutputWriteError);
            return { path: (e as OutputWriteError).path, reason: (e as OutputWriteError).reason };
        }
        throw new Error('no error');
    }
    function expectUnchanged(out: string): void {
        expect(platformState(out, 'alpha')).toBe('old');
        expect(platformState(out, 'beta')).toBe('old');
        // Nothing of the failed run is left, and the lock is released.
        const versions = ['alpha', 'beta'].map((p) => path.basename(readlinkSync(path.join(out, p))));
        expect(readdirSync(path.join(out, STATE_DIR)).sort()).toEqual(versions.sort());
    }

    test('a file where generated files need a folder', () => {
        const out = existingOutput();
        writeFileSync(path.join(out, 'alpha/pkg/gen'), 'a file of the user\n');
        const before = snapshot(path.join(out, 'alpha'));
        expect(failure(() => writeTrees(out, NEW))).toEqual({
            path: path.join(out, 'alpha/pkg/gen'),
            reason: 'is a file where generated files need a folder',
        });
        expect(snapshot(path.join(out, 'alpha'))).toEqual(before);
        expect(platformState(out, 'beta')).toBe('old');
    });

    test('a file where the platform folder or the output folder is needed', () => {
        const root = temp();
        const out = path.join(root, 'out');
        mkdirSync(out);
        writeFileSync(path.join(out, 'alpha'), 'mine\n');
        expect(failure(() => writeTrees(out, NEW))).toEqual({
            path: path.join(out, 'alpha'),
            reason: 'is a file where the platform folder is needed',
        });
        expect(readFileSync(path.join(out, 'alpha'), 'utf8')).toBe('mine\n');
        expect(readdirSync(out)).toEqual(['alpha']);
        const asFile = path.join(root, 'file');
        writeFileSync(asFile, 'x');
        expect(failure(() => writeTrees(asFile, NEW))).toEqual({ path: asFile, reason: 'is a file where the output folder is needed' });
    });

    test('a platform folder that is a link maa-gen did not make is left alone', () => {
        const out = existingOutput();
        const elsewhere = path.join(temp(), 'ws');
        mkdirSync(elsewhere);
        rmSync(path.join(out, 'beta'));
        symlinkSync(elsewhere, path.join(out, 'beta'));
        const e = failure(() => writeTrees(out, NEW));
        expect(e.path).toBe(path.join(out, 'beta'));
        expect(e.reason).toContain('is a symbolic link maa-gen did not create');
        expect(readlinkSync(path.join(out, 'beta'))).toBe(elsewhere);
        expect(platformState(out, 'alpha')).toBe('old');
    });

    test("a second generation into the same output while one runs is refused; a dead one's lock is taken over", () => {
        const out = existingOutput();
        const lock = path.join(out, STATE_DIR, 'lock');
        writeFileSync(lock, `${process.pid}\n`); // this process is alive
        expect(failure(() => writeTrees(out, NEW))).toEqual({
            path: lock,
            reason: `another generation (process ${process.pid}) is writing this output; run again when it has finished`,
        });
        rmSync(lock);
        expectUnchanged(out);
        writeFileSync(lock, '2147483646\n'); // no such process
        writeTrees(out, NEW);
        expectCleanNew(out);
        expect(existsSync(lock)).toBe(false);
    });
});
