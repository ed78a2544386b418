import { describe, expect, test } from 'vitest';
import { comp, dump, hits, validate } from './helpers.js';

const ports = '  port in int i;\n  port out int o;';

describe('automaton/no-initial-state', () => {
    test('an automaton without states has no initial state', async () => {
        const found = await validate(comp('  automaton { }'));
        expect(hits(found, 'automaton/no-initial-state')).toEqual(['automaton/no-initial-state@automaton']);
        expect(found.find((f) => f.code === 'automaton/no-initial-state')!.severity).toBe('error');
    });
    test('an initial substate does not make the automaton initial', async () => {
        const found = await validate(comp('  automaton { state s { initial state inner; }; }'));
        expect(hits(found, 'automaton/no-initial-state')).toEqual(['automaton/no-initial-state@automaton']);
    });
    test('the automaton of an inner component type is checked on its own', async () => {
        const found = await validate(comp('  automaton { initial state s; }\n  component Inner { automaton { } }'));
        expect(found.filter((f) => f.code === 'automaton/no-initial-state').map((f) => f.line)).toEqual([3]);
    });
    test('a hierarchical state without initial substate is a warning on the state', async () => {
        const found = await validate(comp('  automaton {\n    initial state A { state A1; state A2; };\n  }'));
        const w = found.filter((f) => f.code === 'automaton/no-initial-state');
        expect(w.map((f) => `${f.severity}@${f.text}`)).toEqual(['warning@A']);
        expect(w[0]!.message).toContain("'A1'");
    });
    test('valid: one initial state per level', async () => {
        const found = await validate(comp('  automaton {\n    initial state A { initial state A1; state A2; };\n    state B;\n  }'));
        expect(hits(found, 'automaton/no-initial-state', 'automaton/multiple-initial-states'), dump(found)).toEqual([]);
    });
});

describe('automaton/multiple-initial-states', () => {
    test('two initial top-level states: reported on the second', async () => {
        const found = await validate(comp('  automaton {\n    initial state s1;\n    initial state s2;\n  }'));
        const e = found.filter((f) => f.code === 'automaton/multiple-initial-states');
        expect(e.map((f) => `${f.severity}@${f.text}@${f.line}`)).toEqual(['error@initial@4']);
        expect(e[0]!.message).toContain("'s1', 's2'");
    });
    test('several initial substates are a warning', async () => {
        const found = await validate(
            comp('  automaton {\n    initial state A {\n      initial state A1;\n      initial state A2;\n    };\n  }'),
        );
        const w = found.filter((f) => f.code === 'automaton/multiple-initial-states');
        expect(w.map((f) => `${f.severity}@${f.text}@${f.line}`)).toEqual(['warning@initial@5']);
    });
    test('valid: initial states in different automata', async () => {
        const found = await validate(
            comp('  component Inner1 { automaton { initial state s1; } }\n  component Inner2 { automaton { initial state s2; } }'),
        );
        expect(hits(found, 'automaton/multiple-initial-states'), dump(found)).toEqual([]);
    });
});

describe('automaton/duplicate-state', () => {
    test('every repeated declaration is reported', async () => {
        const found = await validate(comp('  automaton {\n    initial state s;\n    state s;\n    state s;\n  }'));
        expect(found.filter((f) => f.code === 'automaton/duplicate-state').map((f) => `${f.text}@${f.line}`)).toEqual(['s@4', 's@5']);
    });
    test('substates share the namespace of the automaton', async () => {
        const found = await validate(comp('  automaton {\n    initial state s1;\n    state s2 { initial state s1; };\n  }'));
        expect(found.filter((f) => f.code === 'automaton/duplicate-state').map((f) => `${f.severity}@${f.text}@${f.line}`)).toEqual([
            'error@s1@4',
        ]);
    });
    test('valid: the same state name in two automata', async () => {
        const found = await validate(comp('  automaton { initial state s; }\n  component Inner { automaton { initial state s; } }'));
        expect(hits(found, 'automaton/duplicate-state'), dump(found)).toEqual([]);
    });
});

