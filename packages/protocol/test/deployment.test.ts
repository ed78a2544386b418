import { readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { deploymentContract, DEPLOYMENT_FILE_NAME } from '../dist/index.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');

function find(dir: string, name: string, out: string[] = []): string[] {
    for (const e of readdirSync(dir)) {
        const abs = path.join(dir, e);
        if (statSync(abs).isDirectory()) find(abs, name, out);
        else if (e === name) out.push(abs);
    }
    return out;
}

describe('deployment.json contract', () => {
    // What the ros2-python generator really writes (its golden files, compared byte for byte by its tests).
    const generated = find(path.join(repo, 'packages/generators-python/test'), DEPLOYMENT_FILE_NAME);

    test('every generated deployment.json keeps the contract', () => {
        expect(generated.length).toBeGreaterThan(0);
        for (const f of generated) expect(deploymentContract.issues(JSON.parse(readFileSync(f, 'utf8'))), f).toEqual([]);
    });

    const valid = {
        format: 'maa-deployment/1',
        nodes: [{ name: 'ctrl', namespace: '/toast', module: 'toast.ctrl', parameters: { threshold: 25, names: ['a'] } }],
    };

    test('a minimal deployment is valid', () => {
        expect(deploymentContract.check(valid)).toBe(true);
    });

    test.each([
        ['wrong format', { ...valid, format: 'maa-deployment/2' }, '/format'],
        ['no nodes', { ...valid, nodes: [] }, '/nodes'],
        ['bad node name', { ...valid, nodes: [{ name: '1ctrl', module: 'm' }] }, '/nodes/0'],
        ['module and executable', { ...valid, nodes: [{ name: 'n', module: 'm', executable: 'x' }] }, '/nodes/0'],
        ['neither module nor executable', { ...valid, nodes: [{ name: 'n' }] }, '/nodes/0'],
        [
            'relative topic',
            { ...valid, nodes: [{ name: 'n', module: 'm', publishes: [{ topic: 'a/b', type: 'std_msgs/msg/Int32' }] }] },
            '/nodes/0',
        ],
        ['use_sim_time parameter', { ...valid, nodes: [{ name: 'n', module: 'm', parameters: { use_sim_time: true } }] }, '/nodes/0'],
        ['mixed parameter list', { ...valid, nodes: [{ name: 'n', module: 'm', parameters: { p: [1, 'a'] } }] }, '/nodes/0'],
        ['reserved env', { ...valid, env: { ROS_DOMAIN_ID: '3' } }, '/env'],
    ])('%s is refused at %s', (_what, value, pointer) => {
        const issues = deploymentContract.issues(value);
        expect(issues.map((i) => i.pointer)).toContain(pointer);
        expect(() => deploymentContract.parse(value, 'x/deployment.json')).toThrow(/^x\/deployment\.json: not a valid deployment: /);
    });
});
