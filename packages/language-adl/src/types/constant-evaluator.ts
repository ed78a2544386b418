import { AstUtils, type AstNode } from 'langium';
import { isCDEnum, type BinaryExpression, type CDEnum, type Expression, type PrefixExpression } from '../generated/ast.js';
import type { SymType } from './sym-type.js';

/**
 * Constant evaluation on the AST: the value of an expression that needs no running system, such
 * as a parameter default or an argument of an instantiation (`new Robot(2 * speed, Color.RED)`).
 * Literals, names of values the caller knows (the enclosing instance's parameters), constants of
 * the expected enum type, and the arithmetic, comparison, logical and conditional operators over
 * them evaluate; anything else (a call, a field of an object, a variable) is not a constant.
 */

/** The value of a constant expression, with its kind (integral and floating-point numbers differ in Java). */
export type ConstantValue =
    | { readonly kind: 'boolean'; readonly value: boolean }
    /** byte, short, int, long */
    | { readonly kind: 'int'; readonly value: number }
    /** float, double */
    | { readonly kind: 'float'; readonly value: number }
    | { readonly kind: 'char'; readonly value: string }
    | { readonly kind: 'string'; readonly value: string }
    /** A constant of an enum of a class diagram, with its ordinal. */
    | { readonly kind: 'enum'; readonly value: string; readonly ordinal: number; readonly decl: CDEnum };

/** An expression that is not constant; `node` is where. */
export class ConstantEvaluationError extends Error {
    constructor(
        message: string,
        readonly node: AstNode,
    ) {
        super(message);
        this.name = 'ConstantEvaluationError';
    }
}

/** What an expression may refer to. */
export interface ConstantEnv {
    /** The value of a name (e.g. a parameter of the enclosing instance), if it has one. */
    lookup(name: string): ConstantValue | undefined;
}

export const EMPTY_CONSTANT_ENV: ConstantEnv = { lookup: () => undefined };

/** A constant environment of the given values. */
export function constantEnv(values: ReadonlyMap<string, ConstantValue>): ConstantEnv {
    return { lookup: (name) => values.get(name) };
}

/**
 * The value of `expr`; `expected` is the type the value is for (an enum constant may be written
 * `RED` or `Color.RED` when an enum is expected). Throws a ConstantEvaluationError when the
 * expression is not constant.
 */
export function evaluateConstant(expr: Expression, env: ConstantEnv, expected?: SymType): ConstantValue {
    switch (expr.$type) {
        case 'BooleanLiteral':
            return { kind: 'boolean', value: expr.value === 'true' };
        case 'IntLiteral':
            return { kind: 'int', value: Number(expr.value) };
        case 'LongLiteral':
            return { kind: 'int', value: Number(String(expr.value).replace(/[lL]$/, '')) };
        case 'FloatLiteral':
            return { kind: 'float', value: Number(String(expr.value).replace(/[fFdD]$/, '')) };
        case 'CharLiteral':
            return { kind: 'char', value: unquote(String(expr.value), "'", expr) };
        case 'StringLiteral':
            return { kind: 'string', value: unquote(String(expr.value), '"', expr) };
        case 'NameExpression':
            return env.lookup(expr.ref.$refText) ?? enumConstant(expected, expr.ref.$refText, expr);
        case 'FieldAccessExpression':
            return enumConstant(expected, String(expr.member), expr);
        case 'PrefixExpression':
            return prefix(expr, evaluateConstant(expr.operand, env, expected));
        case 'BinaryExpression':
            return binary(expr, evaluateConstant(expr.left, env), evaluateConstant(expr.right, env));
        case 'ConditionalExpression': {
            const condition = evaluateConstant(expr.condition, env);
            if (condition.kind !== 'boolean') throw notConstant(expr.condition, 'is not a boolean');
            return evaluateConstant(condition.value ? expr.then : expr.else, env, expected);
        }
        default:
            throw notConstant(expr, 'is not a constant expression');
    }
}

function notConstant(node: AstNode, why: string): ConstantEvaluationError {
    return new ConstantEvaluationError(`'${node.$cstNode?.text ?? node.$type}' ${why}`, node);
}

