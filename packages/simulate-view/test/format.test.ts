import { describe, expect, it } from 'vitest';
import {
    clockSeconds,
    enumLiteralsOf,
    formatNumber,
    formatRosValue,
    isEnumMessage,
    numericValue,
    parseInjectedValue,
} from '../src/format.js';
import { SampleWindow, sparklinePath } from '../src/plot.js';

describe('formatRosValue', () => {
    it('unwraps std_msgs wrappers', () => {
        expect(formatRosValue({ data: 22 })).toBe('22');
        expect(formatRosValue({ data: 'GOLDEN' })).toBe('GOLDEN');
        expect(formatRosValue({ data: true })).toBe('true');
        expect(formatRosValue({ data: 0.060000001 })).toBe('0.06');
        expect(formatRosValue({ data: 1.23456789 })).toBe('1.235');
    });
    it('formats joint states as name=value pairs', () => {
        expect(
            formatRosValue({
                header: { stamp: { sec: 1, nanosec: 0 }, frame_id: '' },
                name: ['base_yaw', 'lift'],
                position: [2.0943951, 0.2],
                velocity: [],
                effort: [],
            }),
        ).toBe('base_yaw=2.094 lift=0.2');
    });
    it('formats structures, arrays and times compactly', () => {
        expect(formatRosValue({ kind: 'MOVE', target: { angle: 1.5, height: 0.07 } })).toBe(
            '{kind: MOVE, target: {angle: 1.5, height: 0.07}}',
        );
        expect(formatRosValue([1, 2, 3, 4, 5, 6, 7, 8, 9, 10])).toBe('[1, 2, 3, 4, 5, 6, 7, 8, …+2]');
        expect(formatRosValue({ sec: 12, nanosec: 500_000_000 })).toBe('12.5 s');
        expect(formatRosValue(null)).toBe('–');
    });
    it('cuts long texts', () => {
        const s = formatRosValue({ data: 'x'.repeat(200) }, 20);
        expect(s).toHaveLength(20);
        expect(s.endsWith('…')).toBe(true);
    });
    it('formats numbers', () => {
        expect(formatNumber(1e-6)).toBe('1.00e-6');
        expect(formatNumber(-0.123456)).toBe('-0.1235');
        expect(formatNumber(NaN)).toBe('NaN');
    });
});

describe('numericValue', () => {
    it('finds the number of a message', () => {
        expect(numericValue({ data: 22 })).toBe(22);
        expect(numericValue({ data: false })).toBe(0);
        expect(numericValue(3.5)).toBe(3.5);
        expect(numericValue({ value: 7 })).toBe(7);
        expect(numericValue({ data: 'GOLDEN' })).toBeUndefined();
        expect(numericValue({ a: 1, b: 2 })).toBeUndefined();
        expect(numericValue({ a: 1, b: 'x' })).toBeUndefined();
        expect(numericValue([1])).toBeUndefined();
    });
    it('reads the clock', () => {
        expect(clockSeconds({ clock: { sec: 3, nanosec: 250_000_000 } })).toBe(3.25);
        expect(clockSeconds({})).toBeUndefined();
    });
});

describe('parseInjectedValue', () => {
    it('wraps plain values for std_msgs primitives', () => {
        expect(parseInjectedValue('std_msgs/msg/Int32', ' 42 ')).toEqual({ data: 42 });
        expect(parseInjectedValue('std_msgs/Float64', '0.5')).toEqual({ data: 0.5 });
        expect(parseInjectedValue('std_msgs/msg/Bool', 'true')).toEqual({ data: true });
        expect(parseInjectedValue('std_msgs/msg/String', 'GOLDEN')).toEqual({ data: 'GOLDEN' });
        expect(parseInjectedValue('std_msgs/msg/Int32', '{"data": 3}')).toEqual({ data: 3 });
    });
    it('rejects values that do not fit', () => {
        expect(() => parseInjectedValue('std_msgs/msg/Int32', '1.5')).toThrow(/integer/);
        expect(() => parseInjectedValue('std_msgs/msg/Int32', 'abc')).toThrow(/number/);
        expect(() => parseInjectedValue('std_msgs/msg/Bool', 'yes')).toThrow();
        expect(() => parseInjectedValue('pkg/msg/Cmd', 'x')).toThrow(/JSON/);
        expect(() => parseInjectedValue('pkg/msg/Cmd', '[1]')).toThrow(/object/);
    });
    it('takes JSON for other types', () => {
        expect(parseInjectedValue('toast_service_robot_interfaces/msg/ToasterCmd', '{"value": "START"}')).toEqual({ value: 'START' });
    });
});

