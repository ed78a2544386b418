import type { ComponentView, DataTypeResult } from '@maa/generator-core';
import type { Node } from '../python/expressions.js';
import { Imports, behaviorTranslator, classPrologue, indent, readInputs, type ClassSpec } from './common.js';

/** The behavior class of a component with `compute`/`init` blocks (the host's `compute` language). */
export function computeClass(component: ComponentView, datatypes: DataTypeResult | undefined, imports: Imports, className = `${component.name}Behavior`): string[] {
    const spec: ClassSpec = {
        className,
        timing: 'sync',
        ports: component.ports,
        parameters: component.parameters,
        fields: component.fields,
        datatypes
    };
    const tr = behaviorTranslator(spec, imports);
    const lines = classPrologue(spec, imports, `Behavior of ${component.qualifiedName}: its compute block (generated).`);
    const init = component.init as Node | undefined;
    if (init) {
        lines.push('', '    def init(self) -> None:', ...indent(tr.block(init.body), 8));
    }
    const compute = component.behavior?.language === 'compute' ? component.behavior.node as Node : undefined;
    const step = [...readInputs(spec), ...(compute ? tr.stmt(compute.body) : [])];
    lines.push('', '    def step(self, inputs: Mapping[str, object]) -> None:', ...indent(step.length ? step : ['del inputs'], 8));
    return lines;
}
