import { GenerationError } from '@maa/generator-core/node';
import { ConstantEvaluationError, ast, constantEnv, evaluateConstant, type ConstantValue } from '@maa/language-adl';
import type { ArchitectureModel, ComponentView, InstanceView, ParameterView } from '@maa/generator-core';
import type { AstNode } from 'langium';
import { primitiveOf, typeKey, type RosDataTypeResult } from '../naming.js';
import type { PyImports } from './imports.js';
import type { Parameter } from './model.js';

/**
 * The parameter values of every instance (ROS parameters are static): its arguments
 * (positional, then `key = value`), else the defaults, evaluated as constants on the AST;
 * arguments may name the enclosing instance's parameters, defaults the earlier parameters.
 */
export function instanceParameters(arch: ArchitectureModel): Map<InstanceView, Map<string, ConstantValue>> {
    const values = new Map<InstanceView, Map<string, ConstantValue>>();
    const byPath = new Map(arch.instances.map((i) => [i.path.join('.'), i]));
    for (const inst of arch.instances) {
        const parent = inst.path.length > 0 ? byPath.get(inst.path.slice(0, -1).join('.')) : undefined;
        values.set(inst, parametersOf(inst, (parent && values.get(parent)) ?? new Map()));
    }
    return values;
}

function parametersOf(inst: InstanceView, outer: ReadonlyMap<string, ConstantValue>): Map<string, ConstantValue> {
    const c = inst.component;
    const given = argumentsByName(inst);
    const values = new Map<string, ConstantValue>();
    for (const p of c.parameters) {
        const arg = given.get(p.name);
        const expr = arg ?? p.default;
        if (!expr) throw new GenerationError(`parameter '${p.name}' of ${c.qualifiedName} has no value`, inst.node ?? p.node);
        values.set(p.name, constant(expr, p, arg ? outer : values));
    }
    return values;
}

/** The arguments of an instantiation by parameter name. */
function argumentsByName(inst: InstanceView): Map<string, ast.Expression> {
    const given = new Map<string, ast.Expression>();
    inst.args.forEach((arg, i) => {
        if (ast.isAssignmentExpression(arg) && arg.op === '=')
            given.set(ast.isNameExpression(arg.left) ? arg.left.ref.$refText : (arg.left.$cstNode?.text ?? ''), arg.right);
        else if (inst.component.parameters[i] && ast.isExpression(arg)) given.set(inst.component.parameters[i]!.name, arg);
    });
    return given;
}

function constant(expr: AstNode, p: ParameterView, env: ReadonlyMap<string, ConstantValue>): ConstantValue {
    if (!ast.isExpression(expr)) throw new GenerationError('ros2.Components needs an expression here', expr);
    try {
        return evaluateConstant(expr, constantEnv(env), p.type);
    } catch (e) {
        if (e instanceof ConstantEvaluationError) {
            throw new GenerationError(`ros2.Components needs a constant value here (ROS parameters are static): ${e.message}`, e.node);
        }
        throw e;
    }
}

/** A ROS parameter of a node or mode manager: its value (an enum's by ordinal) and the enum type to convert it back to. */
export function rosParameter(
    p: ComponentView['parameters'][number],
    value: ConstantValue,
    dt: RosDataTypeResult,
    imports: PyImports,
): Parameter {
    const enumType = p.type.kind === 'object' && !primitiveOf(p.type) ? dt.types?.[typeKey(p.type)] : undefined;
    const local = enumType?.module && enumType.name ? imports.use(enumType.module, enumType.name) : enumType?.name;
    return {
        name: p.name,
        value: value.kind === 'enum' ? value.ordinal : value.value,
        enumType: local,
        float: primitiveOf(p.type)?.py === 'float',
    };
}
