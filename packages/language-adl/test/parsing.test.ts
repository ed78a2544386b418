import { EmptyFileSystem, URI } from 'langium';
import { describe, expect, test } from 'vitest';
import { allPorts, createAdlServices, subcomponentsOf, type ast } from '../src/index.js';
import { validate } from './helpers.js';

const files = {
    'robot/types/Types.cd': `package robot.types;
classdiagram Types {
  enum Mode { IDLE, RUN; }
  abstract class Shape { double area; }
  class Pair<A, B> extends Object { A first; B second; }
  association [1] Shape -> (parts) Shape [*];
}`,
    'robot/Base.arc': `package robot;
component Base<T extends Number>(T gain, int n = 2) {
  port <<sync>> in T x,
       <<sync, delayed>> out double y;
}`,
    'robot/Robot.arc': `package robot;
import robot.types.Types.*;
import robot.types.Mode;

/* every construct of the host language in one model */
<<handwritten>> component Robot(int k = 3) extends Base<Integer>(1, n = 4) {
  port <<sync>> in int a, b, <<timed>> out Mode m;
  port in Pair<Integer, String> p;
  port in int[] samples;
  int f = k * 2, g = 0;
  component Inner(int s) inner(1) {
    port <<sync>> in int i;
    port <<sync>> out double o;
    compute { o = i + s; }
  }
  Base<Double> b1(1.5), b2(gain = 2.0, n = 1);
  a -> inner.i;
  inner.o -> b1.x;
  b1.y -> b2.x;
}`,
};

describe('the host language parses', () => {
    test('a model with every construct, without errors', async () => {
        const found = await validate(files);
        expect(found.filter((f) => f.severity === 'error')).toEqual([]);
    });

    test('into the expected structure', async () => {
        const services = createAdlServices(EmptyFileSystem);
        const root = URI.file('/parse-root');
        services.shared.maa.ModelRoots.setRoots([root]);
        const docs = Object.entries(files).map(([p, t]) =>
            services.shared.workspace.LangiumDocuments.createDocument(URI.file(`/parse-root/${p}`), t),
        );
        await services.shared.workspace.DocumentBuilder.build(docs, {});
        const model = docs[2]!.parseResult.value as ast.ArcModel;
        const robot = model.component!;
        expect(model.package).toBe('robot');
        expect(model.imports.map((i) => i.importedNamespace)).toEqual(['robot.types.Types.*', 'robot.types.Mode']);
        expect(robot.stereotype?.values.map((v) => v.name)).toEqual(['handwritten']);
        expect(robot.params.map((p) => [p.name, p.default?.$cstNode?.text])).toEqual([['k', '3']]);
        expect(robot.parents[0]!.type.ref.ref?.name).toBe('Base');
        expect(robot.parents[0]!.args.map((a) => a.$cstNode?.text)).toEqual(['1', 'n = 4']);
        const ports = allPorts(robot).map(
            (p) => `${p.direction} ${p.name}:${p.timing}${p.delayed ? ':delayed' : ''}${p.owner === robot ? '' : ':inherited'}`,
        );
        expect(ports).toEqual([
            'in a:sync',
            'in b:sync',
            'out m:timed',
            'in p:timed',
            'in samples:timed',
            'in x:sync:inherited',
            'out y:sync:delayed:inherited',
        ]);
        expect(subcomponentsOf(robot).map((s) => s.name)).toEqual(['inner', 'b1', 'b2']);
        const fields = robot.body.elements
            .filter((e): e is ast.FieldDeclaration => e.$type === 'FieldDeclaration')
            .flatMap((d) => d.fields.map((f) => f.name));
        expect(fields).toEqual(['f', 'g']);
        const inner = robot.body.elements.find((e): e is ast.ComponentType => e.$type === 'ComponentType')!;
        expect(inner.params.map((t) => t.name)).toEqual(['s']);
        expect(inner.body.elements.some((e) => e.$type === 'BehaviorDeclaration')).toBe(true);
        const cd = docs[0]!.parseResult.value as ast.CDModel;
        expect(cd.diagram.elements.map((e) => e.$type)).toEqual(['CDEnum', 'CDClass', 'CDClass', 'CDAssociation']);
    });

    test('statements and expressions of compute blocks', async () => {
        const found = await validate({
            'Calc.arc': `component Calc {
  port in int i;
  port out int o;
  int acc = 0;
  compute {
    int t = i << 2;
    for (int j = 0; j < 3; j++) { acc += j; }
    while (acc > 100) acc -= 10;
    if (i >= 0 && !(i == 5)) { o = i > 2 ? t : -t; } else o = Math.abs(i) >> 1;
    ;
  }
}`,
        });
        expect(found.filter((f) => f.severity === 'error')).toEqual([]);
    });
});
