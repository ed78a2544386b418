import type { DataTypeView } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import type { AstNode } from 'langium';
import { isCDMethod, type CDMethod } from '@maa/language-cd';
import { pyName } from './expressions.js';
import type { MethodView } from '../timesync/views.js';

/**
 * The methods a class diagram declares in a class, interface or enum, as Python methods of the
 * generated data type. A class diagram has no method bodies, so each body is a protected region
 * (kept on regeneration) whose generated default raises NotImplementedError naming the method:
 * users write the implementation between the markers. Static methods become `@staticmethod`s.
 * Python has no overloading: two methods of one name in one type are an error.
 */
export function methodViews(t: DataTypeView, annotation: (typeName: string) => string): MethodView[] {
    const methods = t.node.members.filter(isCDMethod);
    const seen = new Map<string, CDMethod>();
    return methods.map((m) => {
        const name = m.name;
        if (seen.has(name)) {
            throw new GenerationError(
                `${t.qualifiedName} declares the method '${name}' twice; Python has no overloading, so the Python generators need distinct method names`,
                m,
            );
        }
        seen.set(name, m);
        const params = m.params.map((p) => ({ name: pyName(p.name), type: typeText(p.type) }));
        const isStatic = m.modifiers.includes('static');
        const returnType = typeText(m.returnType);
        const signature = `${t.qualifiedName}.${name}(${params.map((p) => p.type.replace(/\s+/g, '')).join(',')})`;
        return {
            name: pyName(name),
            isStatic,
            args: [...(isStatic ? [] : ['self']), ...params.map((p) => `${p.name}: ${annotation(p.type)}`)],
            returns: returnType === 'void' ? 'None' : annotation(returnType),
            signature,
            message: `${signature} is declared in the class diagram; implement it between the PROTECTED REGION markers of this file`,
        };
    });
}

function typeText(t: AstNode | undefined): string {
    return t?.$cstNode?.text?.trim() ?? 'Object';
}
