import { describe, expect, it } from 'vitest';
import type { TopicMapAnswer } from '../src/backend.js';
import { PortMap } from '../src/port-map.js';

/** A lock-step map: out ports of atomic instances and the root's in ports (external). */
const lockstep: TopicMapAnswer = {
    app: 'toast-service/TR.arcapp',
    platform: 'timesync',
    mode: 'lockstep',
    ports: [
        {
            portPath: 'toasterCtrl.leverDown',
            instancePath: 'toasterCtrl',
            port: 'leverDown',
            direction: 'out',
            topic: '/tsr/toaster_ctrl/lever_down',
            type: 'std_msgs/msg/Bool',
            external: false,
        },
        {
            portPath: 'distance',
            instancePath: '',
            port: 'distance',
            direction: 'in',
            topic: '/tsr/distance',
            type: 'std_msgs/msg/Float64',
            external: true,
        },
    ],
    nodes: [
        { instancePath: '', node: '/tsr' },
        { instancePath: 'toasterCtrl', node: '/tsr/toaster_ctrl' },
    ],
};

/** A ROS 2 map: every node's out and in ports; a topic fed from outside appears as the in ports reading it. */
const ros2: TopicMapAnswer = {
    app: 'toast-service/TR.arcapp',
    platform: 'rospython',
    mode: 'ros2',
    ports: [
        {
            portPath: 'ctrl.arm',
            instancePath: 'ctrl',
            port: 'arm',
            direction: 'out',
            topic: '/tsr/ctrl/arm',
            type: 'std_msgs/msg/Int32',
            external: false,
        },
        {
            portPath: 'arm.cmd',
            instancePath: 'arm',
            port: 'cmd',
            direction: 'in',
            topic: '/tsr/ctrl/arm',
            type: 'std_msgs/msg/Int32',
            external: false,
        },
        {
            portPath: 'ctrl.distance',
            instancePath: 'ctrl',
            port: 'distance',
            direction: 'in',
            topic: '/tsr/distance',
            type: 'std_msgs/msg/Float64',
            external: true,
        },
        {
            portPath: 'watch.distance',
            instancePath: 'watch',
            port: 'distance',
            direction: 'in',
            topic: '/tsr/distance',
            type: 'std_msgs/msg/Float64',
            external: true,
        },
    ],
    nodes: [{ instancePath: 'ctrl', node: '/tsr/ctrl' }],
};

describe('port map (the served port topics)', () => {
    it('maps topics to their ports; platform topics are no ports', () => {
        const map = new PortMap(lockstep);
        expect(map.portOf('/tsr/toaster_ctrl/lever_down')?.portPath).toBe('toasterCtrl.leverDown');
        expect(map.portOf('/tsr/distance')).toMatchObject({ portPath: 'distance', external: true });
        expect(map.portOf('/clock')).toBeUndefined();
        expect(map.portOf('/tsr/unknown')).toBeUndefined();
    });

    it('shows a published value on its publisher, an outside one on the ports reading it', () => {
        const lock = new PortMap(lockstep);
        expect(lock.diagramPaths('/tsr/toaster_ctrl/lever_down')).toEqual(['toasterCtrl.leverDown']);
        expect(lock.diagramPaths('/tsr/distance')).toEqual(['distance']);
        const ros = new PortMap(ros2);
        expect(ros.portOf('/tsr/ctrl/arm')?.portPath).toBe('ctrl.arm');
        expect(ros.diagramPaths('/tsr/ctrl/arm')).toEqual(['ctrl.arm']);
        expect(ros.portOf('/tsr/distance')).toMatchObject({ portPath: 'ctrl.distance', external: true });
        expect(ros.diagramPaths('/tsr/distance')).toEqual(['ctrl.distance', 'watch.distance']);
        expect(ros.diagramPaths('/clock')).toEqual([]);
    });

    it('maps automaton state nodes to instance paths', () => {
        const map = new PortMap(lockstep);
        expect(map.instanceOf('/tsr')).toBe('');
        expect(map.instanceOf('/tsr/toaster_ctrl/')).toBe('toasterCtrl');
        expect(map.instanceOf('/tsr/other')).toBeUndefined();
    });
});