describe('automaton/missing-state', () => {
    test('missing source and target are both reported on their names', async () => {
        const found = await validate(comp('  automaton {\n    initial state s;\n    s1 -> s2;\n  }'));
        expect(hits(found, 'automaton/missing-state')).toEqual(['automaton/missing-state@s1', 'automaton/missing-state@s2']);
        expect(found.find((f) => f.code === 'automaton/missing-state')!.message).toContain("'s1'");
    });
    test('valid: transitions between states at any depth, in any order', async () => {
        const found = await validate(
            comp('  automaton {\n    a -> bb;\n    bb -> a;\n    initial state a;\n    state b { initial state bb; };\n  }'),
        );
        expect(
            found.filter((f) => f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });
});

describe('automaton/missing-event', () => {
    test('an outgoing port is not an event', async () => {
        const found = await validate(comp(`${ports}\n  automaton {\n    initial state S;\n    S -> S o / o = 1;;\n  }`));
        expect(hits(found, 'automaton/missing-event')).toEqual(['automaton/missing-event@o']);
    });
    test('an unknown name is not an event', async () => {
        const found = await validate(comp(`${ports}\n  automaton {\n    initial state S {\n      -> x / o = 1;;\n    };\n  }`));
        expect(hits(found, 'automaton/missing-event')).toEqual(['automaton/missing-event@x']);
    });
    test('valid: inherited incoming ports are events', async () => {
        const found = await validate({
            'Base.arc': 'component Base {\n  port in int i;\n  port out int o;\n}',
            'Comp.arc': 'component Comp extends Base {\n  automaton {\n    initial state S;\n    S -> S i / { o = i; };\n  }\n}',
        });
        expect(
            found.filter((f) => f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });
});

describe('automaton/guard-not-boolean', () => {
    test('every non-boolean guard is reported on the guard', async () => {
        const found = await validate(comp('  automaton { initial state s; s -> s [1]; s -> s [1 + 2]; }'));
        expect(hits(found, 'automaton/guard-not-boolean')).toEqual(['automaton/guard-not-boolean@1', 'automaton/guard-not-boolean@1 + 2']);
        expect(found.find((f) => f.code === 'automaton/guard-not-boolean')!.message).toMatch(/boolean.*int/);
    });
    test('a parameter of type int is no guard', async () => {
        const found = await validate(comp('  automaton { initial state s; s -> s [p]; }', '(int p)'));
        expect(hits(found, 'automaton/guard-not-boolean')).toEqual(['automaton/guard-not-boolean@p']);
    });
    test('guards of internal transitions are checked', async () => {
        const found = await validate(comp(`${ports}\n  automaton { initial state s { -> [i] / o = 1;; }; }`));
        expect(hits(found, 'automaton/guard-not-boolean')).toEqual(['automaton/guard-not-boolean@i']);
    });
    test('an unresolved name is reported once, as such, not as a non-boolean guard', async () => {
        const found = await validate(comp('  automaton { initial state s; s -> s [nope]; }'));
        expect(found.map((f) => f.code)).toEqual(['expr/unresolved-name']);
        expect(found[0]!.text).toBe('nope');
    });
    test('valid: boolean literals, fields, boxed ports, comparisons', async () => {
        const found = await validate(
            comp(
                '  port in Boolean b;\n  port in int i;\n  boolean v = true;\n  automaton {\n    initial state s;\n    s -> s [true];\n    s -> s [v] i;\n    s -> s [b] b;\n    s -> s [i > 0 && !v] i;\n  }',
            ),
        );
        expect(
            found.filter((f) => f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });
});

describe('automaton/event-in-sync', () => {
    test('a port event in a sync automaton', async () => {
        const found = await validate(comp(`${ports}\n  <<sync>> automaton {\n    initial state S;\n    S -> S i / { o = i; };\n  }`));
        expect(hits(found, 'automaton/event-in-sync')).toEqual(['automaton/event-in-sync@i']);
    });
    test('Tick in a sync automaton', async () => {
        const found = await validate(comp(`${ports}\n  <<sync>> automaton {\n    initial state S;\n    S -> S Tick;\n  }`));
        expect(hits(found, 'automaton/event-in-sync')).toEqual(['automaton/event-in-sync@Tick']);
    });
    test('valid: sync transitions without events', async () => {
        const found = await validate(comp(`${ports}\n  <<sync>> automaton {\n    initial state S;\n    S -> S [i > 0] / { o = i; };\n  }`));
        expect(
            found.filter((f) => f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });
});

describe('automaton/tick-in-untimed', () => {
    test('Tick in an untimed automaton', async () => {
        const found = await validate(comp(`${ports}\n  <<untimed>> automaton {\n    initial state S;\n    S -> S Tick ;\n  }`));
        expect(hits(found, 'automaton/tick-in-untimed')).toEqual(['automaton/tick-in-untimed@Tick']);
    });
    test('valid: Tick in timed automata, explicit or by default', async () => {
        for (const stereo of ['<<timed>> ', '']) {
            const found = await validate(
                comp(
                    `${ports}\n  ${stereo}automaton {\n    initial state S;\n    S -> S Tick / { o = 0; };\n    S -> S i / { o = i; };\n  }`,
                ),
            );
            expect(
                found.filter((f) => f.severity === 'error'),
                dump(found),
            ).toEqual([]);
        }
    });
});

describe('automaton/untimed-no-event', () => {
    test('a transition without event in an untimed automaton: reported on its head', async () => {
        const found = await validate(
            comp(`${ports}\n  <<untimed>> automaton {\n    initial state S;\n    S -> S [i > 0] / { o = i; };\n  }`),
        );
        expect(hits(found, 'automaton/untimed-no-event')).toEqual(['automaton/untimed-no-event@S -> S [i > 0]']);
    });
    test('an internal transition without event', async () => {
        const found = await validate(comp(`${ports}\n  <<untimed>> automaton {\n    initial state S {\n      -> / o = 1;;\n    };\n  }`));
        expect(hits(found, 'automaton/untimed-no-event')).toEqual(['automaton/untimed-no-event@->']);
    });
    test('valid: untimed transitions with port events', async () => {
        const found = await validate(comp(`${ports}\n  <<untimed>> automaton {\n    initial state S;\n    S -> S i / { o = i; };\n  }`));
        expect(
            found.filter((f) => f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });
});

describe('automaton/input-in-initial', () => {
    test('reading an incoming port in an initial block', async () => {
        const found = await validate(comp('  port in int i;\n  automaton { initial { int var = i; } state s; }'));
        expect(hits(found, 'automaton/input-in-initial')).toEqual(['automaton/input-in-initial@i']);
    });
    test('inherited incoming ports, nested initial blocks', async () => {
        const found = await validate({
            'Base.arc': 'component Base {\n  port in int i;\n  port out int o;\n}',
            'Comp.arc':
                'component Comp extends Base {\n  automaton {\n    initial state S {\n      initial { o = i + 1; } state S1;\n    };\n  }\n}',
        });
        expect(hits(found, 'automaton/input-in-initial')).toEqual(['automaton/input-in-initial@i']);
    });
    test('valid: writing outgoing ports, reading fields and parameters, subcomponent ports', async () => {
        const found = await validate(
            comp(
                '  port in int i;\n  port out int o;\n  int f = 1;\n  component Inner { port in int i; }\n  Inner sub;\n  automaton {\n    initial { o = f + p; o = 2; } state s;\n    s -> s Tick / { o = i; };\n  }',
                '(int p)',
            ),
        );
        expect(hits(found, 'automaton/input-in-initial'), dump(found)).toEqual([]);
    });
});

describe('automaton/nondeterministic', () => {
    test('two unguarded tick transitions (Tick and no event) from one state', async () => {
        const found = await validate(
            comp(`${ports}\n  automaton {\n    initial state S;\n    state T;\n    S -> T;\n    S -> S Tick / o = 1;;\n  }`),
        );
        const w = found.filter((f) => f.code === 'automaton/nondeterministic');
        expect(w.map((f) => `${f.severity}@${f.text}@${f.line}`)).toEqual(['warning@S -> S Tick@8']);
        expect(w[0]!.message).toContain("'S -> T'");
        expect(w[0]!.message).toContain('neither has a guard');
    });
    test('one unguarded transition with the same event', async () => {
        const found = await validate(
            comp(`${ports}\n  automaton {\n    initial state S;\n    S -> S [i > 0] i / o = 1;;\n    S -> S i / o = 2;;\n  }`),
        );
        expect(hits(found, 'automaton/nondeterministic')).toEqual(['automaton/nondeterministic@S -> S i']);
    });
    test('identical guards (up to layout), internal and regular transitions', async () => {
        const found = await validate(
            comp(
                `${ports}\n  <<sync>> automaton {\n    initial state S {\n      -> [i>0] / o = 1;;\n    };\n    S -> S [ i > 0 ] / o = 2;;\n  }`,
            ),
        );
        expect(hits(found, 'automaton/nondeterministic')).toEqual(['automaton/nondeterministic@S -> S [ i > 0 ]']);
    });
    test('valid: different guards, events or source states', async () => {
        const found = await validate(
            comp(
                `  port in int i, j;\n  port out int o;\n  automaton {\n    initial state S;\n    state T;\n    S -> T [i > 0] i / o = 1;;\n    S -> S [i <= 0] i / o = 2;;\n    S -> S j / o = 3;;\n    S -> S Tick;\n    T -> S Tick;\n  }`,
            ),
        );
        expect(hits(found, 'automaton/nondeterministic'), dump(found)).toEqual([]);
    });
});

describe('arc/reserved-name for states', () => {
    test('Tick and keywords of the target languages are no state names', async () => {
        const found = await validate(comp('  automaton {\n    initial state Tick;\n    state pass;\n  }'));
        expect(hits(found, 'arc/reserved-name')).toEqual(['arc/reserved-name@Tick', 'arc/reserved-name@pass']);
    });
    test('valid: soft keywords of the automaton language are fine as state names', async () => {
        const found = await validate(comp('  automaton {\n    initial state key;\n    state entry;\n    entry -> key;\n  }'));
        expect(
            found.filter((f) => f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });
});

describe('statements in actions are checked by the host, once', () => {
    test('a type error in an action is reported exactly once', async () => {
        const found = await validate(
            comp(`${ports}\n  automaton {\n    initial { o = true; } state S { entry / o = false; };\n    S -> S / { o = "x"; };\n  }`),
        );
        expect(found.filter((f) => f.code === 'expr/type-mismatch').map((f) => f.line)).toEqual([5, 5, 6]);
    });
});
