import { describe, expect, it } from 'vitest';
import { backendError, defaultPlatform, platformMode, preparingLine, runChoices, statusLine, unwrapStatus } from '../src/logic.js';

const TR = {
    path: 'toast-service/TR.arcapp',
    name: 'TR',
    component: 'toast.ToastServiceRobot',
    platforms: [
        { name: 'rospython', kind: 'ros2' },
        { name: 'timesync', kind: 'timesync' },
        { name: 'docs', kind: 'other' },
    ],
};

describe('simulate panel logic', () => {
    it('maps platform kinds to modes', () => {
        expect(platformMode('timesync')).toBe('lockstep');
        expect(platformMode('ros2')).toBe('ros2');
        expect(platformMode('other')).toBeUndefined();
        expect(runChoices([TR])).toEqual([
            { app: TR.path, platform: 'rospython', mode: 'ros2' },
            { app: TR.path, platform: 'timesync', mode: 'lockstep' },
        ]);
        expect(defaultPlatform(TR)).toBe('timesync');
        expect(defaultPlatform({ ...TR, platforms: [{ name: 'rospython', kind: 'ros2' }] })).toBe('rospython');
        expect(defaultPlatform({ ...TR, platforms: [] })).toBeUndefined();
    });
    it('writes the status line', () => {
        const st = { time: 12.3456, paused: false, speed: 1, real_time_factor: 0.987, toast_level: 0.5 };
        expect(statusLine(st)).toBe('running · t 12.35 s · RTF 0.99 · speed 1× · toast 0.50');
        expect(statusLine({ ...st, paused: true, speed: 0, toast_on_plate: true }, 20)).toBe(
            'paused · t 20.00 s · RTF 0.99 · speed max · toast 0.50 on plate',
        );
        expect(statusLine({ finished: 'goal' })).toBe('finished (goal)');
        expect(statusLine({ real_time_factor: null })).toBe('running');
    });
    it('unwraps status answers', () => {
        expect(unwrapStatus({ success: true, message: '', status: { time: 1 } })).toEqual({ time: 1 });
        expect(unwrapStatus({ time: 2, paused: true })).toEqual({ time: 2, paused: true });
        expect(unwrapStatus(undefined)).toEqual({});
    });
    it('reads backend errors with their log tail', () => {
        expect(backendError(500, { error: 'maa-sim exited', log: ['a', 'b'] })).toEqual({ message: 'maa-sim exited', log: ['a', 'b'] });
        expect(backendError(409, { error: 'busy', log: 'x\ny' })).toEqual({ message: 'busy', log: ['x', 'y'] });
        expect(backendError(502, 'Bad gateway')).toEqual({ message: 'Bad gateway', log: [] });
        expect(backendError(500, null)).toEqual({ message: 'HTTP 500', log: [] });
    });
});

describe('preparingLine', () => {
    it('shows the phase of an open start with the elapsed time', () => {
        expect(preparingLine('TR on timesync', 2)).toBe('Starting TR on timesync (generating, 2 s)…');
        expect(preparingLine('TR on timesync', 3, { running: true, log: [] })).toBe(
            'Starting TR on timesync: waiting for the simulator (3 s)…',
        );
    });
    it('shows the last progress line while a ROS 2 environment is prepared', () => {
        const st = {
            running: false,
            preparing: true,
            log: ['building toast_service_robot_interfaces', 'maa-ide: still building (15 s)', ''],
        };
        expect(preparingLine('TR on rospython', 16, st)).toBe(
            'Preparing TR on rospython (ROS 2 environment, 16 s) · maa-ide: still building (15 s)',
        );
        expect(preparingLine('TR on rospython', 1, { preparing: true })).toBe('Preparing TR on rospython (ROS 2 environment, 1 s)');
    });
});