describe('SampleWindow', () => {
    it('keeps the last samples in order', () => {
        const w = new SampleWindow(3);
        for (let i = 0; i < 5; i++) w.push(i, i * 10);
        expect(w.samples().map((s) => s.v)).toEqual([20, 30, 40]);
        expect(w.length).toBe(3);
        expect(w.range()).toEqual({ min: 20, max: 40 });
        expect(w.last()).toEqual({ t: 4, v: 40 });
        w.push(5, NaN);
        expect(w.length).toBe(3);
        w.clear();
        expect(w.samples()).toEqual([]);
        expect(w.range()).toBeUndefined();
    });
    it('defaults to 200 samples', () => {
        const w = new SampleWindow();
        for (let i = 0; i < 450; i++) w.push(i, i);
        expect(w.length).toBe(200);
        expect(w.samples()[0]!.v).toBe(250);
    });
    it('draws a sparkline into the box', () => {
        expect(sparklinePath([], 100, 20)).toBe('');
        expect(
            sparklinePath(
                [
                    { t: 0, v: 0 },
                    { t: 1, v: 10 },
                ],
                100,
                20,
                0,
            ),
        ).toBe('M 0 20 L 100 0');
        expect(
            sparklinePath(
                [
                    { t: 0, v: 5 },
                    { t: 1, v: 5 },
                ],
                100,
                20,
                0,
            ),
        ).toBe('M 0 10 L 100 10');
    });
});

describe('enum values in both simulator modes', () => {
    it('shows the lock-step form (std_msgs/String) as the literal', () => {
        expect(formatRosValue({ data: 'GOLDEN' })).toBe('GOLDEN');
        expect(numericValue({ data: 'GOLDEN' })).toBeUndefined();
    });
    it('shows the ROS 2 enum message as its literal when the literals are known, else as #ordinal', () => {
        const literals = ['WHITE', 'GOLDEN', 'BURNT'];
        expect(formatRosValue({ value: 1 }, 80, { enumLiterals: literals })).toBe('GOLDEN');
        expect(formatRosValue({ value: 1 })).toBe('#1');
        expect(formatRosValue({ value: 7 }, 80, { enumLiterals: literals })).toBe('#7');
        // ordinals plot as numbers
        expect(numericValue({ value: 2 })).toBe(2);
    });
    it('leaves other messages with a value field alone', () => {
        expect(formatRosValue({ value: 1.5 })).toBe('{value: 1.5}');
        expect(formatRosValue({ value: 1, unit: 'm' })).toBe('{value: 1, unit: m}');
        expect(isEnumMessage({ value: 3 })).toBe(true);
        expect(isEnumMessage({ value: '3' })).toBe(false);
    });
    it('shows enum fields inside structures by ordinal', () => {
        expect(formatRosValue({ color: { value: 2 }, level: 0.5 })).toBe('{color: #2, level: 0.5}');
    });
    it('reads the literals from rosapi message_details', () => {
        expect(enumLiteralsOf({ fieldnames: ['value'], constnames: ['BURNT', 'WHITE', 'GOLDEN'], constvalues: ['2', '0', '1'] })).toEqual([
            'WHITE',
            'GOLDEN',
            'BURNT',
        ]);
        expect(enumLiteralsOf({ fieldnames: ['value'], constnames: [], constvalues: [] })).toBeUndefined();
        expect(enumLiteralsOf({ fieldnames: ['data'], constnames: ['A'], constvalues: ['0'] })).toBeUndefined();
        expect(enumLiteralsOf({ fieldnames: ['value'], constnames: ['A', 'B'], constvalues: ['0', '5'] })).toBeUndefined();
        expect(enumLiteralsOf(undefined)).toBeUndefined();
    });
});
