import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { translatableRule } from '../src/behavior/automata.js';
import { packageDir } from './python-env.js';

// Generator rules of the Python generators: what they cannot translate is reported on the model
// element, and nothing is generated.
const roots: string[] = [];
afterAll(() => {
    for (const r of roots) rmSync(r, { recursive: true, force: true });
});

async function generateModel(
    arc: string,
): Promise<{ ok: boolean; diagnostics: Array<{ code?: string; message: string; severity: string }> }> {
    const root = mkdtempSync(path.join(tmpdir(), 'maa-py-rules-'));
    roots.push(root);
    mkdirSync(path.join(root, 'p'));
    writeFileSync(path.join(root, 'p', 'C.arc'), arc);
    writeFileSync(
        path.join(root, 'A.arcapp'),
        'application A for p.C {\n  platform timesync {\n    timesync.Components;\n    timesync.AutomataBehavior;\n    timesync.RobotArmBehavior;\n    timesync.DataTypes;\n  }\n}\n',
    );
    const { createMaaServices } = await import('@maa/language-server');
    const { generate } = await import('@maa/generator-core/node');
    const { NodeFileSystem } = await import('langium/node');
    const result = await generate({
        services: createMaaServices(NodeFileSystem),
        appFile: path.join(root, 'A.arcapp'),
        outDir: path.join(root, 'out'),
        discoveryRoots: [packageDir],
    });
    return {
        ok: result.ok,
        diagnostics: result.diagnostics.map((d) => ({ code: d.code, message: d.message, severity: String(d.severity) })),
    };
}

describe('generator rules of the timesync family', () => {
    it('a <<sync>> automaton with an event is not generated', async () => {
        // The automata language reports it itself (automaton/event-in-sync) before the generator's rule.
        const r = await generateModel(
            'package p;\ncomponent C {\n  port in int i, out int o;\n  <<sync>> automaton {\n    initial state A;\n    A -> A i / { o = 1; };\n  }\n}\n',
        );
        expect(r.ok).toBe(false);
        const found = r.diagnostics.find((d) => d.code === 'app/generator-rule-violated' || d.code === 'automaton/event-in-sync');
        expect(found, JSON.stringify(r.diagnostics)).toBeDefined();
    }, 60_000);

    it('automata.Translatable rejects an automaton without states', () => {
        const automaton = { $type: 'Automaton', elements: [] as unknown[], $container: { $type: 'BehaviorDeclaration' } };
        const scope = { behaviors: [{ language: 'automaton', node: automaton, component: 'p.C' }] } as unknown as Parameters<
            typeof translatableRule.check
        >[0];
        const violations = [...translatableRule.check(scope)];
        expect(violations.map((v) => v.message)).toEqual(['the Python generators cannot translate an automaton without states']);
    });

    it('an assignment inside an expression stops generation on the expression', async () => {
        const r = await generateModel(
            'package p;\ncomponent C {\n  port <<sync>> in int i, <<sync>> out int o;\n  int n = 0;\n  compute {\n    o = n++;\n  }\n}\n',
        );
        expect(r.ok).toBe(false);
        const found = r.diagnostics.find((d) => d.code === 'gen/generator-failed');
        expect(found?.message, JSON.stringify(r.diagnostics)).toContain('assignment inside an expression');
    }, 60_000);

    it('a well-formed model generates', async () => {
        const r = await generateModel(
            'package p;\ncomponent C {\n  port <<sync>> in int i, <<sync>> out int o;\n  compute {\n    o = i / 2;\n  }\n}\n',
        );
        expect(r.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
        expect(r.ok).toBe(true);
    }, 60_000);
});
