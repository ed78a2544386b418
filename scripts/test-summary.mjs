// The bookkeeping of `npm test` (scripts/test-all.mjs): one tally of tests and of every kind of
// failure, its closing lines, and the counts read from pytest's JUnit XML. A module of its own
// so that scripts/test/test-summary.test.ts can hold the summary to its exit code.

/** Tests passed and skipped, and every failure by kind, each failure with a name. */
export class Tally {
    passed = 0;
    skipped = 0;
    /** kind → what failed (one entry per failure), in the order they were found. */
    failures = new Map();

    fail(kind, what) {
        if (!this.failures.has(kind)) this.failures.set(kind, []);
        this.failures.get(kind).push(what);
    }

    /** Failures of every kind: the "failed" of the closing line. */
    get failed() {
        let n = 0;
        for (const list of this.failures.values()) n += list.length;
        return n;
    }

    /** 0 exactly when nothing failed and some test passed. */
    get exitCode() {
        return this.failed === 0 && this.passed > 0 ? 0 : 1;
    }

    /**
     * The closing lines: what failed, by kind and by name; a `failures:` line counting each kind;
     * the time; and last `tests: N passed, N failed, N skipped`, where failed counts every kind.
     */
    summary(minutes) {
        const lines = [];
        if (this.failed > 0) {
            lines.push('', 'test-all: what failed:');
            for (const [kind, list] of this.failures) {
                lines.push(`  ${kind} (${list.length}):`);
                for (const what of list) lines.push(`    - ${what}`);
            }
            lines.push('', `failures: ${[...this.failures].map(([kind, list]) => `${list.length} ${kind}`).join(', ')}`);
        } else if (this.passed === 0) {
            lines.push('', 'test-all: no test was run');
        } else {
            lines.push('');
        }
        if (minutes !== undefined) lines.push(`test-all: finished in ${minutes.toFixed(1)} min`);
        lines.push(`tests: ${this.passed} passed, ${this.failed} failed, ${this.skipped} skipped`);
        return lines;
    }
}

const unescapeXml = (text) =>
    text
        .replace(/&#10;/g, '\n')
        .replace(/&quot;/g, '"')
        .replace(/&apos;/g, "'")
        .replace(/&lt;/g, '<')
        .replace(/&gt;/g, '>')
        .replace(/&amp;/g, '&');

/**
 * pytest's JUnit XML (`<testsuite errors= failures= skipped= tests=>` with `<testcase>`s): the
 * counts, and the names of failed tests and of errors (setup/teardown errors, collection errors).
 * undefined when the text holds no test suite.
 */
export function junitCounts(xml) {
    const suite = /<testsuite\b([^>]*)>/.exec(xml);
    if (!suite) return undefined;
    const attribute = (name) => Number((new RegExp(`\\b${name}="(\\d+)"`).exec(suite[1]) ?? [])[1] ?? 0);
    const failed = [];
    const errors = [];
    for (const match of xml.matchAll(/<testcase\b([^>]*?)(?:\/>|>([\s\S]*?)<\/testcase>)/g)) {
        const body = match[2] ?? '';
        const attr = (name) => unescapeXml(new RegExp(`\\b${name}="([^"]*)"`).exec(match[1])?.[1] ?? '');
        const name = [attr('classname'), attr('name')].filter(Boolean).join('::');
        const message = (tag) => unescapeXml(new RegExp(`<${tag}\\b[^>]*\\bmessage="([^"]*)"`).exec(body)?.[1] ?? tag).split('\n')[0];
        if (/<failure\b/.test(body)) failed.push(`${name}: ${message('failure')}`);
        else if (/<error\b/.test(body)) errors.push(`${name}: ${message('error')}`);
    }
    // The attributes count; the cases name what they can (for pytest the two agree).
    while (failed.length < attribute('failures')) failed.push('a failed test (not named in the report)');
    while (errors.length < attribute('errors')) errors.push('an error (not named in the report)');
    const skipped = attribute('skipped');
    return { passed: attribute('tests') - failed.length - errors.length - skipped, failed, errors, skipped };
}

/**
 * The children's CPU time (user + sys, in ms) from the output of bash's `times`: two lines of
 * `<user> <sys>` (e.g. `1m2.345s 0m0.120s`), the shell's own and then its children's.
 * undefined when the text does not hold them.
 */
export function parseTimes(text) {
    const lines = text
        .trim()
        .split('\n')
        .map((line) => [...line.matchAll(/(\d+)m([\d.]+)s/g)].map((m) => (Number(m[1]) * 60 + Number(m[2])) * 1000));
    if (lines.length !== 2 || lines.some((times) => times.length !== 2)) return undefined;
    return lines[1][0] + lines[1][1];
}

/**
 * The table of stages: when each stage started (from the start of the run), its wall time and its
 * CPU time (user + sys of the processes it ran), the sum of the CPU times, and the whole run's wall
 * time; stages that ran side by side overlap, so their wall times add up to more than the total.
 */
export function stageTable(stages, totalMs) {
    const seconds = (ms) => (ms === undefined ? '?'.padStart(8) : `${(ms / 1000).toFixed(1).padStart(6)} s`);
    const width = Math.max(5, ...stages.map((s) => s.title.length));
    const lines = ['', 'test-all: time per stage (wall, CPU = user + sys of its processes):'];
    lines.push(`  ${'stage'.padEnd(width)}  ${'start'.padStart(8)}  ${'wall'.padStart(8)}  ${'CPU'.padStart(8)}`);
    for (const s of stages) lines.push(`  ${s.title.padEnd(width)}  ${seconds(s.startMs)}  ${seconds(s.wallMs)}  ${seconds(s.cpuMs)}`);
    const cpu = stages.reduce((sum, s) => sum + (s.cpuMs ?? 0), 0);
    lines.push(`  ${'total'.padEnd(width)}  ${seconds(0)}  ${seconds(totalMs)}  ${seconds(cpu)}`);
    return lines;
}
