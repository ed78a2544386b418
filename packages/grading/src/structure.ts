/**
 * The structure criterion, checked on the symbols: each required component exists, has the
 * ports (direction, type), the subcomponents and the behavior kind (automaton size, named states)
 * the specification asks for. The score is the share of these checks met.
 */
import type { ComponentView, PortView } from '@maa/generator-core';
import type { CriterionGrade, Feedback, StructureCriterion, StructureRequirement } from '@maa/protocol/grading';
import { automatonFacts, behaviorKind, componentView } from './component.js';
import { criterionGrade, plural } from './feedback.js';
import { elementOf, type SubmissionModel, where } from './model.js';

/** One check of a requirement: met, or the feedback saying why not. */
type Check = { met: true } | { met: false; feedback: Feedback };

/** How many checks a requirement has (a missing component fails them all). */
export function checkCount(requirement: StructureRequirement): number {
    const behavior = requirement.behavior;
    const behaviorChecks = behavior
        ? 1 + (behavior.minStates !== undefined ? 1 : 0) + (behavior.minTransitions !== undefined ? 1 : 0) + (behavior.states?.length ?? 0)
        : 0;
    return 1 + (requirement.ports?.length ?? 0) + (requirement.subcomponents?.length ?? 0) + behaviorChecks;
}

export function gradeStructure(criterion: StructureCriterion, model: SubmissionModel): CriterionGrade {
    let total = 0;
    let met = 0;
    const feedback: Feedback[] = [];
    for (const requirement of criterion.require) {
        const checks = checkRequirement(requirement, model);
        total += checkCount(requirement);
        met += checks.filter((c) => c.met).length;
        for (const c of checks) if (!c.met) feedback.push(c.feedback);
    }
    if (feedback.length === 0) feedback.push({ severity: 'info', text: `All ${plural(total, 'structure check')} met.` });
    return criterionGrade(criterion, total === 0 ? 1 : met / total, feedback);
}

function checkRequirement(requirement: StructureRequirement, model: SubmissionModel): Check[] {
    const node = model.components.get(requirement.component);
    if (!node) {
        const name = requirement.component.slice(requirement.component.lastIndexOf('.') + 1);
        const elsewhere = [...model.components.keys()].filter((q) => q.endsWith(`.${name}`) || q === name);
        const hint = elsewhere.length > 0 ? ` (there is ${elsewhere.join(', ')}: check its package)` : '';
        return [{ met: false, feedback: { severity: 'error', text: `There is no component ${requirement.component}${hint}.` } }];
    }
    const view = componentView(node);
    const here = elementOf(model, node, view.qualifiedName);
    return [
        { met: true },
        ...(requirement.ports ?? []).map((p) => checkPort(p, view, model)),
        ...(requirement.subcomponents ?? []).map((s) => checkSubcomponent(s, view, model)),
        ...(requirement.behavior ? checkBehavior(requirement.behavior, view, here) : []),
    ];
}

type PortRequirement = NonNullable<StructureRequirement['ports']>[number];
type SubcomponentRequirement = NonNullable<StructureRequirement['subcomponents']>[number];
type BehaviorRequirement = NonNullable<StructureRequirement['behavior']>;

/** Whether a port's type is the required one: as written (`int`, `ToastColor`) or qualified (`toast.types.Types.ToastColor`). */
export function typeMatches(port: Pick<PortView, 'typeName' | 'qualifiedTypeName'>, required: string): boolean {
    const want = required.replace(/\s+/g, '');
    return port.typeName === want || port.qualifiedTypeName === want || port.qualifiedTypeName.endsWith(`.${want}`);
}

