import { AstUtils, type AstNode, type LangiumDocument } from 'langium';
import { describe, expect, test } from 'vitest';
import type { Automaton, InternalTransition, NameExpression, Port, State, Transition } from '../src/generated/ast.js';
import { allStates, allTransitions } from '../src/index.js';
import { build, services } from './helpers.js';

async function parse(files: Record<string, string>): Promise<{ doc: LangiumDocument; a: Automaton }> {
    const { docs } = await build(files);
    const doc = docs.find((d) => d.uri.path.endsWith('/Comp.arc'))!;
    const a = AstUtils.streamAst(doc.parseResult.value).find((n): n is Automaton => n.$type === 'Automaton')!;
    return { doc, a };
}

function scopeNames(node: AstNode, property: string): string[] {
    const s = services().Arc.references.ScopeProvider;
    const reference = (node as unknown as Record<string, { $refText: string }>)[property]!;
    return s
        .getScope({ container: node, property, reference: reference as never })
        .getAllElements()
        .map((d) => d.name)
        .toArray();
}

describe('states', () => {
    test('form one flat namespace: every state of the automaton is visible from every transition', async () => {
        const { a } = await parse({
            'Comp.arc':
                'component Comp {\n  automaton {\n    initial state A { initial state A1 { -> ; A1 -> B2; }; };\n    state B { initial state B1; state B2; };\n  }\n}',
        });
        const t = allTransitions(a).find((x): x is Transition => x.$type === 'Transition')!;
        expect(scopeNames(t, 'source')).toEqual(['A', 'A1', 'B', 'B1', 'B2']);
        expect(t.target.ref?.name).toBe('B2');
    });

    test('do not leak into other automata', async () => {
        const {
            docs: [doc],
        } = await build({
            'Comp.arc':
                'component Comp {\n  component Inner { automaton { initial state X; } }\n  automaton { initial state S; S -> X; }\n}',
        });
        expect(doc!.diagnostics?.map((d) => `${d.code}`)).toContain('automaton/missing-state');
    });

    test('references to a state are found for rename and find-references', async () => {
        const { a } = await parse({
            'Comp.arc':
                'component Comp {\n  automaton {\n    initial state A;\n    state B { initial state B1; };\n    A -> B1;\n    B1 -> A;\n    B -> A;\n  }\n}',
        });
        const A = allStates(a).find((s) => s.name === 'A')!;
        const refs = services().Arc.references.References.findReferences(A, { includeDeclaration: false }).toArray();
        expect(refs.map((r) => r.segment.range.start.line + 1)).toEqual([5, 6, 7]);
    });
});

describe('events', () => {
    test('are the incoming ports of the component, inherited ones included', async () => {
        const { a } = await parse({
            'Base.arc': 'component Base {\n  port in int fromBase;\n  port out int toBase;\n}',
            'Comp.arc':
                'component Comp extends Base {\n  port in boolean own;\n  port out int o;\n  automaton {\n    initial state S { -> own; };\n    S -> S fromBase;\n  }\n}',
        });
        const [internal, t] = allTransitions(a) as [InternalTransition, Transition];
        expect(scopeNames(t, 'event')).toEqual(['own', 'fromBase']);
        expect(scopeNames(internal, 'event')).toEqual(['own', 'fromBase']);
        expect((t.event!.ref as Port).direction).toBe('in');
        expect(AstUtils.getDocument(t.event!.ref!).uri.path).toMatch(/Base\.arc$/);
    });
});

describe('guards and actions', () => {
    test('resolve ports, fields, parameters and local variables of the enclosing component', async () => {
        const { a } = await parse({
            'Comp.arc':
                'component Comp(int p) {\n  port in int i;\n  port out int o;\n  int f = 0;\n  automaton {\n    initial { o = p; } state S { entry / { int l = f; o = l; } };\n    S -> S [i > p && f == 0] / { f = i; };\n  }\n}',
        });
        const names = AstUtils.streamAst(a)
            .filter((n): n is NameExpression => n.$type === 'NameExpression')
            .map((n) => `${n.ref.$refText}:${n.ref.ref?.$type}`)
            .toArray();
        expect(names).toEqual([
            'o:Port',
            'p:Parameter',
            'f:Field',
            'o:Port',
            'l:LocalVariable',
            'i:Port',
            'p:Parameter',
            'f:Field',
            'f:Field',
            'i:Port',
        ]);
    });
    test('a state name is no value', async () => {
        const {
            docs: [doc],
        } = await build({ 'Comp.arc': 'component Comp {\n  automaton {\n    initial state S;\n    S -> S [S];\n  }\n}' });
        expect(doc!.diagnostics?.map((d) => d.code)).toEqual(['expr/unresolved-name']);
    });
});

test('states are named nodes for outline and hover', async () => {
    const { a } = await parse({ 'Comp.arc': 'component Comp {\n  automaton {\n    /** Waiting. */\n    initial state Idle;\n  }\n}' });
    const idle = allStates(a)[0] as State;
    expect(services().Arc.references.NameProvider.getName(idle)).toBe('Idle');
    expect(services().Arc.documentation.DocumentationProvider.getDocumentation(idle)).toContain('Waiting.');
});
