import type { DataTypeView } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import { pyName, type Node } from './expressions.js';

/**
 * The methods a class diagram declares in a class, interface or enum, as Python methods of the
 * generated data type. A class diagram has no method bodies, so each body is a protected region
 * (kept on regeneration) whose generated default raises NotImplementedError naming the method:
 * users write the implementation between the markers. Static methods become `@staticmethod`s.
 * Python has no overloading: two methods of one name in one type are an error.
 */
export function methodStubs(t: DataTypeView, annotation: (typeName: string) => string): string[] {
    const methods = ((t.node as unknown as Node).members as Node[] | undefined ?? []).filter((m) => m.$type === 'CDMethod');
    const seen = new Map<string, Node>();
    const lines: string[] = [];
    for (const m of methods) {
        const name = String(m.name);
        if (seen.has(name)) {
            throw new GenerationError(`${t.qualifiedName} declares the method '${name}' twice; Python has no overloading, so the Python generators need distinct method names`, m);
        }
        seen.set(name, m);
        const params = (m.params as Node[]).map((p) => ({ name: pyName(String(p.name)), type: typeText(p.type as Node) }));
        const isStatic = (m.modifiers as string[]).includes('static');
        const returnType = typeText(m.returnType as Node);
        const signature = `${t.qualifiedName}.${name}(${params.map((p) => p.type.replace(/\s+/g, '')).join(',')})`;
        const args = [...(isStatic ? [] : ['self']), ...params.map((p) => `${p.name}: ${annotation(p.type)}`)];
        const ret = returnType === 'void' ? 'None' : annotation(returnType);
        lines.push('');
        if (isStatic) lines.push('    @staticmethod');
        lines.push(
            `    def ${pyName(name)}(${args.join(', ')}) -> ${ret}:`,
            `        # PROTECTED REGION BEGIN ${signature}`,
            `        raise NotImplementedError(${JSON.stringify(`${signature} is declared in the class diagram; implement it between the PROTECTED REGION markers of this file`)})`,
            `        # PROTECTED REGION END ${signature}`
        );
    }
    return lines;
}

function typeText(t: Node | undefined): string {
    return t?.$cstNode?.text?.trim() ?? 'Object';
}
