import { topicMapContract, type TopicMapAnswer } from '@maa/protocol';
import { describe, expect, it } from 'vitest';
import { instanceOfNode, portsByTopic } from '../src/backend.js';

const map: TopicMapAnswer = topicMapContract.parse({
    app: 'toast-service/TR.arcapp',
    platform: 'rospython',
    mode: 'ros2',
    ports: [
        {
            portPath: 'ctrl.distance',
            instancePath: 'ctrl',
            port: 'distance',
            direction: 'in',
            topic: '/toast_service_robot/distance',
            type: 'std_msgs/msg/Int32',
            external: true,
        },
        {
            portPath: 'ctrl.arm',
            instancePath: 'ctrl',
            port: 'arm',
            direction: 'out',
            topic: '/toast_service_robot/ctrl/arm',
            type: 'std_msgs/msg/String',
            external: false,
        },
        {
            portPath: 'arm.program',
            instancePath: 'arm',
            port: 'program',
            direction: 'in',
            topic: '/toast_service_robot/ctrl/arm',
            type: 'std_msgs/msg/String',
            external: false,
        },
        {
            portPath: 'toasterCtrl.leverDown',
            instancePath: 'toasterCtrl',
            port: 'leverDown',
            direction: 'out',
            topic: '/toast_service_robot/toaster_ctrl/lever_down',
            type: 'std_msgs/msg/Bool',
            external: false,
        },
    ],
    nodes: [{ instancePath: 'toasterCtrl', node: '/toast_service_robot/toaster_ctrl' }],
});

describe('the backend topic map (GET /api/sim/topics)', () => {
    it('maps a topic to the port that publishes it, keeping the port path spelling', () => {
        const byTopic = portsByTopic(map);
        expect(byTopic.get('/toast_service_robot/ctrl/arm')?.portPath).toBe('ctrl.arm');
        expect(byTopic.get('/toast_service_robot/toaster_ctrl/lever_down')?.portPath).toBe('toasterCtrl.leverDown');
        expect(byTopic.get('/toast_service_robot/distance')).toMatchObject({ external: true, direction: 'in' });
        expect(byTopic.get('/clock')).toBeUndefined();
    });

    it('maps an automaton-state node to its instance path, not a snake-case guess', () => {
        expect(instanceOfNode(map, '/toast_service_robot/toaster_ctrl')).toBe('toasterCtrl');
        expect(instanceOfNode(map, '/toast_service_robot/toaster_ctrl/')).toBe('toasterCtrl');
        expect(instanceOfNode(map, '/other/node')).toBeUndefined();
    });

    it('refuses a map that breaks the contract', () => {
        expect(topicMapContract.check({ ...map, ports: [{ ...map.ports[0], topic: 'relative' }] })).toBe(false);
        expect(topicMapContract.check({ ...map, mode: 'fast' })).toBe(false);
    });
});
