import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import type { AstNode } from 'langium';
import { NodeFileSystem } from 'langium/node';
import { afterAll, describe, expect, it } from 'vitest';
import { createMaaServices } from '@maa/language-server';
import { deploymentContract } from '@maa/protocol';
import type { ComponentView, InstanceView } from '@maa/generator-core';
import { GenerationError, generate, type GenerateResult } from '@maa/generator-core/node';
import { deploymentJson, deploymentOf, formatJson } from '../src/ros2/model/deployment.js';
import { PyImports } from '../src/ros2/model/imports.js';
import type { ComponentNode, ModeManagerNode, NodePort, Parameter, Ros2Application } from '../src/ros2/model/model.js';
import { TOPIC_RULES, checkTopicRules } from '../src/ros2/model/topic-rules.js';

const here = path.dirname(fileURLToPath(import.meta.url));

/** A stand-in AST node: the rules and the deployment only pass nodes on. */
const AST = { $type: 'Stub' } as AstNode;

function component(qualifiedName: string): ComponentView {
    // The rules and the deployment read the qualified name and the node only.
    return { qualifiedName, node: AST } as unknown as ComponentView;
}

function port(name: string, topic: string, rosType = 'std_msgs/msg/Int32'): NodePort {
    return { port: name, topic, rosType, helper: 'std_port', codec: 'std_port(Int32, int)', sampled: true, delayed: false, node: AST };
}

function node(
    fqn: string,
    options: {
        inputs?: NodePort[];
        outputs?: NodePort[];
        parameters?: Parameter[];
        publishes?: Array<{ topic: string; type: string }>;
    } = {},
): ComponentNode {
    const name = fqn.split('/').pop()!;
    const namespace = fqn.slice(0, fqn.length - name.length - 1) || '/';
    const c = component(`app.${name}`);
    const instance: InstanceView = { path: [name], component: c, args: [] };
    return {
        kind: 'component',
        instance,
        name,
        namespace,
        fqn,
        module: `app.nodes.${name}`,
        moduleName: name,
        file: `app/app/nodes/${name}.py`,
        instancePath: `robot.${name}`,
        parameters: options.parameters ?? [],
        imports: new PyImports(),
        component: c,
        behavior: { module: 'maa_behavior', cls: 'NoBehavior' },
        inputs: options.inputs ?? [],
        outputs: options.outputs ?? [],
        platform: { subscribes: [], publishes: options.publishes ?? [] },
        gates: [],
    };
}

function manager(fqn: string, relayTarget: string): ModeManagerNode {
    const c = component('app.Modes');
    return {
        kind: 'manager',
        instance: { path: ['m'], component: c, args: [] },
        name: 'maa_modes',
        namespace: fqn.replace(/\/maa_modes$/, ''),
        fqn,
        module: 'app.nodes.m__maa_modes',
        moduleName: 'm__maa_modes',
        file: 'app/app/nodes/m__maa_modes.py',
        instancePath: 'robot.m',
        parameters: [],
        imports: new PyImports(),
        modeTopic: `${fqn}/mode`,
        inputs: [],
        relays: [
            {
                source: '/robot/a/o',
                target: relayTarget,
                rosType: 'std_msgs/msg/Int32',
                helper: 'std_port',
                codec: 'std_port(Int32, int)',
                sampled: true,
                modes: ['On'],
                port: 'o',
            },
        ],
    };
}

function app(nodes: ComponentNode[], managers: ModeManagerNode[] = []): Ros2Application {
    return { pkg: 'app', ifacePkg: 'app_interfaces', rootNs: '/robot', nodes, managers };
}

function violations(a: Ros2Application): string[] {
    return TOPIC_RULES.flatMap((r) => [...r.check(a)].map((v) => `${r.name}: ${v.message}`));
}

describe('ros2 application model: topic rules', () => {
    it('a well-formed application keeps every rule', () => {
        const a = app([
            node('/robot/a', { outputs: [port('o', '/robot/a/o')], inputs: [port('i', '/robot/i')] }),
            node('/robot/b', { inputs: [port('i', '/robot/a/o')] }),
        ]);
        expect(violations(a)).toEqual([]);
        expect(() => checkTopicRules(a)).not.toThrow();
    });

    it("two publishers of a topic (a port and a handwritten PUBLISHES, or a mode manager's relay)", () => {
        const a = app([
            node('/robot/a', { outputs: [port('o', '/robot/a/o')] }),
            node('/robot/s', { publishes: [{ topic: '/robot/a/o', type: 'std_msgs/msg/Int32' }] }),
        ]);
        expect(violations(a)).toEqual([
            'ros2.OnePublisherPerTopic: topic /robot/a/o would have two publishers, /robot/a and /robot/s; a topic has exactly one publisher',
        ]);
        expect(() => checkTopicRules(a)).toThrow(GenerationError);
        const m = app([node('/robot/m/x', { outputs: [port('o', '/robot/m/o')] })], [manager('/robot/m/maa_modes', '/robot/m/o')]);
        expect(violations(m)).toEqual([
            'ros2.OnePublisherPerTopic: topic /robot/m/o would have two publishers, /robot/m/maa_modes and /robot/m/x; a topic has exactly one publisher',
        ]);
    });

    it('two types on a topic', () => {
        const a = app([
            node('/robot/a', { outputs: [port('o', '/robot/a/o')] }),
            node('/robot/b', { inputs: [port('i', '/robot/a/o', 'std_msgs/msg/String')] }),
        ]);
        expect(violations(a)).toEqual([
            'ros2.OneTypePerTopic: topic /robot/a/o would carry two types, std_msgs/msg/Int32 and std_msgs/msg/String',
        ]);
    });

    it('a read topic without a publisher (topics below the root namespace count as fed from outside)', () => {
        const a = app([node('/robot/b', { inputs: [port('i', '/elsewhere/o'), port('j', '/robot/j')] })]);
        expect(violations(a)).toEqual([
            "ros2.ReadTopicsArePublished: in port 'i' of /robot/b reads topic /elsewhere/o, which has no publisher",
        ]);
    });
});

