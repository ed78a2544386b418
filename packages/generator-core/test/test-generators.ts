import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { NodeFileSystem } from 'langium/node';
import type { AstNode } from 'langium';
import {
    GeneratorRegistry,
    snakeCase,
    sourceText,
    type BehaviorGenerator,
    type ComponentGenerator,
    type DataTypeGenerator,
    type GeneratorInstantiation,
} from '../src/index.js';
import { generate, type GenerateOptions, type GenerateResult } from '../src/node.js';
import { createTestFamily } from './helpers.js';
import { STATE_DIR } from '../src/output/layout.js';

/**
 * Small in-test generators (the real ones come with the Python generator families) and a
 * model root for orchestrator tests: a composed Robot with a handwritten Sensor, a Filter with
 * a compute block and a Ctrl automaton; data types from a class diagram.
 */
export const MODELS: Record<string, string> = {
    'robot/Robot.arc': [
        'package robot;',
        '',
        'component Robot {',
        '  Sensor sensor;',
        '  Ctrl ctrl;',
        '  Filter filter;',
        '',
        '  sensor.value -> filter.raw;',
        '  filter.smooth -> ctrl.distance;',
        '}',
        '',
    ].join('\n'),
    'robot/Sensor.arc': 'package robot;\n\n<<handwritten>> component Sensor {\n  port out int value;\n}\n',
    'robot/Filter.arc': [
        'package robot;',
        '',
        'component Filter {',
        '  port in int raw;',
        '  port out int smooth;',
        '',
        '  compute {',
        '    smooth = raw / 2;',
        '  }',
        '}',
        '',
    ].join('\n'),
    'robot/Ctrl.arc': [
        'package robot;',
        '',
        'import robot.types.*;',
        '',
        'component Ctrl {',
        '  port in int distance;',
        '  port out Mode mode;',
        '',
        '  automaton {',
        '    initial { mode = Mode.IDLE; } state Idle;',
        '    state Busy;',
        '    Idle -> Busy [distance < 10] / { mode = Mode.BUSY; };',
        '    Busy -> Idle [distance >= 10] / { mode = Mode.IDLE; };',
        '  }',
        '}',
        '',
    ].join('\n'),
    'robot/types/Types.cd': 'package robot.types;\n\nclassdiagram Types {\n  enum Mode { IDLE, BUSY; }\n}\n',
    'App.arcapp': [
        'application Demo for robot.Robot {',
        '  platform alpha {',
        '    t.Components;',
        '    t.Automata;',
        '    t.DataTypes;',
        '  }',
        '  platform beta {',
        '    t.Components;',
        '    t.Automata;',
        '    t.DataTypes;',
        '  }',
        '}',
        '',
    ].join('\n'),
};

export const MANIFESTS = [
    {
        name: 't.Components',
        kind: 'component',
        supports: ['compute'],
        output: { gpl: 'python', rte: 't-rte' },
        entry: 'components.js',
        templates: 'templates',
    },
    {
        name: 't.Automata',
        kind: 'behavior',
        language: 'automaton',
        output: { gpl: 'python', rte: 't-rte' },
        entry: 'automata.js',
        requires: ['ports', 'package'],
    },
    { name: 't.DataTypes', kind: 'datatype', output: { gpl: 'python' }, entry: 'datatypes.js' },
];

export const TEMPLATES: Record<string, string> = {
    'component.py.njk': [
        '# {{ c.qualifiedName }}',
        'class {{ c.name | pascal_case }}:',
        '{% for p in c.ports %}',
        '{% trace p %}',
        '    {{ p.name | snake_case }}: {{ p.typeName | py_str }}  # {{ p.direction }}',
        '{% endtrace %}',
        '{% endfor %}',
        '',
    ].join('\n'),
};

/** What the generators did, in order. */
export interface Recorder {
    log: string[];
    /** Keys of the context each behavior generator call got. */
    contexts: Array<{ component: string; keys: string[] }>;
    /** Options that change the generators' behavior between runs. */
    failIn?: 'datatypes' | 'components' | 'automata';
    /** Produce fewer files (to test stale-file removal). */
    fewer?: boolean;
    /** Write this path from the component generator (to test output path checks). */
    badPath?: string;
}

