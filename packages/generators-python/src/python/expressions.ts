import type { AstNode } from 'langium';
import { GenerationError } from '@maa/generator-core/node';
import { ast as adlAst, PYTHON_KEYWORDS, PYTHON_SOFT_KEYWORDS, portHeader, printType, typeOfMCType } from '@maa/language-adl';
import { JAVA_LIBRARY } from './java-library.js';
import { ControlFlow } from './control-flow.js';

/** A loosely typed AST node: the translators read `$type` and fields, so they work on any family build. */
// biome-ignore lint/suspicious/noExplicitAny: the translators read fields of any family build's nodes by name
export type Node = AstNode & Record<string, any>;

/** How names of the model appear in the generated Python code. */
export interface NameContext {
    /** Python for a name expression that refers to `target` (a port, field, parameter, local variable, type or constant). */
    name(target: Node, ref: Node): string;
    /** Python statement for writing `value` to an out port, or undefined when `target` is no out port. */
    send?(target: Node, value: string): string | undefined;
    /** Python for a class-diagram type (enum/class). */
    type(decl: Node): string;
    /** Python for a type named as written in a qualified reference (`pkg.Types.Color` of `pkg.Types.Color.RED`), if known. */
    typeBySimpleName?(name: string): string | undefined;
}

/** `a.b.c` of a chain of names and field accesses whose first name does not resolve (a package prefix). */
function qualifiedParts(e: Node): string[] | undefined {
    if (e.$type === 'NameExpression') return e.ref?.ref ? undefined : [String(e.ref?.$refText)];
    if (e.$type === 'FieldAccessExpression') {
        const head = qualifiedParts(e.receiver as Node);
        return head ? [...head, String(e.member)] : undefined;
    }
    return undefined;
}

/** What a generated Python identifier must not be: a keyword, soft ones included. */
const PY_KEYWORDS = new Set([...PYTHON_KEYWORDS, ...PYTHON_SOFT_KEYWORDS]);

/** A Python-safe identifier for a model name. */
export function pyName(name: string): string {
    return PY_KEYWORDS.has(name) ? `${name}_` : name;
}

export function isOutPort(n: Node | undefined): boolean {
    return adlAst.isPort(n) && portHeader(n).direction === 'out';
}

export function isInPort(n: Node | undefined): boolean {
    return adlAst.isPort(n) && portHeader(n).direction === 'in';
}

const BINARY: Record<string, string> = {
    '||': 'or',
    '&&': 'and',
    '==': '==',
    '!=': '!=',
    '<': '<',
    '<=': '<=',
    '>': '>',
    '>=': '>=',
    '+': '+',
    '-': '-',
    '*': '*',
    '|': '|',
    '^': '^',
    '&': '&',
    '<<': '<<',
    '>>': '>>',
};

/** `x == null` as `(x is None)`: a comparison with null tests identity, as in Java (and ruff's E711 asks for `is`). */
function nullComparison(e: Node, l: string, r: string): string | undefined {
    const isNull = (n: unknown): boolean => (n as Node | undefined)?.$type === 'NullLiteral';
    if ((e.op !== '==' && e.op !== '!=') || !(isNull(e.left) || isNull(e.right))) return undefined;
    return `(${l} ${e.op === '==' ? 'is' : 'is not'} ${r})`;
}

function stripSuffix(text: string): string {
    return text.replace(/[lLfFdD]$/, '');
}

function pyString(s: string): string {
    return JSON.stringify(s);
}

/** Translates the Java-like expressions and statements of the models to Python. */
export class PythonTranslator {
    /** do-while, switch, break and continue (control-flow.ts). */
    private readonly control = new ControlFlow({
        expr: (e) => this.expr(e),
        stmt: (s) => this.stmt(s),
        expressionStatement: (e) => this.exprStmt(e),
        pyName,
    });

    constructor(private readonly names: NameContext) {}