function checkPort(required: PortRequirement, view: ComponentView, model: SubmissionModel): Check {
    const port = view.ports.find((p) => p.name === required.name);
    const owner = elementOf(model, view.node, view.qualifiedName);
    const expected = [required.direction, required.type, required.name].filter(Boolean).join(' ');
    if (!port)
        return {
            met: false,
            feedback: {
                severity: 'error',
                text: `${view.name} has no port ${required.name} (expected: port ${expected}) (${where(owner)}).`,
                element: owner,
            },
        };
    const element = elementOf(model, port.node, `${view.qualifiedName}.${port.name}`);
    if (required.direction && port.direction !== required.direction)
        return {
            met: false,
            feedback: {
                severity: 'error',
                text: `Port ${port.name} of ${view.name} is an ${port.direction} port; it must be an ${required.direction} port (${where(element)}).`,
                element,
            },
        };
    if (required.type && !typeMatches(port, required.type))
        return {
            met: false,
            feedback: {
                severity: 'error',
                text: `Port ${port.name} of ${view.name} has type ${port.typeName}; it must have type ${required.type} (${where(element)}).`,
                element,
            },
        };
    return { met: true };
}

function checkSubcomponent(required: SubcomponentRequirement, view: ComponentView, model: SubmissionModel): Check {
    const typeOk = (type: string) => !required.type || type === required.type || type.endsWith(`.${required.type}`);
    const named = required.name ? view.subcomponents.find((s) => s.name === required.name) : undefined;
    const owner = elementOf(model, view.node, view.qualifiedName);
    if (required.name && !named) {
        const what = required.type ? `${required.type} ${required.name}` : required.name;
        return {
            met: false,
            feedback: { severity: 'error', text: `${view.name} has no subcomponent ${what} (${where(owner)}).`, element: owner },
        };
    }
    if (named && !typeOk(named.type)) {
        const element = elementOf(model, named.node, `${view.qualifiedName}.${named.name}`);
        return {
            met: false,
            feedback: {
                severity: 'error',
                text: `Subcomponent ${named.name} of ${view.name} is a ${named.type}; it must be a ${required.type} (${where(element)}).`,
                element,
            },
        };
    }
    if (!named && !view.subcomponents.some((s) => typeOk(s.type)))
        return {
            met: false,
            feedback: {
                severity: 'error',
                text: `${view.name} has no subcomponent of type ${required.type} (${where(owner)}).`,
                element: owner,
            },
        };
    return { met: true };
}

const KIND_WORDS: Record<string, string> = {
    automaton: 'an automaton',
    robotarm: 'a RobotArm program',
    compute: 'a compute block',
    handwritten: 'handwritten code (<<handwritten>>)',
    composed: 'composed of subcomponents',
    none: 'without behavior',
};

function checkBehavior(required: BehaviorRequirement, view: ComponentView, element: ReturnType<typeof elementOf>): Check[] {
    const kind = behaviorKind(view);
    const checks: Check[] = [];
    const fail = (text: string): Check => ({ met: false, feedback: { severity: 'error', text: `${text} (${where(element)}).`, element } });
    checks.push(
        kind === required.kind ? { met: true } : fail(`${view.name} must be ${KIND_WORDS[required.kind]}; it is ${KIND_WORDS[kind]}`),
    );
    const facts = automatonFacts(view);
    const states = facts?.states.length ?? 0;
    const transitions = facts?.transitions.length ?? 0;
    if (required.minStates !== undefined)
        checks.push(
            states >= required.minStates
                ? { met: true }
                : fail(`The automaton of ${view.name} has ${plural(states, 'state')}; it needs at least ${required.minStates}`),
        );
    if (required.minTransitions !== undefined)
        checks.push(
            transitions >= required.minTransitions
                ? { met: true }
                : fail(
                      `The automaton of ${view.name} has ${plural(transitions, 'transition')}; it needs at least ${required.minTransitions}`,
                  ),
        );
    for (const name of required.states ?? []) {
        const found = facts?.states.some((s) => s.path === name || s.path.endsWith(`.${name}`));
        checks.push(found ? { met: true } : fail(`The automaton of ${view.name} has no state ${name}`));
    }
    return checks;
}
