/**
 * The port topics of the running application as the backend serves them (`GET /api/sim/topics`,
 * read from what the generator wrote): the port a topic carries, the diagram's port paths a
 * value goes to, and the instance of a node of `/maa/automaton_states`. Pure over the answer.
 */
import { instanceOfNode, portsByTopic, type PortTopicEntry, type TopicMapAnswer } from './backend.js';

export class PortMap {
    private readonly byTopic: Map<string, PortTopicEntry>;
    /** The in ports that read a topic no port publishes (external), by topic. */
    private readonly readers = new Map<string, string[]>();

    constructor(private readonly map: TopicMapAnswer) {
        this.byTopic = portsByTopic(map);
        for (const p of map.ports) {
            if (p.direction !== 'in' || this.byTopic.get(p.topic)?.direction !== 'in') continue;
            const list = this.readers.get(p.topic) ?? [];
            if (!list.includes(p.portPath)) list.push(p.portPath);
            this.readers.set(p.topic, list);
        }
    }

    /** The port a topic carries (its publisher; for a topic fed from outside, a port reading it); `undefined` for platform topics. */
    portOf(topic: string): PortTopicEntry | undefined {
        return this.byTopic.get(topic);
    }

    /** The port paths the diagram shows a topic's value on: its publisher, or every port reading a topic nobody publishes. */
    diagramPaths(topic: string): string[] {
        const port = this.byTopic.get(topic);
        if (!port) return [];
        return port.direction === 'out' ? [port.portPath] : (this.readers.get(topic) ?? [port.portPath]);
    }

    /** The instance path of a node path (`/toast_service_robot/ctrl` → `ctrl`), `undefined` for other nodes. */
    instanceOf(node: string): string | undefined {
        return instanceOfNode(this.map, node);
    }
}
