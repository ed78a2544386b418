/**
 * `GET /api/sim/topics`: the port topics of a generated platform, read from what the generators
 * wrote (never guessed from names): a ros2 platform's `deployment.json` (@maa/protocol's
 * Deployment: each node's instance and the topics of its ports), a timesync platform's app
 * module (`lockstep.json` names it; its `PORT_TOPICS` and `NODE_NAMES` tables, one entry a line).
 * Both also hold the automata table (deployment.json's `automata`, the app module's `AUTOMATA`:
 * one JSON entry a line); a build generated before the table existed has none (an empty list).
 */
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import {
    automatonEntryContract,
    deploymentContract,
    DEPLOYMENT_FILE_NAME,
    type Deployment,
    type AutomatonEntry,
    type InstanceNode,
    type PortTopicEntry,
    type SimMode,
    type TopicMapAnswer,
} from '@maa/protocol';
import { HttpError } from './http-util.js';
import { findPackageDir } from './sim-session.js';

/** The instance path relative to the root: `toastServiceRobot.unit.ctrl` → `unit.ctrl` (the first segment is the root instance). */
function relativeInstance(instance: string): string {
    const dot = instance.indexOf('.');
    return dot < 0 ? '' : instance.slice(dot + 1);
}

function entry(instancePath: string, port: string, direction: 'in' | 'out', topic: string, type: string): PortTopicEntry {
    return { portPath: instancePath ? `${instancePath}.${port}` : port, instancePath, port, direction, topic, type, external: false };
}

/** Marks the in ports whose topic no port publishes (fed from outside: root in ports, platform topics). */
function markExternal(ports: PortTopicEntry[]): PortTopicEntry[] {
    const published = new Set(ports.filter((p) => p.direction === 'out').map((p) => p.topic));
    return ports.map((p) => (p.direction === 'in' && !published.has(p.topic) ? { ...p, external: true } : p));
}

/** The port topics and nodes of a deployment (ros2). */
export function fromDeployment(deployment: Deployment): { ports: PortTopicEntry[]; nodes: InstanceNode[]; automata: AutomatonEntry[] } {
    const ports: PortTopicEntry[] = [];
    const nodes: InstanceNode[] = [];
    for (const node of deployment.nodes) {
        if (node.instance === undefined) continue;
        const instancePath = relativeInstance(node.instance);
        const namespace = node.namespace ?? '/';
        nodes.push({ instancePath, node: `${namespace === '/' ? '' : namespace}/${node.name}` });
        for (const t of node.publishes ?? []) if (t.port) ports.push(entry(instancePath, t.port, 'out', t.topic, t.type));
        for (const t of node.subscribes ?? []) if (t.port) ports.push(entry(instancePath, t.port, 'in', t.topic, t.type));
    }
    return { ports: markExternal(ports), nodes, automata: deployment.automata ?? [] };
}

/**
 * A table of the python-timesync app module: `NAME: dict[...] = {` then one `"key": value,` a line
 * up to `}`. Returns the key and the value's quoted strings per line.
 */
export function pythonTable(source: string, name: string): Array<[string, string[]]> {
    const lines = source.split('\n');
    const start = lines.findIndex((l) => l.startsWith(`${name}: `) && l.endsWith('= {'));
    if (start < 0) throw new HttpError(409, `the generated app module has no ${name} table`);
    const rows: Array<[string, string[]]> = [];
    for (const line of lines.slice(start + 1)) {
        if (line === '}') return rows;
        const strings = [...line.matchAll(/"((?:[^"\\]|\\.)*)"/g)].map((m) => JSON.parse(`"${m[1]}"`) as string);
        if (strings.length < 2) throw new HttpError(409, `unexpected line in the generated ${name} table: ${line.trim()}`);
        rows.push([strings[0]!, strings.slice(1)]);
    }
    throw new HttpError(409, `the generated ${name} table is not closed`);
}

