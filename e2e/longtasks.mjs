// Long main-thread tasks in every frame of a page (the IDE benchmark, e2e/bench.mjs): a
// PerformanceObserver for 'longtask' installed in each document before its scripts run
// (context.addInitScript reaches the webviews' iframes too), drained frame by frame into one list
// with wall-clock start times, and attributed to the phases the benchmark names.

/** The goal: no main-thread task longer than this (issue 18). */
export const LONG_TASK_MS = 200;

/** Installs the observer once per document (idempotent: also run at each drain, for frames created before). */
const OBSERVE = `(() => {
    if (window.__maaLongTasks) return;
    const list = (window.__maaLongTasks = []);
    try {
        new PerformanceObserver((entries) => {
            for (const e of entries.getEntries()) list.push({ at: performance.timeOrigin + e.startTime, ms: e.duration, culprit: e.name });
        }).observe({ type: 'longtask', buffered: true });
    } catch {
        /* no long-task timing in this document */
    }
})()`;

/** What a frame shows, for the report (the webviews' documents have no telling URL). */
const DRAIN = `(() => {
    ${OBSERVE};
    const kind = document.querySelector('[data-testid=diagram]')
        ? 'diagram'
        : document.querySelector('[data-testid=simulate-panel]')
          ? 'simulate view'
          : document.querySelector('canvas') && /viser|8080|\\/sim\\//.test(location.href)
            ? 'viser'
            : document.querySelector('[data-testid=workbench]')
              ? 'workbench'
              : 'frame';
    return { kind, tasks: window.__maaLongTasks.splice(0) };
})()`;

export class LongTasks {
    /** Every long task seen: `{ at, ms, frame }` (`at`: epoch milliseconds). */
    tasks = [];
    /** The measured windows: `{ name, start, end }` (epoch milliseconds; a name may recur). */
    windows = [];

    /** Observes every document of `context` from now on. */
    static async attach(context) {
        await context.addInitScript(OBSERVE);
        return new LongTasks();
    }

    /** Collects the tasks of every frame of `page` so far (before a navigation drops its frames). */
    async drain(page) {
        for (const frame of page.frames()) {
            const got = await frame.evaluate(DRAIN).catch(() => undefined);
            if (!got) continue;
            for (const t of got.tasks) this.tasks.push({ ...t, frame: got.kind });
        }
    }

    /** Runs `run` as (a window of) phase `name`; its tasks are those that started inside the window. */
    async phase(name, page, run) {
        const start = Date.now();
        try {
            return await run();
        } finally {
            await this.drain(page);
            this.windows.push({ name, start, end: Date.now() });
        }
    }

    /**
     * The tasks as the main threads ran them: a frame sees the tasks of every frame of its process
     * (the same task, reported to each), so the reports of one task (same start and length) are
     * merged; `frames` are the frames that saw it, `frame` the one that ran it (its entry names
     * itself, 'self'). A task only the viser frame saw ran in a process of its own (viser-view.ts
     * in maa-ide), not on the IDE's main thread.
     */
    merged() {
        const sorted = [...this.tasks].sort((a, b) => a.at - b.at);
        const out = [];
        for (const t of sorted) {
            const same = out.find((m) => Math.abs(m.at - t.at) < 2 && Math.abs(m.ms - t.ms) < 2);
            if (same) {
                same.frames.add(t.frame);
                if (t.culprit === 'self') same.frame = t.frame;
            } else out.push({ at: t.at, ms: t.ms, frames: new Set([t.frame]), frame: t.culprit === 'self' ? t.frame : undefined });
        }
        return out.map((m) => ({ ...m, frame: m.frame ?? 'a frame of another origin', ide: [...m.frames].some((f) => f !== 'viser') }));
    }

    /**
     * Per phase (in the order first seen): measured time, the longest task on the IDE's main thread,
     * the IDE's tasks over the goal by the frame that ran them, and the longest task of a viser
     * frame in a process of its own.
     */
    summary() {
        const names = [...new Set(this.windows.map((w) => w.name))];
        const tasks = this.merged();
        return names.map((name) => {
            const windows = this.windows.filter((w) => w.name === name);
            const inside = tasks.filter((t) => windows.some((w) => t.at >= w.start && t.at <= w.end));
            const ide = inside.filter((t) => t.ide);
            const over = ide.filter((t) => t.ms > LONG_TASK_MS);
            const frames = {};
            for (const t of over) frames[t.frame] = (frames[t.frame] ?? 0) + 1;
            return {
                phase: name,
                measuredMs: windows.reduce((acc, w) => acc + (w.end - w.start), 0),
                longTasks: ide.length,
                longestMs: ide.reduce((acc, t) => Math.max(acc, t.ms), 0),
                over: over.length,
                overByFrame: frames,
                longest: [...ide]
                    .sort((a, b) => b.ms - a.ms)
                    .slice(0, 5)
                    .map((t) => ({ ...t, frames: [...t.frames] })),
                ownProcessViserLongestMs: inside.filter((t) => !t.ide).reduce((acc, t) => Math.max(acc, t.ms), 0),
            };
        });
    }
}
