// No text of a laid-out C&C diagram covers another (issue 19): the boxes of a component's name,
// type, badge, expand button, port names, the rooms of live values and of the current-state chip
// (drawn during a run), and behavior lines, computed from the language server's model with the
// real ELK layout, for the example and for the benchmark's 200-component model. Every port values
// flow out of has the room of its value, and every component with an automaton or modes the room
// of its chip, so that a run's decorations cannot cover anything either.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, test } from 'vitest';
import type { SModelElement, SModelRoot } from 'sprotty-protocol';
import { generateModels, writeSystemComponent } from '../../cli/bench/generate-models.mjs';
import { EXPAND_TOGGLE_ROOM } from '../src/diagram/layout.js';
import { diagramWorkspace, exampleFiles, TestClient, type DiagramWorkspace } from './diagram-helpers.js';

type Element = SModelElement & Record<string, unknown>;
interface Box {
    x: number;
    y: number;
    width: number;
    height: number;
}
interface TextBox {
    id: string;
    box: Box;
}

const size = (e: Element): { width: number; height: number } =>
    (e.size as { width: number; height: number } | undefined) ?? { width: 0, height: 0 };
const pos = (e: Element): { x: number; y: number } => (e.position as { x: number; y: number } | undefined) ?? { x: 0, y: 0 };
const children = (e: Element): Element[] => (e.children ?? []) as Element[];
const isLabel = (e: Element): boolean => String(e.type).startsWith('label');

function intersect(a: Box, b: Box, tolerance = 0.5): boolean {
    return (
        a.x + a.width - tolerance > b.x &&
        b.x + b.width - tolerance > a.x &&
        a.y + a.height - tolerance > b.y &&
        b.y + b.height - tolerance > a.y
    );
}

function inside(inner: Box, outer: Box): boolean {
    return (
        inner.x >= outer.x - 0.5 &&
        inner.y >= outer.y - 0.5 &&
        inner.x + inner.width <= outer.x + outer.width + 0.5 &&
        inner.y + inner.height <= outer.y + outer.height + 0.5
    );
}

/** The text boxes a component node draws (absolute, its origin at `origin`): its labels, its ports' labels, the expand button. */
function textBoxes(node: Element, origin: { x: number; y: number }): TextBox[] {
    const out: TextBox[] = [];
    for (const c of children(node)) {
        if (isLabel(c)) out.push({ id: c.id, box: { x: origin.x + pos(c).x, y: origin.y + pos(c).y, ...size(c) } });
        if (c.type !== 'port') continue;
        for (const l of children(c).filter(isLabel))
            out.push({ id: l.id, box: { x: origin.x + pos(c).x + pos(l).x, y: origin.y + pos(c).y + pos(l).y, ...size(l) } });
    }
    // The client's expand/collapse button of a composed subcomponent (component-view.ts: x w-20, y 20, 14 x 14).
    if (node.composed && node.instancePath)
        out.push({ id: `${node.id}#expand`, box: { x: origin.x + size(node).width - 20, y: origin.y + 20, width: 14, height: 14 } });
    return out;
}

