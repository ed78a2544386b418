import { describe, expect, it } from 'vitest';
import { rosName } from '@maa/generators-python/ros-names';
import { instancePathToNode, nodeToInstancePath, portPathToTopic, rootNamespace, topicIndex, topicToPort } from '../src/simulate/topics.js';
import { parseAutomatonStates } from '../src/simulate/states.js';
import { rosbridgeUrl } from '../src/ros/url.js';

const ROOT = 'toast.ToastServiceRobot';

describe('naming', () => {
    it('spells segments like the ROS 2 generator', () => {
        expect(rosName('ToastServiceRobot')).toBe('toast_service_robot');
        expect(rosName('armCmd')).toBe('arm_cmd');
        expect(rosName('HTTPServer2go')).toBe('http_server2go');
        expect(rosName('ctrl')).toBe('ctrl');
        expect(rosName('2x')).toBe('x_2x');
        expect(rootNamespace(ROOT)).toBe('/toast_service_robot');
    });
    it('maps port paths to topics', () => {
        expect(portPathToTopic(ROOT, 'ctrl.arm')).toBe('/toast_service_robot/ctrl/arm');
        expect(portPathToTopic(ROOT, 'unit.sensorA.rawValue')).toBe('/toast_service_robot/unit/sensor_a/raw_value');
        expect(portPathToTopic(ROOT, 'distance')).toBe('/toast_service_robot/distance');
        expect(instancePathToNode(ROOT, 'ctrl')).toBe('/toast_service_robot/ctrl');
        expect(instancePathToNode(ROOT, '')).toBe('/toast_service_robot');
    });
});

describe('topicToPort', () => {
    it('maps port topics to port paths, root ports included', () => {
        expect(topicToPort(ROOT, '/toast_service_robot/ctrl/arm')).toEqual({
            topic: '/toast_service_robot/ctrl/arm', portPath: 'ctrl.arm', instancePath: 'ctrl', port: 'arm', rootPort: false,
        });
        expect(topicToPort(ROOT, '/toast_service_robot/start')).toMatchObject({ portPath: 'start', instancePath: '', rootPort: true });
        expect(topicToPort(ROOT, '/toast_service_robot/unit/ctrl/value')?.portPath).toBe('unit.ctrl.value');
    });
    it('leaves platform topics out', () => {
        expect(topicToPort(ROOT, '/clock')).toBeUndefined();
        expect(topicToPort(ROOT, '/sensors/distance')).toBeUndefined();
        expect(topicToPort(ROOT, '/toast_service_robot')).toBeUndefined();
        expect(topicToPort(ROOT, '/toast_service_robot_x/a')).toBeUndefined();
    });
    it('restores the spelling of known port paths', () => {
        const idx = topicIndex(ROOT, ['ctrl.armCmd', 'sensorUnit.rawValue', 'ctrl.arm']);
        expect(topicToPort(ROOT, '/toast_service_robot/ctrl/arm_cmd', idx)?.portPath).toBe('ctrl.armCmd');
        expect(topicToPort(ROOT, '/toast_service_robot/sensor_unit/raw_value', idx)).toMatchObject({ portPath: 'sensorUnit.rawValue', instancePath: 'sensorUnit', port: 'rawValue' });
        expect(topicToPort(ROOT, '/toast_service_robot/ctrl/unknown_port', idx)?.portPath).toBe('ctrl.unknown_port');
    });
    it('round-trips', () => {
        for (const p of ['ctrl.arm', 'a.b.c', 'x']) expect(topicToPort(ROOT, portPathToTopic(ROOT, p))?.portPath).toBe(p);
    });
});

describe('nodeToInstancePath', () => {
    it('maps node paths with and without known spellings', () => {
        expect(nodeToInstancePath(ROOT, '/toast_service_robot/ctrl')).toBe('ctrl');
        expect(nodeToInstancePath(ROOT, '/toast_service_robot/unit/arm_ctrl', ['unit.armCtrl'])).toBe('unit.armCtrl');
        expect(nodeToInstancePath(ROOT, '/toast_service_robot')).toBe('');
        expect(nodeToInstancePath(ROOT, '/other/ctrl')).toBeUndefined();
    });
});

describe('parseAutomatonStates', () => {
    it('parses the JSON in data', () => {
        const m = parseAutomatonStates({ data: JSON.stringify({ '/toast_service_robot/ctrl': 'Toasting', '/toast_service_robot/unit/armCtrl': 'Outer.Inner', '/elsewhere/x': 'A' }) }, ROOT, ['unit.armCtrl']);
        expect([...m]).toEqual([['ctrl', 'Toasting'], ['unit.armCtrl', 'Outer.Inner']]);
    });
    it('tolerates malformed messages', () => {
        expect(parseAutomatonStates({ data: 'not json' }, ROOT).size).toBe(0);
        expect(parseAutomatonStates({ data: '[1]' }, ROOT).size).toBe(0);
        expect(parseAutomatonStates(undefined, ROOT).size).toBe(0);
        expect(parseAutomatonStates({ data: JSON.stringify({ '/toast_service_robot/ctrl': 3 }) }, ROOT).size).toBe(0);
    });
    it('accepts the bare string', () => {
        expect(parseAutomatonStates('{"/toast_service_robot/ctrl":"Idle"}', ROOT).get('ctrl')).toBe('Idle');
    });
});

describe('rosbridgeUrl', () => {
    it('follows the page protocol', () => {
        expect(rosbridgeUrl({ protocol: 'http:', host: '127.0.0.1:3000' })).toBe('ws://127.0.0.1:3000/sim/rosbridge');
        expect(rosbridgeUrl({ protocol: 'https:', host: 'lab.example.org' })).toBe('wss://lab.example.org/sim/rosbridge');
    });
});
