import path from 'node:path';
import type { SimulatorFinished, SimulatorProgress } from '@maa/protocol';
import type { CliIo } from '../io.js';
import { createProgress } from '../progress.js';
import type { MaaSimListener } from './run.js';
import type { SimTarget } from './prepare.js';

function seconds(value: number): string {
    return `${value.toFixed(2)} s`;
}

function factor(value: number): string {
    return `${value >= 10 ? value.toFixed(0) : value.toFixed(1)}x`;
}

/** `12.34 s simulated, 24x real time, goal not reached, 4078 messages recorded` */
export function progressText(p: SimulatorProgress): string {
    const parts = [
        `${seconds(p.time)} simulated`,
        `${factor(p.real_time_factor)} real time`,
        p.goal_reached ? 'goal reached' : 'goal not reached',
    ];
    if (p.paused) parts.push('paused');
    if (p.recorded_messages !== null) parts.push(`${p.recorded_messages} messages recorded`);
    return parts.join(', ');
}

/**
 * Progress on stderr: one line redrawn in place on a terminal, a plain line per progress event
 * otherwise (pipes, CI logs); maa-sim's own stderr lines pass through.
 */
export function progressListener(io: CliIo): MaaSimListener & { done(): void } {
    const progress = createProgress(io);
    return {
        viewer(url) {
            progress?.done();
            io.err(`maa-gen: the simulation's 3D view: ${url}\n`);
        },
        progress(line) {
            const text = `sim: ${progressText(line)}`;
            if (progress) progress.update(text);
            else io.err(`${text}\n`);
        },
        log(line) {
            progress?.done();
            io.err(`${line}\n`);
        },
        done() {
            progress?.done();
        },
    };
}

/** The summary (stdout) of a finished run. */
export function summaryText(target: SimTarget, finished: SimulatorFinished, untilGoal: boolean, cwd: string): string {
    const row = (label: string, value: string): string => `  ${label.padEnd(18)}${value}`;
    const lines = [
        `${target.platform} (${target.mode} mode): ${finished.reason}`,
        row('simulated time', seconds(finished.time)),
        row('wall time', seconds(finished.wall_seconds)),
        row('real-time factor', factor(finished.real_time_factor)),
        row('goal', `${finished.goal_reached ? 'reached' : 'not reached'}${untilGoal ? '' : ' (not waited for)'}`),
    ];
    const record = finished.record;
    if (record) {
        const topics = Object.keys(record.topics).length;
        lines.push(row('recording', `${path.relative(cwd, record.path) || record.path}: ${record.messages} messages on ${topics} topics`));
    }
    return `${lines.join('\n')}\n`;
}

/** The `--format json` summary: maa-sim's finished line with the platform and mode. */
export function summaryJson(target: SimTarget, finished: SimulatorFinished): string {
    const { event: _event, ...rest } = finished;
    return `${JSON.stringify({ platform: target.platform, mode: target.mode, package: target.packageDir, ...rest }, null, 2)}\n`;
}