export function createGenerators(rec: Recorder): Record<string, (i: GeneratorInstantiation) => unknown> {
    const datatypes = (): DataTypeGenerator => ({
        kind: 'datatype',
        generate(ctx) {
            rec.log.push('datatypes');
            if (rec.failIn === 'datatypes') throw new Error('datatypes exploded');
            const f = ctx.out.file('types.py');
            f.line(`# data types of ${ctx.platform.application} for ${ctx.platform.platform}`);
            const types: Record<string, Record<string, string>> = {};
            for (const t of ctx.dataTypes) {
                f.traced(t.node, () => {
                    f.line(`class ${t.name}:`);
                    for (const c of t.constants) f.line(`    ${c} = ${JSON.stringify(c)}`);
                });
                types[t.qualifiedName] = { module: 'types', name: t.name };
            }
            return { types };
        },
    });
    const automata = (): BehaviorGenerator => ({
        kind: 'behavior',
        generate(behavior, ctx) {
            rec.log.push(`automata:${behavior.component}:${behavior.language}`);
            rec.contexts.push({ component: behavior.component, keys: Object.keys(ctx).sort() });
            if (rec.failIn === 'automata') throw new Error('automata exploded');
            const name = `${snakeCase(behavior.component.split('.').pop()!)}_automaton.py`;
            const f = ctx.out.file(`behaviors/${name}`);
            f.line(`# automaton of ${behavior.component} in package ${ctx.packageName}`);
            f.line(`PORTS = ${JSON.stringify(ctx.ports?.map((p) => p.name))}`);
            for (const s of (behavior.node as AstNode & { elements: Array<AstNode & { name?: string }> }).elements) {
                if (s.$type === 'State') f.line(`STATE_${s.name} = ${JSON.stringify(s.name)}`, s);
            }
            return { module: `behaviors.${name.replace(/\.py$/, '')}` };
        },
    });
    const components = (i: GeneratorInstantiation): ComponentGenerator => ({
        kind: 'component',
        async generate(ctx) {
            rec.log.push(`components:start:${Object.keys(ctx.datatypes.types ?? {}).join(',')}`);
            if (rec.failIn === 'components') throw new Error('components exploded');
            if (rec.badPath) ctx.out.file(rec.badPath).line('x');
            const shown = rec.fewer ? ctx.architecture.components.slice(0, 2) : ctx.architecture.components;
            for (const c of shown) {
                const f = ctx.out.file(`components/${snakeCase(c.name)}.py`);
                f.render('component.py.njk', { c }, c.node);
                const delegated = await ctx.behavior(c);
                if (delegated?.handledBy === 'behavior-generator') {
                    rec.log.push(`components:${c.qualifiedName}:delegated:${delegated.generator}`);
                    f.line(`BEHAVIOR = ${JSON.stringify(delegated.result['module'])}`);
                } else if (delegated?.handledBy === 'component-generator') {
                    rec.log.push(`components:${c.qualifiedName}:own:${delegated.language}`);
                    f.line(`def step(self):  # ${sourceText(delegated.behavior.node).replace(/\s+/g, ' ')}`, delegated.behavior.node);
                    f.line('    pass');
                } else {
                    rec.log.push(`components:${c.qualifiedName}:none`);
                }
                f.line('# PROTECTED REGION BEGIN extra');
                f.line('# your code here');
                f.line('# PROTECTED REGION END extra');
                if (c.handwritten) {
                    ctx.out
                        .file(`user/${snakeCase(c.name)}_impl.py`, { userFile: true })
                        .line(`# implement ${c.name} here (generated once)`);
                }
            }
            rec.log.push(`components:end:${i.manifest.name}`);
        },
    });
    return { 'components.js': components, 'automata.js': automata, 'datatypes.js': datatypes };
}

/** A model root and a generator package folder in a fresh temporary folder. */
export class Workspace {
    readonly dir = mkdtempSync(path.join(tmpdir(), 'maa-generate-'));
    readonly models = path.join(this.dir, 'models');
    readonly gens = path.join(this.dir, 'gens');
    readonly rec: Recorder = { log: [], contexts: [] };

    constructor(files: Record<string, string> = MODELS, manifests: unknown[] = MANIFESTS) {
        for (const [rel, text] of Object.entries(files)) this.write(path.join('models', rel), text);
        for (const [rel, text] of Object.entries(TEMPLATES)) this.write(path.join('gens', 'templates', rel), text);
        this.manifests = manifests;
    }

    manifests: unknown[];

    write(rel: string, text: string): void {
        const file = path.join(this.dir, rel);
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, text);
    }

    registry(): GeneratorRegistry {
        return GeneratorRegistry.fromManifests(this.manifests, 'test-gens', this.gens);
    }

    async generate(options: Partial<GenerateOptions> = {}, modules = createGenerators(this.rec)): Promise<GenerateResult> {
        return generate({
            services: createTestFamily(NodeFileSystem),
            appFile: path.join(this.models, 'App.arcapp'),
            outDir: path.join(this.dir, 'out'),
            registry: this.registry(),
            loadModule: async (url) => {
                const base = url.substring(url.lastIndexOf('/') + 1);
                if (!(base in modules)) throw new Error(`no test module ${base}`);
                return { default: modules[base] };
            },
            ...options,
        });
    }

    out(rel = ''): string {
        return path.join(this.dir, 'out', rel);
    }

    dispose(): void {
        rmSync(this.dir, { recursive: true, force: true });
    }
}

/**
 * Every file below a folder with its content (and folders as entries), for before/after
 * comparisons. Platform links are followed; the writer's hidden version folders (`.maa-gen`,
 * whose names differ per generation) are left out: what a reader sees is compared.
 */
export function snapshot(dir: string): Record<string, string> {
    const out: Record<string, string> = {};
    const walk = (d: string): void => {
        let entries: string[];
        try {
            entries = readdirSync(d).sort();
        } catch {
            return;
        }
        for (const e of entries) {
            if (e === STATE_DIR) continue;
            const p = path.join(d, e);
            const rel = path.relative(dir, p);
            if (statSync(p).isDirectory()) {
                out[`${rel}/`] = '';
                walk(p);
            } else {
                out[rel] = readFileSync(p, 'utf8');
            }
        }
    };
    walk(dir);
    return out;
}
