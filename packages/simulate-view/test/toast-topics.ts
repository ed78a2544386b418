/** The port topics of a lock-step run of the toast example as the backend answers them (shared test data). */
import type { TopicMapAnswer } from '../src/backend.js';

/** A map with the lever's out port of `ctrl` and the root's `distance` in port, and the given nodes. */
export function toastTopicMap(nodes: TopicMapAnswer['nodes']): TopicMapAnswer {
    return {
        app: 'toast-service/TR.arcapp',
        platform: 'timesync',
        mode: 'lockstep',
        ports: [
            {
                portPath: 'ctrl.leverDown',
                instancePath: 'ctrl',
                port: 'leverDown',
                direction: 'out',
                topic: '/tsr/ctrl/lever_down',
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
        nodes,
    };
}