    expr(e: Node): string {
        switch (e.$type) {
            case 'BooleanLiteral':
                return e.value === 'true' ? 'True' : 'False';
            case 'NullLiteral':
                return 'None';
            case 'IntLiteral':
                return String(typeof e.value === 'number' ? e.value : Number(e.value));
            case 'LongLiteral':
                return String(Number(stripSuffix(String(e.value))));
            case 'FloatLiteral': {
                const raw = String(e.value);
                const text = /[eE.]/.test(raw) ? stripSuffix(raw) : `${stripSuffix(raw)}.0`;
                return /[fF]$/.test(raw) ? `f32(${text})` : text;
            }
            case 'CharLiteral': {
                const raw = String(e.value);
                const inner = raw.startsWith("'") ? raw.slice(1, -1) : raw;
                const ch = inner.startsWith('\\') ? (JSON.parse(`"${inner}"`) as string) : inner;
                return String(ch.codePointAt(0) ?? 0);
            }
            case 'StringLiteral': {
                const raw = String(e.value);
                return raw.startsWith('"') ? pyString(JSON.parse(raw) as string) : pyString(raw);
            }
            case 'NameExpression': {
                const target = e.ref?.ref as Node | undefined;
                if (!target) throw new GenerationError(`unresolved name '${e.ref?.$refText}'`, e);
                return this.names.name(target, e);
            }
            case 'FieldAccessExpression': {
                const recv = e.receiver as Node;
                const libType = libraryTypeOf(recv);
                if (libType) return `jfield(${pyString(libType)}, ${pyString(String(e.member))})`;
                const parts = qualifiedParts(e);
                if (parts && parts.length >= 2) {
                    const type = this.names.typeBySimpleName?.(parts.slice(0, -1).join('.'));
                    if (type) return `${type}.${pyName(parts[parts.length - 1])}`;
                    throw new GenerationError(`unresolved name '${parts.join('.')}'`, e);
                }
                const recvTarget = recv.$type === 'NameExpression' ? (recv.ref?.ref as Node | undefined) : undefined;
                if (isTypeDecl(recvTarget)) return `${this.names.type(recvTarget)}.${pyName(e.member)}`;
                return `${this.expr(recv)}.${pyName(e.member)}`;
            }
            case 'CallExpression':
                return this.call(e);
            case 'ArrayAccessExpression':
                return `${this.expr(e.receiver)}[${this.expr(e.index)}]`;
            case 'ConditionalExpression':
                return `(${this.expr(e.then)} if ${this.expr(e.condition)} else ${this.expr(e.else)})`;
            case 'SwitchExpression': {
                const hoisted = this.hoisted;
                return this.control.switchExpression(e, hoisted && ((lines) => hoisted.push(...lines)));
            }
            case 'BinaryExpression': {
                const l = this.expr(e.left);
                const r = this.expr(e.right);
                if (e.op === '/') return `jdiv(${l}, ${r})`;
                if (e.op === '%') return `jmod(${l}, ${r})`;
                if (e.op === '>>>') return `jushr(${l}, ${r})`;
                if (e.op === '+' && (this.isStringy(e.left) || this.isStringy(e.right))) {
                    // chars are their codes at run time; in a string they are characters again
                    return `jconcat(${isChar(e.left) ? `chr(${l})` : l}, ${isChar(e.right) ? `chr(${r})` : r})`;
                }
                const nullTest = nullComparison(e, l, r);
                if (nullTest) return nullTest;
                const op = BINARY[e.op as string];
                if (!op) throw new GenerationError(`operator '${e.op}' is not supported by the Python generators`, e);
                return `(${l} ${op} ${r})`;
            }
            case 'CastExpression':
                return `jcast(${this.expr(e.operand)}, ${pyString(String(e.type?.name))})`;
            case 'PrefixExpression': {
                const o = this.expr(e.operand);
                switch (e.op) {
                    case '!':
                        return `(not ${o})`;
                    case '-':
                        return `(-${o})`;
                    case '+':
                        return o;
                    case '~':
                        return `(~${o})`;
                    default:
                        throw new GenerationError(`'${e.op}' inside an expression is not supported; use it as a statement`, e);
                }
            }
            case 'AssignmentExpression':
            case 'PostfixExpression':
                throw new GenerationError(
                    'an assignment inside an expression is not supported by the Python generators; use it as a statement',
                    e,
                );
            default:
                if (e.$type === 'Expression' && e.expression) return this.expr(e.expression);
                throw new GenerationError(`expression '${e.$type}' is not supported by the Python generators`, e);
        }
    }

