import type { AstNode } from 'langium';
import { GenerationError } from '@maa/generator-core/node';
import { publishedTopics, type Ros2Application } from './model.js';

/**
 * The rules every generated application keeps (docs/generating-ros2.md): each is checked on
 * the application model after it is built, and the first violation stops generation as a
 * `gen/generator-failed` diagnostic on the model element that breaks it. They need the built
 * model (topics of handwritten nodes come from their user files, types from ros2.DataTypes), so
 * they are not manifest `checks`, which run on the architecture before any generator does.
 */
export interface TopicRule {
    readonly name: string;
    readonly description: string;
    check(app: Ros2Application): Iterable<{ readonly node: AstNode; readonly message: string }>;
}

export const TOPIC_RULES: readonly TopicRule[] = [
    {
        name: 'ros2.OnePublisherPerTopic',
        description: "A topic has exactly one publisher: a node's out port, a handwritten node's PUBLISHES, or a mode manager.",
        *check(app) {
            const publishers = new Map<string, string>();
            for (const n of [...app.managers, ...app.nodes]) {
                for (const t of publishedTopics(n)) {
                    const other = publishers.get(t.topic);
                    if (other)
                        yield {
                            node: t.node,
                            message: `topic ${t.topic} would have two publishers, ${other} and ${n.fqn}; a topic has exactly one publisher`,
                        };
                    publishers.set(t.topic, n.fqn);
                }
            }
        },
    },
    {
        name: 'ros2.OneTypePerTopic',
        description: 'Every node that publishes or reads a topic agrees on its message type.',
        *check(app) {
            const types = new Map<string, string>();
            for (const n of app.nodes) {
                const read = [
                    ...n.inputs.map((i) => ({ topic: i.topic, type: i.rosType, node: i.node })),
                    ...n.platform.subscribes.map((t) => ({ ...t, node: n.component.node })),
                ];
                for (const t of [...publishedTopics(n), ...read]) {
                    const known = types.get(t.topic);
                    if (known && known !== t.type)
                        yield { node: t.node, message: `topic ${t.topic} would carry two types, ${known} and ${t.type}` };
                    types.set(t.topic, t.type);
                }
            }
        },
    },
    {
        name: 'ros2.ReadTopicsArePublished',
        description: "A topic a node's in port reads has a publisher, unless it is an in port of the application (fed from outside).",
        *check(app) {
            const published = new Set([...app.managers, ...app.nodes].flatMap((n) => publishedTopics(n).map((t) => t.topic)));
            for (const n of app.nodes) {
                for (const i of n.inputs) {
                    if (!published.has(i.topic) && !i.topic.startsWith(`${app.rootNs}/`)) {
                        yield { node: i.node, message: `in port '${i.port}' of ${n.fqn} reads topic ${i.topic}, which has no publisher` };
                    }
                }
            }
        },
    },
];

/** Throws a GenerationError for the first violation of a topic rule. */
export function checkTopicRules(app: Ros2Application, rules: readonly TopicRule[] = TOPIC_RULES): void {
    for (const rule of rules) {
        for (const v of rule.check(app)) throw new GenerationError(v.message, v.node);
    }
}
