import { GenerationError } from '@maa/generator-core/node';
import type { Node } from './expressions.js';

/** What the control-flow translation needs of the statement translator. */
export interface StatementHost {
    expr(e: Node): string;
    stmt(s: Node): string[];
    /** Python statements for an expression used as a statement (an assignment, `i++`, a call). */
    expressionStatement(e: Node): string[];
    /** The Python name of a model name (a local variable's). */
    pyName(name: string): string;
}

const LOOPS = new Set(['WhileStatement', 'DoWhileStatement', 'ForStatement']);

function indent(lines: readonly string[]): string[] {
    return (lines.length ? lines : ['pass']).map((l) => `    ${l}`);
}

/**
 * Java's `do`-`while`, `switch`, `break` and `continue` in Python 3.11, with Java's semantics:
 *
 * - `do S while (c);` runs S once before testing c; a `continue` in S goes to the test:
 *   `first = True` / `while first or (c):` / `first = False` / S.
 * - `switch` picks the index of the group whose label matches (else the default's, else none)
 *   and runs the groups from there on inside a one-pass `while True:` loop, so a group without
 *   `break` falls through into the next one and `break` leaves the switch. `case ... ->` rules
 *   end with an implicit `break`.
 * - `continue` inside a switch would only restart that one-pass loop in Python, so it sets a
 *   flag of the switch and breaks; after the switch the flag continues the enclosing loop.
 * - A `for` whose body continues runs its updates at the top of the next round (Python's
 *   `continue` would skip updates written at the end of the body).
 *
 * Temporary names start with `_maa_` and a number unique within the translator.
 */
export class ControlFlow {
    private counter = 0;
    private readonly switchFlags = new Map<Node, string>();

    constructor(private readonly host: StatementHost) {}

    private fresh(base: string): string {
        return `_maa_${base}${++this.counter}`;
    }

    doWhile(s: Node): string[] {
        const first = this.fresh('first');
        return [
            `${first} = True`,
            `while ${first} or ${this.host.expr(s.condition)}:`,
            `    ${first} = False`,
            ...indent(this.host.stmt(s.body)),
        ];
    }

    /** A `for` statement whose body has a `continue` of its own (other `for` loops keep the plain translation). */
    needsContinueForm(s: Node): boolean {
        return continuesOf(s).length > 0;
    }

    forWithContinue(s: Node): string[] {
        const next = this.fresh('next');
        const out: string[] = s.init ? this.host.stmt(s.init) : [];
        const updates = (s.updates as Node[]).flatMap((u) => this.host.expressionStatement(u));
        out.push(`${next} = False`, 'while True:');
        if (updates.length > 0) out.push(`    if ${next}:`, ...updates.map((u) => `        ${u}`));
        out.push(`    ${next} = True`);
        if (s.condition) out.push(`    if not ${this.host.expr(s.condition)}:`, '        break');
        out.push(...indent(this.host.stmt(s.body)));
        return out;
    }

    switchStatement(s: Node): string[] {
        const value = this.fresh('sw');
        const start = this.fresh('start');
        const groups = s.groups as Node[];
        const out = [`${value} = ${this.host.expr(s.selector)}`];
        let defaultIndex = groups.length;
        const tests: string[][] = [];
        groups.forEach((g, i) => {
            for (const label of g.labels as Node[]) {
                if (label.default) defaultIndex = i;
                for (const v of label.values as Node[]) {
                    (tests[i] ??= []).push(`${value} == ${this.host.expr(v)}`);
                }
            }
        });
        let first = true;
        groups.forEach((_, i) => {
            const t = tests[i];
            if (!t) return;
            out.push(`${first ? 'if' : 'elif'} ${t.join(' or ')}:`, `    ${start} = ${i}`);
            first = false;
        });
        if (first) out.push(`${start} = ${defaultIndex}`);
        else out.push('else:', `    ${start} = ${defaultIndex}`);
        const flag = this.needsContinueFlag(s) ? this.fresh('cont') : undefined;
        if (flag) {
            this.switchFlags.set(s, flag);
            out.push(`${flag} = False`);
        }
        out.push('while True:');
        groups.forEach((g, i) => {
            const body = (g.statements as Node[]).flatMap((x) => this.host.stmt(x));
            if ((g.labels as Node[]).some((l) => l.arrow)) body.push('break');
            out.push(`    if ${start} <= ${i}:`, ...indent(body).map((l) => `    ${l}`));
        });
        out.push('    break');
        if (flag) out.push(`if ${flag}:`, ...indent(this.continueFrom(s)));
        return out;
    }