/** Texts that cover each other or leave their node, rooms for a run's decorations that are missing. */
function textProblems(root: SModelRoot): string[] {
    const problems: string[] = [];
    const visit = (node: Element, origin: { x: number; y: number }, isRoot: boolean): TextBox[] => {
        const here = { x: origin.x + pos(node).x, y: origin.y + pos(node).y };
        const box = { ...here, ...size(node) };
        const texts = textBoxes(node, here);
        const subs = children(node).filter((c) => c.type === 'node:component');
        const open = subs.length > 0;
        for (const [i, t] of texts.entries()) {
            if (!inside(t.box, box)) problems.push(`${t.id} leaves ${node.id}`);
            for (const u of texts.slice(i + 1)) if (intersect(t.box, u.box)) problems.push(`${t.id} covers ${u.id}`);
        }
        // Rooms for a run: the chip of an automaton or mode automaton, the values of the ports values flow out of.
        if ((node.behaviorKind === 'automaton' || node.modeAutomaton) && !children(node).some((c) => c.type === 'label:chip'))
            problems.push(`${node.id} has no room for its current state`);
        for (const p of children(node).filter((c) => c.type === 'port')) {
            const source = isRoot ? p.direction === 'in' || !open : p.direction === 'out';
            if (source && !children(p).some((c) => c.type === 'label:value')) problems.push(`${p.id} has no room for its live value`);
        }
        const subTexts = subs.map((s) => ({ sub: s, texts: visit(s, here, false) }));
        // A child's box covers none of this node's texts; siblings' texts cover neither each other nor the siblings.
        for (const { sub, texts: inner } of subTexts) {
            const b = { x: here.x + pos(sub).x, y: here.y + pos(sub).y, ...size(sub) };
            for (const t of texts) if (intersect(t.box, b)) problems.push(`${t.id} is covered by ${sub.id}`);
            for (const { sub: other, texts: theirs } of subTexts) {
                if (other === sub) continue;
                const ob = { x: here.x + pos(other).x, y: here.y + pos(other).y, ...size(other) };
                for (const t of inner) if (intersect(t.box, ob)) problems.push(`${t.id} is covered by ${other.id}`);
                if (other.id > sub.id)
                    for (const t of inner) for (const u of theirs) if (intersect(t.box, u.box)) problems.push(`${t.id} covers ${u.id}`);
            }
        }
        return texts;
    };
    for (const top of children(root as Element).filter((c) => c.type === 'node:component')) visit(top, { x: 0, y: 0 }, true);
    return problems;
}

async function ccModel(ws: DiagramWorkspace, file: string, extra: Record<string, unknown> = {}): Promise<SModelRoot> {
    return new TestClient(ws.diagrams).requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri(file), needsClientLayout: false, ...extra });
}

describe('texts of the laid-out C&C diagram', () => {
    test('of the example: every component shown on its own and the application, no text covers another', async () => {
        const ws = await diagramWorkspace();
        const files = Object.keys(exampleFiles()).filter((f) => f.endsWith('.arc'));
        const problems: string[] = [];
        for (const file of files) for (const p of textProblems(await ccModel(ws, file))) problems.push(`${file}: ${p}`);
        expect(problems).toEqual([]);
        expect(EXPAND_TOGGLE_ROOM).toBeGreaterThanOrEqual(14 + 6);
    }, 120_000);

    test('a broken layout is caught: a port name moved onto the type name', async () => {
        const ws = await diagramWorkspace();
        const m = await ccModel(ws, 'toast/ToastServiceRobot.arc');
        expect(textProblems(m)).toEqual([]);
        const ctrl = children(children(m as Element)[0]!).find((c) => c.id === 'root.ctrl')!;
        const port = children(ctrl).find((c) => c.type === 'port')!;
        const label = children(port).find((c) => c.type === 'label:port')!;
        label.position = { x: 10, y: 20 - pos(port).y }; // over the type (y 20 of the node)
        expect(textProblems(m).some((p) => p.includes(`${label.id} covers`) || p.includes(`covers ${label.id}`))).toBe(true);
    });

    describe('of the benchmark model with 200 subcomponents', () => {
        const dir = mkdtempSync(join(tmpdir(), 'maa-diagram-200-'));
        afterAll(() => rmSync(dir, { recursive: true, force: true }));

        test('System and one composed and one atomic component shown on their own: no text covers another', async () => {
            const gen = generateModels(dir, 200);
            writeSystemComponent(dir, gen);
            const files = exampleFiles(dir);
            const ws = await diagramWorkspace(files);
            const composed = Object.keys(files).find((f) => /\/C\d+_\d+\.arc$/.test(f))!;
            const atomic = Object.keys(files).find((f) => /\/A\d+_\d+\.arc$/.test(f))!;
            for (const file of ['robot/System.arc', composed, atomic]) {
                const m = await ccModel(ws, file);
                expect(children(children(m as Element)[0]!).filter((c) => c.type === 'node:component').length, file).toBeGreaterThan(
                    file === atomic ? -1 : 0,
                );
                expect(textProblems(m), file).toEqual([]);
            }
        }, 300_000);
    });
});
