import { AstUtils } from 'langium';
import { describe, expect, test } from 'vitest';
import type { ModeAutomaton, ModeTransition } from '../src/generated/ast.js';
import { isDecomposedWithModes, modeConnectors, modesOf, modeSubcomponents, modeTransitionsOf, startMode } from '../src/index.js';
import { build, dump, validate } from './helpers.js';

const PASS = 'component Pass {\n  port in int i;\n  port out int o;\n  <<sync>> compute { o = i; }\n}';
const NEG = 'component Neg {\n  port in int i;\n  port out int o;\n  <<sync>> compute { o = -i; }\n}';
const BOOL = 'component Flag {\n  port in int i;\n  port out boolean o;\n  <<sync>> compute { o = i > 0; }\n}';

function switcher(body: string): Record<string, string> {
    return {
        'Pass.arc': PASS,
        'Neg.arc': NEG,
        'Flag.arc': BOOL,
        'Switch.arc': `component Switch {\n  port in int i;\n  port out int o;\n${body}\n}`,
    };
}

const TWO_MODES =
    '  <<sync>> mode automaton {\n    initial mode Up { Pass p; i -> p.i; p.o -> o; }\n    mode Down { Neg n; i -> n.i; n.o -> o; }\n    Up -> Down [i < 0];\n    Down -> Up [i >= 0];\n  }';

