import { AstUtils } from 'langium';
import { describe, expect, test } from 'vitest';
import type { Automaton, InternalTransition, State, StateAction, Transition } from '../src/generated/ast.js';
import { allStates, allTransitions, automatonTiming, startState, triggerOf } from '../src/index.js';
import { build, comp, dump, validate } from './helpers.js';

async function automatonOf(body: string, header = ''): Promise<Automaton> {
    const { docs } = await build(comp(body, header));
    const doc = docs[0]!;
    const errors = (doc.diagnostics ?? []).filter((d) => String(d.code).startsWith('syntax/'));
    expect(errors, JSON.stringify(errors, null, 1)).toEqual([]);
    const a = AstUtils.streamAst(doc.parseResult.value).find((n): n is Automaton => n.$type === 'Automaton');
    expect(a).toBeDefined();
    return a!;
}

describe('states', () => {
    test('simple, initial, hierarchical states with and without trailing semicolons', async () => {
        const a = await automatonOf(`
  automaton {
    initial state A;
    state B { };
    state C {
      initial state C1;
      state C2 { initial state C21; }
    };
    state D { state D1; }
  }`);
        expect(allStates(a).map((s) => s.name)).toEqual(['A', 'B', 'C', 'C1', 'C2', 'C21', 'D', 'D1']);
        expect(
            allStates(a)
                .filter((s) => s.initial)
                .map((s) => s.name),
        ).toEqual(['A', 'C1', 'C21']);
        expect(startState(a)?.name).toBe('A');
    });

    test('initial blocks before `state`, also on substates', async () => {
        const a = await automatonOf(`
  port out int o;
  automaton {
    initial { o = 1; o = 2; } state A {
      initial {
        o = 3;
      } state A1;
    };
  }`);
        const [A, A1] = allStates(a);
        expect(A!.initialAction?.statements).toHaveLength(2);
        expect(A1!.initial && A1!.initialAction?.statements.length).toBe(1);
    });

    test('entry, exit and do actions as blocks or single statements', async () => {
        const a = await automatonOf(`
  port out String o;
  automaton {
    initial state A {
      entry / o = "Enter A";
      do / o = "Do A";
      exit / o = "Exit A";
    };
    state B {
      entry / { o = "a"; o = "b"; }
      exit / { o = "c"; };
      do / if (true) o = "d";
    };
  }`);
        const actions = AstUtils.streamAst(a)
            .filter((n): n is StateAction => n.$type === 'StateAction')
            .toArray();
        expect(actions.map((x) => `${x.$container.name}.${x.kind}:${x.action.$type}`)).toEqual([
            'A.entry:ExpressionStatement',
            'A.do:ExpressionStatement',
            'A.exit:ExpressionStatement',
            'B.entry:Block',
            'B.exit:Block',
            'B.do:IfStatement',
        ]);
    });

    test('stereotypes on states and transitions', async () => {
        const a = await automatonOf(`
  automaton {
    <<important>> initial state A;
    <<note="x">> A -> A;
  }`);
        expect(allStates(a)[0]!.stereotype?.values[0]?.name).toBe('important');
        expect((allTransitions(a)[0] as Transition).stereotype?.values[0]?.value).toBe('x');
    });
});

describe('transitions', () => {
    test('every combination of guard, event and action; MontiArc double semicolons', async () => {
        const a = await automatonOf(
            `
  port in int i;
  port out int o;
  automaton {
    initial state S;
    state T;
    S -> T;
    S -> T [i > 0];
    S -> T i;
    S -> T Tick;
    S -> T / o = 1;;
    S -> T / { o = 1; };
    S -> T [i > 0] i / { o = i; };
    S -> T [i < 0] Tick / o = -1;;
    T -> S / { o = 0; }
    T -> S / o = 0;
  }`,
            '',
        );
        const ts = allTransitions(a) as Transition[];
        expect(
            ts.map((t) =>
                [t.source.$refText, t.target.$refText, t.guard !== undefined, triggerOf(t).kind, t.action?.$type ?? '-'].join(' '),
            ),
        ).toEqual([
            'S T false none -',
            'S T true none -',
            'S T false port -',
            'S T false tick -',
            'S T false none ExpressionStatement',
            'S T false none Block',
            'S T true port Block',
            'S T true tick ExpressionStatement',
            'T S false none Block',
            'T S false none ExpressionStatement',
        ]);
        expect(ts.every((t) => t.source.ref && t.target.ref)).toBe(true);
    });

    test('internal transitions inside states', async () => {
        const a = await automatonOf(`
  port in String i;
  port out String o;
  automaton {
    initial state A {
      -> [i.equals("internal")] i / o = "internal A";;
      -> / { o = "x"; };
      -> Tick;
    };
  }`);
        const ts = allTransitions(a) as InternalTransition[];
        expect(ts.map((t) => `${t.$type}:${t.$container.name}:${triggerOf(t).kind}`)).toEqual([
            'InternalTransition:A:port',
            'InternalTransition:A:none',
            'InternalTransition:A:tick',
        ]);
    });

    test('transitions may be declared inside states and before the states they name', async () => {
        const a = await automatonOf(`
  automaton {
    A -> B;
    initial state A { B -> A; };
    state B;
  }`);
        expect(allTransitions(a).map((t) => (t as Transition).source.ref?.name)).toEqual(['A', 'B']);
    });

    test('the timing of the behavior declaration, timed by default', async () => {
        expect(automatonTiming(await automatonOf('  <<sync>> automaton { initial state S; }'))).toBe('sync');
        expect(automatonTiming(await automatonOf('  <<untimed>> automaton { initial state S; }'))).toBe('untimed');
        expect(automatonTiming(await automatonOf('  automaton { initial state S; }'))).toBe('timed');
    });
});

describe('soft keywords', () => {
    test('Tick, state, initial, entry, exit remain usable as names outside automata', async () => {
        const found = await validate(
            comp(
                '  port in int state, entry, exit;\n  port out int initial;\n  automaton {\n    initial state S;\n    S -> S entry / initial = state + exit;;\n  }',
            ),
        );
        expect(
            found.filter((f) => f.code.startsWith('syntax/') || f.code.startsWith('link/')),
            dump(found),
        ).toEqual([]);
    });
    test('a port named Tick parses and is reported as a reserved name', async () => {
        const found = await validate(comp('  port in int Tick;'));
        expect(
            found.filter((f) => f.code.startsWith('syntax/')),
            dump(found),
        ).toEqual([]);
        expect(found.map((f) => f.code)).toContain('arc/reserved-name');
    });
});

describe('syntax errors', () => {
    test('a transition without semicolon is a syntax error', async () => {
        const found = await validate(comp('  automaton {\n    initial state S;\n    S -> S\n  }'));
        expect(found.map((f) => f.code)).toContain('syntax/unexpected-token');
    });
    test('an initial block needs `initial`', async () => {
        const found = await validate(comp('  automaton {\n    { } state S;\n  }'));
        expect(found.some((f) => f.code.startsWith('syntax/'))).toBe(true);
    });
});

// States are plain named nodes: a transition's source and target are references to them.
test('references point at the declared states', async () => {
    const a = await automatonOf('  automaton {\n    initial state A { initial state A1; };\n    A1 -> A;\n  }');
    const t = allTransitions(a)[0] as Transition;
    const [A, A1] = allStates(a) as [State, State];
    expect(t.source.ref).toBe(A1);
    expect(t.target.ref).toBe(A);
});