/** The port topics and nodes of a timesync app module (`PORT_TOPICS`: out ports of atomic instances, in ports of the root). */
export function fromAppModule(source: string): { ports: PortTopicEntry[]; nodes: InstanceNode[]; automata: AutomatonEntry[] } {
    const ports = pythonTable(source, 'PORT_TOPICS').map(([key, [topic, type]]) => {
        const dot = key.lastIndexOf('.');
        return dot < 0 ? entry('', key, 'in', topic!, type ?? '') : entry(key.slice(0, dot), key.slice(dot + 1), 'out', topic!, type ?? '');
    });
    const nodes = pythonTable(source, 'NODE_NAMES').map(([instancePath, [node]]) => ({ instancePath, node: node! }));
    return { ports: markExternal(ports), nodes, automata: automataTable(source) };
}

/** The app module's `AUTOMATA` table (none in a build generated before it existed): each line's JSON entry, checked. */
export function automataTable(source: string): AutomatonEntry[] {
    if (!source.split('\n').some((l) => l.startsWith('AUTOMATA: '))) return [];
    return pythonTable(source, 'AUTOMATA').map(([instancePath, [json]]) => {
        let value: unknown;
        try {
            value = JSON.parse(json!);
        } catch (e) {
            throw new HttpError(409, `the generated AUTOMATA entry of ${instancePath} is no JSON: ${(e as Error).message}`);
        }
        if (!automatonEntryContract.check(value)) {
            const issue = automatonEntryContract.issues(value)[0];
            throw new HttpError(409, `the generated AUTOMATA entry of ${instancePath} is invalid: ${issue?.pointer} ${issue?.message}`);
        }
        return value;
    });
}

async function readJson(file: string): Promise<unknown> {
    try {
        return JSON.parse(await readFile(file, 'utf8'));
    } catch (e) {
        throw new HttpError(409, `cannot read ${path.basename(file)}: ${(e as Error).message}`);
    }
}

/** The automata table with its files relative to the workspace (`modelRoot`: the model root's path in it, `""` for its top). */
export function inWorkspace(automata: readonly AutomatonEntry[], modelRoot: string): AutomatonEntry[] {
    return automata.map((a) => ({ ...a, file: modelRoot ? path.posix.join(modelRoot, a.file) : a.file }));
}

/**
 * The topic map of a generated platform folder for a mode (409 when the platform lacks the file of
 * the mode); `modelRoot` is the application's model root relative to the workspace.
 */
export async function topicMap(platformDir: string, app: string, platform: string, mode: SimMode, modelRoot = ''): Promise<TopicMapAnswer> {
    const file = mode === 'ros2' ? DEPLOYMENT_FILE_NAME : 'lockstep.json';
    const dir = findPackageDir(platformDir, file);
    if (!dir) throw new HttpError(409, `the generated platform ${platform} has no ${file} (generate it first)`);
    if (mode === 'ros2') {
        const deployment = deploymentContract.parse(await readJson(path.join(dir, file)), `${platform}/${file}`);
        const map = fromDeployment(deployment);
        return { app, platform, mode, ...map, automata: inWorkspace(map.automata, modelRoot) };
    }
    const lockstep = (await readJson(path.join(dir, file))) as { factory?: unknown };
    const module = typeof lockstep.factory === 'string' ? lockstep.factory.split(':')[0] : undefined;
    if (!module || !/^[A-Za-z_][A-Za-z0-9_.]*$/.test(module)) throw new HttpError(409, `${platform}/lockstep.json names no factory module`);
    const source = await readFile(`${path.join(dir, ...module.split('.'))}.py`, 'utf8').catch(() => {
        throw new HttpError(409, `the generated app module ${module} of ${platform} is missing`);
    });
    const map = fromAppModule(source);
    return { app, platform, mode, ...map, automata: inWorkspace(map.automata, modelRoot) };
}