    private isStringy(e: Node): boolean {
        return (
            e.$type === 'StringLiteral' ||
            (e.$type === 'BinaryExpression' && e.op === '+' && (this.isStringy(e.left) || this.isStringy(e.right)))
        );
    }

    private call(e: Node): string {
        const recv = e.receiver as Node;
        const args = (e.args as Node[]).map((a) => this.expr(a));
        if (recv.$type === 'FieldAccessExpression') {
            const member = String(recv.member);
            const libType = libraryTypeOf(recv.receiver as Node);
            if (libType) return `jstatic(${pyString(libType)}, ${pyString(member)}, ${pyTuple(args)})`;
            const obj = this.expr(recv.receiver);
            if (member === 'ordinal' && args.length === 0) return `jordinal(${obj})`;
            if (JAVA_LIBRARY.instanceMethods.has(member)) {
                const hint = declaredType(recv.receiver as Node);
                return `jcall(${obj}, ${pyString(member)}, ${pyTuple(args)}${hint ? `, ${pyString(hint)}` : ''})`;
            }
            return `${obj}.${pyName(member)}(${args.join(', ')})`;
        }
        return `${this.expr(recv)}(${args.join(', ')})`;
    }

    /**
     * Lines to place before the statement being translated (the local functions of switch
     * expressions' block arms, control-flow.ts); undefined outside a statement.
     */
    private hoisted: string[] | undefined;

    /** Python statements (one per line, unindented) for a statement. */
    stmt(s: Node): string[] {
        const outer = this.hoisted;
        const hoisted: string[] = [];
        this.hoisted = hoisted;
        try {
            const lines = this.statement(s);
            return hoisted.length > 0 ? [...hoisted, ...lines] : lines;
        } finally {
            this.hoisted = outer;
        }
    }

    private statement(s: Node): string[] {
        switch (s.$type) {
            case 'Block': {
                const out = (s.statements as Node[]).flatMap((x) => this.stmt(x));
                return out;
            }
            case 'EmptyStatement':
                return [];
            case 'LocalVariableDeclaration':
                return (s.variables as Node[]).map((v) => `${pyName(v.name)} = ${v.init ? this.expr(v.init) : 'None'}`);
            case 'IfStatement': {
                const out = [`if ${this.expr(s.condition)}:`, ...this.body(s.then)];
                if (s.else) {
                    const elseLines = this.body(s.else);
                    out.push('else:', ...elseLines);
                }
                return out;
            }
            case 'WhileStatement':
                return [`while ${this.expr(s.condition)}:`, ...this.body(s.body)];
            case 'DoWhileStatement':
                return this.control.doWhile(s);
            case 'SwitchStatement':
                return this.control.switchStatement(s);
            case 'BreakStatement':
                return this.control.breakStatement();
            case 'ContinueStatement':
                return this.control.continueStatement(s);
            case 'ForStatement': {
                if (this.control.needsContinueForm(s)) return this.control.forWithContinue(s);
                const out: string[] = s.init ? this.stmt(s.init) : [];
                const cond = s.condition ? this.expr(s.condition) : 'True';
                const updates = (s.updates as Node[]).flatMap((u) => this.exprStmt(u));
                out.push(`while ${cond}:`, ...this.body(s.body), ...updates.map((u) => `    ${u}`));
                return out;
            }
            case 'ExpressionStatement':
                return this.exprStmt(s.expression);
            // Only in a switch expression's block arm (checked), which is a local function (control-flow.ts).
            case 'YieldStatement':
                return [`return ${this.expr(s.value)}`];
            default:
                throw new GenerationError(`statement '${s.$type}' is not supported by the Python generators`, s);
        }
    }

    /** An indented body (never empty). */
    body(s: Node): string[] {
        const lines = this.stmt(s);
        return (lines.length ? lines : ['pass']).map((l) => `    ${l}`);
    }

    /** Statements for a block/statement, `pass` when empty. */
    block(s: Node | undefined): string[] {
        const lines = s ? this.stmt(s) : [];
        return lines.length ? lines : ['pass'];
    }

