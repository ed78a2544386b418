import type { AutomatonEntry, Deployment, DeploymentNode, PortTopic } from '@maa/protocol';
import { DEPLOYMENT_FORMAT } from '@maa/protocol/formats';
import {
    publishedTopics,
    subscribedTopics,
    type ComponentNode,
    type ModeManagerNode,
    type Parameter,
    type Ros2Application,
} from './model.js';
import { automatonEntry } from '../../behavior/automata-table.js';

/**
 * `deployment.json` (the contract `Deployment` of `@maa/protocol`, docs/simulation.md): the
 * application model as the simulator starts it without `launch`.
 */
export function deploymentOf(app: Ros2Application, application: string): Deployment {
    return {
        format: DEPLOYMENT_FORMAT,
        application,
        package: app.pkg,
        python_path: ['.'],
        env: {},
        nodes: [...app.nodes, ...app.managers].map(deploymentNode),
        automata: automataOf(app),
    };
}

/**
 * The automata table (the IDE's trace and breakpoints): the nodes of instances with an automaton,
 * and the mode automata of mode components under their mode manager's namespace (the instance's
 * node path, where the manager reports the mode and its transitions).
 */
function automataOf(app: Ros2Application): AutomatonEntry[] {
    const nodes = app.nodes.flatMap((n) => {
        const entry = automatonEntry(n.instance, `${n.namespace === '/' ? '' : n.namespace}/${n.name}`);
        return entry ? [entry] : [];
    });
    const managers = app.managers.flatMap((m) => {
        const entry = automatonEntry(m.instance, m.namespace);
        return entry ? [entry] : [];
    });
    return [...nodes, ...managers];
}

function deploymentNode(n: ComponentNode | ModeManagerNode): DeploymentNode {
    return {
        name: n.name,
        namespace: n.namespace,
        instance: n.instancePath,
        component: n.instance.component.qualifiedName,
        module: n.module,
        args: [],
        parameters: Object.fromEntries(n.parameters.map((p) => [p.name, p.value])),
        subscribes: subscribedTopics(n).map(portTopic),
        publishes: publishedTopics(n).map(portTopic),
    };
}

function portTopic(t: PortTopic): PortTopic {
    return { ...(t.port !== undefined ? { port: t.port } : {}), topic: t.topic, type: t.type };
}

/**
 * The text of deployment.json: JSON with two-space indentation, and a double parameter keeps its
 * decimal point (`1.0`): rcl would read `1` as an integer and reject it for a parameter the node
 * declares as double.
 */
export function deploymentJson(app: Ros2Application, deployment: Deployment): string {
    const floats = new Map([...app.nodes, ...app.managers].map((n, i) => [i, new Set(n.parameters.filter(isFloat).map((p) => p.name))]));
    const text = formatJson(deployment, (value, path) => {
        const [nodes, index, parameters, name] = path;
        const float = nodes === 'nodes' && parameters === 'parameters' && path.length === 4 && floats.get(Number(index))?.has(String(name));
        return float && Number.isInteger(value) ? `${value}.0` : JSON.stringify(value);
    });
    return `${text}\n`;
}

function isFloat(p: Parameter): boolean {
    return p.float;
}

/**
 * JSON.stringify(value, null, 2) with the text of numbers chosen by `number` (given the path
 * of keys and indices to the number).
 */
export function formatJson(
    value: unknown,
    number: (n: number, path: ReadonlyArray<string | number>) => string,
    path: ReadonlyArray<string | number> = [],
    indent = '',
): string {
    if (typeof value === 'number') return number(value, path);
    if (value === null || typeof value !== 'object') return JSON.stringify(value);
    const inner = `${indent}  `;
    if (Array.isArray(value)) {
        if (value.length === 0) return '[]';
        return `[\n${value.map((v, i) => `${inner}${formatJson(v, number, [...path, i], inner)}`).join(',\n')}\n${indent}]`;
    }
    const entries = Object.entries(value).filter(([, v]) => v !== undefined);
    if (entries.length === 0) return '{}';
    return `{\n${entries.map(([k, v]) => `${inner}${JSON.stringify(k)}: ${formatJson(v, number, [...path, k], inner)}`).join(',\n')}\n${indent}}`;
}