describe('mode automata', () => {
    test('parse into modes with their subcomponents, connectors and transitions', async () => {
        const { docs } = await build(switcher(TWO_MODES));
        const doc = docs.find((d) => d.uri.path.endsWith('/Switch.arc'))!;
        const a = AstUtils.streamAst(doc.parseResult.value).find((n): n is ModeAutomaton => n.$type === 'ModeAutomaton')!;
        expect(modesOf(a).map((m) => m.name)).toEqual(['Up', 'Down']);
        expect(startMode(a)?.name).toBe('Up');
        expect(modesOf(a).map((m) => modeSubcomponents(m).map((s) => s.name))).toEqual([['p'], ['n']]);
        expect(modeConnectors(modesOf(a)[1]!).map((c) => c.$cstNode?.text)).toEqual(['i -> n.i;', 'n.o -> o;']);
        const ts: ModeTransition[] = modeTransitionsOf(a);
        expect(ts.map((t) => `${t.source.ref?.name}->${t.target.ref?.name}`)).toEqual(['Up->Down', 'Down->Up']);
        const comp = AstUtils.streamAst(doc.parseResult.value).find((n) => n.$type === 'ComponentType')!;
        expect(isDecomposedWithModes(comp as never)).toBe(true);
    });

    test('a valid model with two modes driving the same out port has no errors', async () => {
        const found = await validate(switcher(TWO_MODES));
        expect(
            found.filter((f) => f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });

    test("a mode's connectors see its own subcomponents and the shared ones, not another mode's", async () => {
        const found = await validate(
            switcher(
                '  Pass shared;\n  i -> shared.i;\n  <<sync>> mode automaton {\n    initial mode Up { Pass p; shared.o -> p.i; p.o -> o; }\n    mode Down { n.o -> o; }\n  }',
            ),
        );
        const links = found.filter((f) => f.code.startsWith('link/') || f.code === 'arc/missing-subcomponent');
        expect(
            links.map((f) => f.text),
            dump(found),
        ).toEqual(['n']);
    });

    test('mode transitions name modes of their automaton (automaton/missing-state otherwise)', async () => {
        const found = await validate(switcher(TWO_MODES.replace('Down -> Up', 'Down -> Sideways')));
        expect(
            found.filter((f) => f.code === 'automaton/missing-state').map((f) => f.text),
            dump(found),
        ).toEqual(['Sideways']);
    });

    test('guards are boolean and sync mode transitions take no event', async () => {
        const found = await validate(switcher(TWO_MODES.replace('[i < 0]', '[i - 1] i')));
        expect(
            found
                .filter((f) => f.severity === 'error')
                .map((f) => f.code)
                .sort(),
            dump(found),
        ).toEqual(['automaton/event-in-sync', 'automaton/guard-not-boolean']);
    });

    test('connectors in a mode: directions, types and one sender per port in that mode', async () => {
        const found = await validate(
            switcher('  <<sync>> mode automaton {\n    initial mode Up { Pass p; Flag f; o -> p.i; i -> f.i; f.o -> o; p.o -> o; }\n  }'),
        );
        expect(
            found
                .filter((f) => f.severity === 'error')
                .map((f) => f.code)
                .sort(),
            dump(found),
        ).toEqual(['arc/connector-type-mismatch', 'arc/multiple-senders', 'arc/source-direction-mismatch']);
    });

    test('duplicate mode names are reported', async () => {
        const found = await validate(switcher(TWO_MODES.replace('mode Down', 'mode Up')));
        expect(found.filter((f) => f.code === 'automaton/duplicate-state').length, dump(found)).toBe(1);
    });

    test('a mode automaton is no second behavior of its component', async () => {
        const found = await validate(switcher(`${TWO_MODES}\n  <<sync>> compute { }`));
        expect(
            found.filter((f) => f.code === 'arc/multiple-behaviors'),
            dump(found),
        ).toEqual([]);
    });

    test('mode and final stay usable as names', async () => {
        const found = await validate({
            'Comp.arc': 'component Comp {\n  port in int mode, out int final;\n  <<sync>> compute { final = mode; }\n}',
        });
        expect(
            found.filter((f) => f.code.startsWith('syntax/')),
            dump(found),
        ).toEqual([]);
    });
});

describe('connectedness with modes', () => {
    test('ports connected only in a mode count as connected (shared subcomponents, out ports)', async () => {
        const found = await validate(
            switcher(
                '  Pass always;\n  i -> always.i;\n  <<sync>> mode automaton {\n    initial mode Up { Pass p; always.o -> p.i; p.o -> o; }\n    mode Down { Neg n; always.o -> n.i; n.o -> o; }\n  }',
            ),
        );
        expect(
            found.filter((f) => f.code.startsWith('arc/unconnected') || f.code.startsWith('arc/unused')),
            dump(found),
        ).toEqual([]);
    });

    test('a port of a shared subcomponent connected in no mode is still reported', async () => {
        const found = await validate(
            switcher('  Pass always;\n  <<sync>> mode automaton {\n    initial mode Up { Pass p; i -> p.i; p.o -> o; }\n  }'),
        );
        expect(
            found.filter((f) => f.code === 'arc/unconnected-sub-in-port').map((f) => f.text),
            dump(found),
        ).toEqual(['always']);
    });
});

describe('partial input', () => {
    test.each([
        '  <<sync>> mode automaton {\n    initial mode',
        '  <<sync>> mode automaton {\n    initial mode A { Pass p; -> p.i; }\n    A -> ;\n  }',
        '  <<sync>> mode automaton {\n    mode { i -> }\n    -> B [;\n  }',
        '  mode automaton { initial mode A { port in int; } A -> A Tick / o = ; }',
    ])('gives diagnostics, never a failed check: %s', async (body) => {
        const found = await validate(switcher(body));
        expect(
            found.filter((f) => f.code === 'internal/check-failed'),
            dump(found),
        ).toEqual([]);
        expect(found.length).toBeGreaterThan(0);
    });
});

describe('subcomponent names', () => {
    test('are unique across the component and all its modes (arc/duplicate-name)', async () => {
        const found = await validate(
            switcher(
                '  Pass p;\n  i -> p.i;\n  <<sync>> mode automaton {\n    initial mode Up { Pass q; p.o -> q.i; q.o -> o; }\n    mode Down { Pass p; Neg q; p.o -> q.i; q.o -> o; }\n  }',
            ),
        );
        expect(
            found
                .filter((f) => f.code === 'arc/duplicate-name')
                .map((f) => f.text)
                .sort(),
            dump(found),
        ).toEqual(['p', 'q']);
    });

    test('distinct names in different modes are fine', async () => {
        const found = await validate(switcher(TWO_MODES));
        expect(
            found.filter((f) => f.code === 'arc/duplicate-name'),
            dump(found),
        ).toEqual([]);
    });
});