/** A string or char literal's value: the parser may keep the quotes; Java escapes are decoded. */
function unquote(raw: string, quote: string, node: AstNode): string {
    const inner = raw.startsWith(quote) && raw.endsWith(quote) && raw.length >= 2 ? raw.slice(1, -1) : raw;
    if (!inner.includes('\\')) return inner;
    try {
        return JSON.parse(`"${inner.replace(/\\'/g, "'")}"`) as string;
    } catch {
        throw notConstant(node, 'has an escape sequence that cannot be evaluated');
    }
}

/** A constant of the expected enum type, by name. */
function enumConstant(expected: SymType | undefined, name: string, node: AstNode): ConstantValue {
    const decl =
        expected?.kind === 'object' && isCDEnum(expected.decl) && AstUtils.getDocument(expected.decl).uri.scheme !== 'builtin'
            ? expected.decl
            : undefined;
    const ordinal = decl ? decl.constants.findIndex((c) => c.name === name) : -1;
    if (decl && ordinal >= 0) return { kind: 'enum', value: name, ordinal, decl };
    throw notConstant(node, 'is not a constant (a parameter or a constant of the expected enum)');
}

function isNumeric(v: ConstantValue): v is Extract<ConstantValue, { kind: 'int' | 'float' }> {
    return v.kind === 'int' || v.kind === 'float';
}

function prefix(expr: PrefixExpression, v: ConstantValue): ConstantValue {
    if (expr.op === '!' && v.kind === 'boolean') return { kind: 'boolean', value: !v.value };
    if (expr.op === '-' && isNumeric(v)) return { kind: v.kind, value: -v.value };
    if (expr.op === '+' && isNumeric(v)) return v;
    if (expr.op === '~' && v.kind === 'int') return { kind: 'int', value: ~v.value };
    throw notConstant(expr, `applies '${expr.op}' to a ${v.kind}`);
}

function binary(expr: BinaryExpression, l: ConstantValue, r: ConstantValue): ConstantValue {
    const op = expr.op;
    if (op === '+' && (l.kind === 'string' || r.kind === 'string')) return { kind: 'string', value: `${display(l)}${display(r)}` };
    if ((op === '&&' || op === '||') && l.kind === 'boolean' && r.kind === 'boolean') {
        return { kind: 'boolean', value: op === '&&' ? l.value && r.value : l.value || r.value };
    }
    if (op === '==' || op === '!=') {
        const equal = l.kind === 'enum' && r.kind === 'enum' ? l.decl === r.decl && l.ordinal === r.ordinal : l.value === r.value;
        return { kind: 'boolean', value: op === '==' ? equal : !equal };
    }
    if (isNumeric(l) && isNumeric(r)) return numeric(expr, l, r);
    throw notConstant(expr, `applies '${op}' to a ${l.kind} and a ${r.kind}`);
}

function display(v: ConstantValue): string {
    if (v.kind === 'float' && Number.isInteger(v.value)) return `${v.value}.0`;
    return String(v.value);
}

/** Java's binary numeric promotion: int op int is an int (division truncates), anything with a float is a float. */
function numeric(
    expr: BinaryExpression,
    l: { kind: 'int' | 'float'; value: number },
    r: { kind: 'int' | 'float'; value: number },
): ConstantValue {
    const kind = l.kind === 'float' || r.kind === 'float' ? 'float' : 'int';
    const a = l.value;
    const b = r.value;
    if (kind === 'int' && (expr.op === '/' || expr.op === '%') && b === 0) throw notConstant(expr, 'divides by zero');
    switch (expr.op) {
        case '+':
            return { kind, value: a + b };
        case '-':
            return { kind, value: a - b };
        case '*':
            return { kind, value: a * b };
        case '/':
            return { kind, value: kind === 'int' ? Math.trunc(a / b) : a / b };
        case '%':
            return { kind, value: a % b };
        case '<':
            return { kind: 'boolean', value: a < b };
        case '<=':
            return { kind: 'boolean', value: a <= b };
        case '>':
            return { kind: 'boolean', value: a > b };
        case '>=':
            return { kind: 'boolean', value: a >= b };
        default:
            throw notConstant(expr, `applies '${expr.op}' to numbers`);
    }
}