    /**
     * A switch expression as one conditional chain that evaluates the selector once, first (a
     * walrus in the first test), then the matching arm only: `(10 if (_maa_sw1 := s) == 1 or
     * _maa_sw1 == 2 else 0)`. A block arm becomes a local function `_maa_armN` that `hoist`
     * places right before the statement using the expression (`-> object`; its `yield`s return; outer locals
     * it assigns are `nonlocal`); the chain calls it. Without a `default` (an enum switch naming
     * every constant) the last arm is the chain's `else`.
     */
    switchExpression(e: Node, hoist: ((lines: string[]) => void) | undefined): string {
        const value = this.fresh('sw');
        const selector = `(${value} := ${this.host.expr(e.selector)})`;
        const arms = e.arms as Node[];
        let defaultArm: Node | undefined;
        const cases: Array<{ tests: string[]; arm: Node }> = [];
        for (const arm of arms) {
            const label = arm.label as Node;
            if (label.default) defaultArm = arm;
            const values = label.values as Node[];
            if (values.length > 0) cases.push({ tests: values.map((v) => this.host.expr(v)), arm });
        }
        const armValue = (arm: Node): string => (arm.value ? this.host.expr(arm.value) : this.blockArm(arm.body as Node, hoist));
        let last = defaultArm;
        if (!last) {
            const final = cases.pop();
            if (!final) throw new GenerationError('a switch expression without arms', e);
            last = final.arm;
        }
        if (cases.length === 0) return `(${selector}, ${armValue(last)})[1]`;
        const parts: string[] = [];
        cases.forEach((c, i) => {
            const tests = c.tests.map((t, j) => `${i === 0 && j === 0 ? selector : value} == ${t}`);
            parts.push(`${armValue(c.arm)} if ${tests.join(' or ')} else`);
        });
        return `(${parts.join(' ')} ${armValue(last)})`;
    }

    private blockArm(body: Node, hoist: ((lines: string[]) => void) | undefined): string {
        if (!hoist)
            throw new GenerationError(
                'a switch expression with a block arm is supported by the Python generators inside statements only (compute blocks, actions), not in guards or initializers',
                body,
            );
        const fn = this.fresh('arm');
        const lines = this.host.stmt(body);
        const nonlocals = assignedOuterLocals(body).map((n) => this.host.pyName(n));
        hoist([`def ${fn}() -> object:`, ...(nonlocals.length > 0 ? [`    nonlocal ${nonlocals.join(', ')}`] : []), ...indent(lines)]);
        return `${fn}()`;
    }

    breakStatement(): string[] {
        return ['break'];
    }

    continueStatement(s: Node): string[] {
        return this.continueFrom(s);
    }

    /** Python for a `continue` at `node`: `continue`, or leaving the switches between it and its loop. */
    private continueFrom(node: Node): string[] {
        for (let n = node.$container as Node | undefined; n; n = n.$container as Node | undefined) {
            if (LOOPS.has(n.$type)) return ['continue'];
            if (n.$type === 'SwitchStatement') {
                const flag = this.switchFlags.get(n);
                if (!flag) throw new GenerationError('internal: a continue inside a switch without a continue flag', node);
                return [`${flag} = True`, 'break'];
            }
        }
        throw new GenerationError("'continue' outside a loop", node);
    }

    /** Whether a `continue` inside the switch leaves it (for a loop around it). */
    private needsContinueFlag(s: Node): boolean {
        return continuesOf(s, true).length > 0;
    }
}

/** Names of the local variables declared outside `body` that it assigns (`x = ...`, `x += ...`, `x++`). */
function assignedOuterLocals(body: Node): string[] {
    const names = new Set<string>();
    const inside = (n: Node): boolean => {
        for (let c: Node | undefined = n; c; c = c.$container as Node | undefined) if (c === body) return true;
        return false;
    };
    const visit = (n: Node): void => {
        let target: Node | undefined;
        if (n.$type === 'AssignmentExpression') target = n.left as Node;
        else if ((n.$type === 'PrefixExpression' || n.$type === 'PostfixExpression') && (n.op === '++' || n.op === '--'))
            target = n.operand as Node;
        const decl = target?.$type === 'NameExpression' ? (target.ref?.ref as Node | undefined) : undefined;
        if (decl?.$type === 'LocalVariable' && !inside(decl)) names.add(String(decl.name));
        for (const [key, value] of Object.entries(n)) {
            if (key.startsWith('$')) continue;
            for (const c of Array.isArray(value) ? value : [value]) {
                if (c && typeof c === 'object' && typeof (c as Node).$type === 'string') visit(c as Node);
            }
        }
    };
    visit(body);
    return [...names].sort();
}

/**
 * The `continue` statements inside `root` that belong to `root` (a loop) or, with `throughSwitch`,
 * that leave `root` (a switch) for a loop around it: nested loops keep their own.
 */
function continuesOf(root: Node, throughSwitch = false): Node[] {
    const found: Node[] = [];
    const visit = (n: Node): void => {
        for (const [key, value] of Object.entries(n)) {
            if (key.startsWith('$')) continue;
            const children = Array.isArray(value) ? value : [value];
            for (const c of children) {
                if (!c || typeof c !== 'object' || typeof (c as Node).$type !== 'string') continue;
                const child = c as Node;
                if (child.$type === 'ContinueStatement') found.push(child);
                else if (!LOOPS.has(child.$type)) visit(child);
            }
        }
    };
    if (throughSwitch || LOOPS.has(root.$type)) visit(root);
    return found;
}
