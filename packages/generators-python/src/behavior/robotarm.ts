import type { BehaviorGenerator, BehaviorGeneratorFactory, BehaviorView, RuleViolation, WellFormednessRule } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import type { AstNode } from 'langium';
import {
    commandTable,
    isEmbedded,
    isRobotArmBody,
    programSteps,
    programsOf,
    protocolPorts,
    type JointSource,
} from '@maa/language-robotarm';
import { renderLines } from '../python/templates.js';
import { Imports, typeRef, specFrom } from './common.js';
import { behaviorModule, moduleText } from './automata.js';
import { modelFile } from './automata-table.js';

const str = (s: string): string => JSON.stringify(s);

function num(x: number): string {
    const s = String(Number(x.toPrecision(15)));
    return /[.eE]/.test(s) ? s : `${s}.0`;
}

function joint(j: JointSource): string {
    switch (j.kind) {
        case 'fixed':
            return `Fixed(${num(j.si)})`;
        case 'keep':
            return 'Keep()';
        default:
            return `FromPort(${str(j.name)}, ${num(j.toSI)})`;
    }
}

/** A statement's `(line, "source")` tuple for `/maa/program_steps`: its 1-based line and its text on one line. */
function stepSource(node: AstNode): string {
    const cst = node.$cstNode;
    const line = cst ? cst.range.start.line + 1 : 1;
    const text = (cst?.text ?? '').replace(/\s+/g, ' ').trim();
    return `(${line}, ${str(text)})`;
}

/** robotarm.Translatable: the executor needs the embedded protocol (cmd enum, status enum). */
export const robotArmRule: WellFormednessRule = {
    name: 'robotarm.Translatable',
    description: 'robot arms translated by the Python generators are embedded in a component with the cmd/status protocol',
    *check(scope): Iterable<RuleViolation> {
        for (const b of scope.behaviors) {
            if (b.language !== 'robotarm') continue;
            const body = b.node;
            if (!isRobotArmBody(body) || !isEmbedded(body)) {
                yield { node: b.node, message: 'the Python generators translate only robot arms embedded in a component' };
                continue;
            }
            const { cmd, status } = protocolPorts(body);
            if (!cmd || !status)
                yield { node: b.node, message: 'the Python generators need the cmd and status ports of the RobotArm protocol' };
        }
    },
};

/** The behavior generator; its import lines wrap at `lineLength` (see Imports). */
export function robotArmGenerator(lineLength?: number): BehaviorGenerator {
    return {
        kind: 'behavior',
        rules: [robotArmRule],
        generate(behavior: BehaviorView, ctx) {
            const component = ctx.component;
            if (!component) throw new GenerationError('the RobotArm generator needs the component (requires: component)', behavior.node);
            const body = behavior.node;
            if (!isRobotArmBody(body) || !isEmbedded(body))
                throw new GenerationError('only embedded robot arms can be translated', behavior.node);
            const spec = specFrom(ctx, component, 'sync');
            const imports = new Imports(lineLength);
            imports.add('maa_behavior.robotarm', 'RobotArmExecutor');
            imports.add('typing', 'ClassVar');
            imports.add('collections.abc', 'Mapping');
            const statusPort = spec.ports.find((p) => p.name === 'status');
            const statusDecl = statusPort?.type.kind === 'object' ? statusPort.type.decl : undefined;
            const statusType = statusDecl ? typeRef(ctx.datatypes, imports, statusDecl) : 'None';
            const programs: Array<{ name: string; steps: string[]; sources: string[] }> = [];
            let stepKinds = new Set<string>();
            for (const p of programsOf(body)) {
                const sources = programSteps(p).map((s) => stepSource(s.node));
                const steps = programSteps(p).map((s) => {
                    if (s.kind !== 'move') {
                        stepKinds.add('Gripper');
                        return `Gripper(close=${s.kind === 'close' ? 'True' : 'False'})`;
                    }
                    stepKinds.add('Move');
                    for (const j of [s.angle, s.height])
                        stepKinds.add(j.kind === 'fixed' ? 'Fixed' : j.kind === 'keep' ? 'Keep' : 'FromPort');
                    return `Move(${joint(s.angle)}, ${joint(s.height)}${s.target ? `, ${str(s.target.name)}` : ''})`;
                });
                programs.push({ name: p.name, steps, sources });
            }
            stepKinds = new Set([...stepKinds].sort());
            for (const k of stepKinds) imports.add('maa_behavior.robotarm', k);
            imports.add('maa_behavior.robotarm', 'Step');
            const commands = commandTable(body).flatMap((c) => (c.program ? [{ constant: c.constant, program: c.program.name }] : []));
            const outs = spec.ports.filter((p) => p.direction === 'out');
            const cls = renderLines('behavior/robotarm.njk', {
                className: spec.className,
                qualifiedName: component.qualifiedName,
                file: modelFile(body, component.packageName),
                inPorts: spec.ports.filter((p) => p.direction === 'in').map((p) => p.name),
                outPorts: outs.map((p) => p.name),
                delayed: outs.filter((p) => p.delayed).map((p) => p.name),
                statusType,
                programs,
                commands,
            });
            const { module, file } = behaviorModule(component.packageName, component.name);
            const out = ctx.out.file(file);
            out.traced(behavior.node, () =>
                out.write(
                    moduleText(
                        `Behavior of ${component.qualifiedName}: its robot arm (generated by the Python RobotArm generator).`,
                        imports,
                        cls,
                    ),
                ),
            );
            return { module, class: spec.className, timing: 'sync' };
        },
    };
}

const create: BehaviorGeneratorFactory = () => robotArmGenerator();

export default create;