    private exprStmt(e: Node): string[] {
        if (e.$type === 'AssignmentExpression') {
            const left = e.left as Node;
            let value = this.expr(e.right);
            if (e.op !== '=') {
                const op = (e.op as string).slice(0, -1);
                const cur = this.expr(left);
                // `s += x` on a String is Java's concatenation (a char joins as the character)
                if (op === '+' && declaredType(left) === 'String')
                    value = `jconcat(${cur}, ${isChar(e.right as Node) ? `chr(${value})` : value})`;
                else
                    value =
                        op === '/'
                            ? `jdiv(${cur}, ${value})`
                            : op === '%'
                              ? `jmod(${cur}, ${value})`
                              : op === '>>>'
                                ? `jushr(${cur}, ${value})`
                                : `(${cur} ${op} ${value})`;
            }
            return [this.assign(left, value)];
        }
        if ((e.$type === 'PostfixExpression' || e.$type === 'PrefixExpression') && (e.op === '++' || e.op === '--')) {
            const operand = e.operand as Node;
            return [this.assign(operand, `(${this.expr(operand)} ${e.op === '++' ? '+' : '-'} 1)`)];
        }
        return [this.expr(e)];
    }

    private assign(left: Node, value: string): string {
        if (left.$type === 'NameExpression') {
            const target = left.ref?.ref as Node | undefined;
            if (!target) throw new GenerationError(`unresolved name '${left.ref?.$refText}'`, left);
            const sent = this.names.send?.(target, value);
            if (sent) return sent;
            return `${this.names.name(target, left)} = ${value}`;
        }
        return `${this.expr(left)} = ${value}`;
    }
}

/** A Python tuple expression. */
function pyTuple(xs: readonly string[]): string {
    return xs.length === 0 ? '()' : `(${xs.join(', ')}${xs.length === 1 ? ',' : ''})`;
}

/** The qualified name of the JDK library type an expression names (`Math`, `java.util.Date`), if it names one. */
function libraryTypeOf(e: Node): string | undefined {
    if (e.$type === 'NameExpression') {
        const target = e.ref?.ref as Node | undefined;
        if (!target || !isTypeDecl(target) || !isBuiltin(target)) return undefined;
        const pkg = String((rootOf(target) as Node).package ?? '');
        return `${pkg}.${String(target.name)}`;
    }
    const parts = qualifiedParts(e);
    const q = parts?.join('.');
    return q && JAVA_LIBRARY.types.has(q) ? q : undefined;
}

function rootOf(n: Node): Node {
    let root = n;
    while (root.$container) root = root.$container as Node;
    return root;
}

function isBuiltin(n: Node): boolean {
    return (rootOf(n).$document?.uri?.scheme ?? '') === 'builtin';
}

/** The declared type of a name or literal (what Python cannot tell apart: `long`/`int`, `float`/`double`, `char`). */
function declaredType(e: Node): string | undefined {
    switch (e.$type) {
        case 'IntLiteral':
            return 'int';
        case 'LongLiteral':
            return 'long';
        case 'FloatLiteral':
            return /[fF]$/.test(String(e.value)) ? 'float' : 'double';
        case 'CharLiteral':
            return 'char';
        case 'CastExpression':
            return String(e.type?.name);
        case 'NameExpression': {
            const t = e.ref?.ref as Node | undefined;
            if (!t) return undefined;
            const mcType = adlAst.isPort(t)
                ? portHeader(t).type
                : t.$type === 'Field' || t.$type === 'LocalVariable'
                  ? (t.$container as Node).type
                  : t.$type === 'Parameter'
                    ? t.type
                    : undefined;
            return mcType ? printType(typeOfMCType(mcType)) : undefined;
        }
        default:
            return undefined;
    }
}

/** Whether an expression is a `char` or `Character` (a code at run time). */
function isChar(e: Node): boolean {
    const t = declaredType(e);
    return t === 'char' || t === 'Character';
}

/** Whether a node declares a class-diagram type (class, interface, enum). */
export function isTypeDecl(n: Node | undefined): n is Node & { readonly $type: 'CDType' | 'CDClass' | 'CDInterface' | 'CDEnum' } {
    return !!n && ['CDType', 'CDClass', 'CDInterface', 'CDEnum'].includes(n.$type);
}