describe('ros2 application model: deployment.json', () => {
    it('formatJson writes what JSON.stringify(value, null, 2) writes', () => {
        const value = { a: 1, b: [1, 'x', { c: null, d: [] }], e: {}, f: true, g: 'q"uote', h: undefined, i: -2.5 };
        expect(formatJson(value, (n) => JSON.stringify(n))).toBe(JSON.stringify(value, null, 2));
    });

    it('serializes the typed model: a float parameter keeps its decimal point, the result is a valid Deployment', () => {
        const parameters: Parameter[] = [
            { name: 'speed', value: 2, float: true },
            { name: 'count', value: 2, float: false },
            { name: 'gain', value: 0.5, float: true },
            { name: 'color', value: 1, enumType: 'Color', float: false },
        ];
        const a = app(
            [node('/robot/a', { outputs: [port('o', '/robot/a/o')], parameters })],
            [manager('/robot/m/maa_modes', '/robot/m/o')],
        );
        const deployment = deploymentOf(a, 'app.Robot');
        expect(deploymentContract.parse(deployment, 'model')).toEqual(deployment);
        const text = deploymentJson(a, deployment);
        expect(text).toContain('"speed": 2.0,\n');
        expect(text).toContain('"count": 2,\n');
        expect(text).toContain('"gain": 0.5,\n');
        expect(JSON.parse(text)).toEqual(deployment);
        expect(deployment.nodes[1]).toMatchObject({
            name: 'maa_modes',
            subscribes: [{ topic: '/robot/a/o', type: 'std_msgs/msg/Int32' }],
            publishes: [
                { topic: '/robot/m/maa_modes/mode', type: 'std_msgs/msg/String' },
                { port: 'o', topic: '/robot/m/o', type: 'std_msgs/msg/Int32' },
            ],
        });
    });

    it('the golden deployment.json is a valid Deployment', () => {
        const text = readFileSync(path.join(here, 'golden-ros2', 'robot', 'deployment.json'), 'utf8');
        expect(() => deploymentContract.parse(JSON.parse(text), 'golden')).not.toThrow();
    });
});

describe('ros2 parameters: constant expressions evaluated on the AST', () => {
    const modelRoot = path.join(here, 'ros2', 'model');
    const temps: string[] = [];
    afterAll(() => {
        for (const d of temps) rmSync(d, { recursive: true, force: true });
    });

    /** The golden model with Robot.arc's instantiations replaced; generated into a fresh folder. */
    async function generateWith(scale: string, unit: string): Promise<{ result: GenerateResult; out: string }> {
        const root = mkdtempSync(path.join(tmpdir(), 'maa-ros2-params-'));
        const out = mkdtempSync(path.join(tmpdir(), 'maa-ros2-params-out-'));
        temps.push(root, out);
        cpSync(modelRoot, root, { recursive: true });
        const robot = path.join(root, 'robot', 'Robot.arc');
        writeFileSync(
            robot,
            readFileSync(robot, 'utf8')
                .replace('Scale scale(3);', `Scale scale(${scale});`)
                .replace('Unit unit(Mode.FAST, 2.5);', `Unit unit(${unit});`),
        );
        const result = await generate({
            services: createMaaServices(NodeFileSystem),
            appFile: path.join(root, 'Golden.arcapp'),
            modelRoot: root,
            outDir: out,
        });
        return { result, out };
    }

    it('arguments written as constant expressions generate the same files as their values', async () => {
        const { result, out } = await generateWith('(7 - 1) / 2', 'true ? Mode.FAST : Mode.SLOW, 5 / 2.0');
        expect(result.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
        for (const f of [
            'robot/deployment.json',
            'robot/launch/golden.launch.py',
            'robot/robot/nodes/scale.py',
            'robot/robot/nodes/unit__ctrl.py',
        ]) {
            expect(readFileSync(path.join(out, 'rospython', f), 'utf8'), f).toBe(readFileSync(path.join(here, 'golden-ros2', f), 'utf8'));
        }
    });

    it('an argument that is not constant is gen/generator-failed on the expression', async () => {
        const { result } = await generateWith('Math.max(1, 2)', 'Mode.FAST, 2.5');
        expect(result.ok).toBe(false);
        const d = result.diagnostics.find((x) => x.code === 'gen/generator-failed');
        expect(d?.message).toContain(
            "ros2.Components needs a constant value here (ROS parameters are static): 'Math.max(1, 2)' is not a constant expression",
        );
    });
});
