import type { ComponentView, DataTypeResult } from '@maa/generator-core';
import type { Node } from '../python/expressions.js';
import { renderLines } from '../python/templates.js';
import { type Imports, behaviorTranslator, prologueView, readInputs, type ClassSpec } from './common.js';
import type { ComputeClassView } from './views.js';

/** The view of the behavior class of a component with `compute`/`init` blocks (the host's `compute` language). */
export function computeClassView(
    component: ComponentView,
    datatypes: DataTypeResult | undefined,
    imports: Imports,
    className = `${component.name}Behavior`,
): ComputeClassView {
    const spec: ClassSpec = {
        className,
        timing: 'sync',
        ports: component.ports,
        parameters: component.parameters,
        fields: component.fields,
        datatypes,
    };
    const tr = behaviorTranslator(spec, imports);
    const prologue = prologueView(spec, imports, `Behavior of ${component.qualifiedName}: its compute block (generated).`);
    const init: Node | undefined = component.init;
    const compute: Node | undefined = component.behavior?.language === 'compute' ? component.behavior.node : undefined;
    return {
        prologue,
        init: init ? tr.block(init.body) : undefined,
        step: [...readInputs(spec), ...(compute ? tr.stmt(compute.body) : [])],
    };
}

/** The behavior class of a component with `compute`/`init` blocks, as lines (templates/behavior/compute.njk). */
export function computeClass(
    component: ComponentView,
    datatypes: DataTypeResult | undefined,
    imports: Imports,
    className = `${component.name}Behavior`,
): string[] {
    return renderLines('behavior/compute.njk', computeClassView(component, datatypes, imports, className));
}
