// SimSessions' `wrap` option (the lab runs maa-sim in its sandbox through it): the session runs the
// wrapper's command line, which gets maa-sim's command, arguments and package folder; stops reach
// the wrapped maa-sim through the wrapper. Stand-ins (shell scripts) for the wrapper and maa-sim.
import { chmodSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer, type Server } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { SIM_PACKAGE_FILE } from '@maa/protocol/sim-package';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type SimLaunch, SimSessions } from '../src/sim-session.js';

describe('simulation sessions with a command wrapper', () => {
    let listener: Server;
    let dir: string;

    beforeAll(async () => {
        listener = createServer((socket) => socket.destroy()); // stands in for the rosbridge port
        await new Promise<void>((resolve) => listener.listen(0, '127.0.0.1', resolve));
        dir = mkdtempSync(path.join(tmpdir(), 'maa-sim-wrap-'));
    });
    afterAll(async () => {
        await new Promise<void>((resolve) => listener.close(() => resolve()));
        rmSync(dir, { recursive: true, force: true });
    });

    const script = (name: string, body: string) => {
        const file = path.join(dir, name);
        writeFileSync(file, `#!/bin/bash\n${body}\n`);
        chmodSync(file, 0o755);
        return file;
    };

    it('runs the wrapped command line and stops maa-sim through it', async () => {
        const port = (listener.address() as { port: number }).port;
        const stopped = path.join(dir, 'stopped');
        const maaSim = script(
            'fake-maa-sim',
            `trap 'echo "$PWD" > ${stopped}; exit 0' TERM\necho '{"event": "ready", "rosbridge": "ws://127.0.0.1:${port}", "viser": null}'\nwhile :; do sleep 0.1; done`,
        );
        const seen = path.join(dir, 'wrapper-args');
        // The wrapper records what it runs, passes SIGTERM on and waits, as maa_sim.sandbox does. In
        // Python: a bash stand-in (trap, `cmd &`, `wait`) now and then ended by the stop's signal before
        // its trap was set, or with 255 from `wait`, under load (seen in 1 of 200 runs).
        const wrapper = path.join(dir, 'wrapper');
        writeFileSync(
            wrapper,
            [
                '#!/usr/bin/env python3',
                'import signal, subprocess, sys',
                'child = None',
                'signal.signal(signal.SIGTERM, lambda *_: child and child.send_signal(signal.SIGTERM))',
                `with open(${JSON.stringify(seen)}, 'w') as f:`,
                "    f.write('\\n'.join(sys.argv[1:]) + '\\n')",
                'child = subprocess.Popen(sys.argv[2:])',
                'sys.exit(child.wait())',
                '',
            ].join('\n'),
        );
        chmodSync(wrapper, 0o755);
        const platformDir = path.join(dir, 'platform');
        mkdirSync(platformDir);
        writeFileSync(path.join(platformDir, SIM_PACKAGE_FILE.lockstep), '{}');
        const launches: SimLaunch[] = [];
        const sims = new SimSessions(maaSim, {
            stopGraceMs: 30_000,
            wrap: (launch) => {
                launches.push(launch);
                return { command: wrapper, args: ['--', launch.command, ...launch.args] };
            },
        });
        try {
            await sims.start({ app: 'a/A.arcapp', platform: 'timesync', mode: 'lockstep', platformDir });
            expect(sims.status().running).toBe(true);
            expect(launches).toHaveLength(1);
            expect(launches[0]).toMatchObject({ command: maaSim, cwd: platformDir, request: { mode: 'lockstep' } });
            expect(launches[0]!.args.slice(0, 3)).toEqual(['run', '--package', platformDir]);
            // one set of run controls: the simulate view's (viser's panel without its own)
            const controls = launches[0]!.args.indexOf('--viser-controls');
            expect(launches[0]!.args[controls + 1]).toBe('off');
            expect(readFileSync(seen, 'utf8').split('\n').slice(0, 3)).toEqual(['--', maaSim, 'run']);
            await sims.stop();
            // maa-sim got the stop's SIGTERM (through the wrapper) and ended gracefully in its package folder
            expect(readFileSync(stopped, 'utf8').trim()).toBe(platformDir);
            expect(sims.status()).toMatchObject({ running: false, exitCode: 0 });
        } finally {
            sims.dispose();
        }
    }, 120_000);
});
