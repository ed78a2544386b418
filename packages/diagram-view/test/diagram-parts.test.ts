import { describe, expect, it } from 'vitest';
import { SelectAction, type Action } from 'sprotty-protocol';
import type { DiagramTarget } from '../src/contracts.js';
import { ALL_VARIATION_POINTS } from '../src/configuration.js';
import { LiveLayer } from '../src/live-layer.js';
import type { SchemaElement } from '../src/schema.js';
import { elementAt, selectionHandler, tracesOf } from '../src/selection.js';
import { standaloneSvg, svgFileName } from '../src/svg-export.js';
import { TargetMemory, targetKey } from '../src/target-memory.js';

const URI = 'file:///workspace/toast/ToastServiceRobot.arc';

/** A C&C diagram of `component` with instance `ctrl` (a `toast.Controller`) and port paths. */
function cc(component: string, ctrlType = 'toast.Controller'): SchemaElement {
    return {
        type: 'graph',
        id: 'g',
        component,
        children: [
            {
                type: 'node:component',
                id: 'root',
                instancePath: '',
                componentType: component,
                trace: `${URI}?0:0-20:0`,
                children: [
                    { type: 'port', id: 'root.p.distance', portPath: 'distance', trace: `${URI}?2:4-2:20` },
                    {
                        type: 'node:component',
                        id: 'ctrl',
                        instancePath: 'ctrl',
                        componentType: ctrlType,
                        trace: `${URI}?5:4-5:30`,
                        children: [
                            { type: 'port', id: 'ctrl.p.armCmd', portPath: 'ctrl.armCmd', trace: `${URI}?5:10-5:16` },
                            { type: 'label:text', id: 'ctrl.label', trace: `${URI}?5:4-5:30` },
                        ],
                    },
                ],
            },
        ],
    };
}

/** The C&C diagram of `toast.Controller` shown on its own (no instances of its own). */
function controllerAlone(): SchemaElement {
    return {
        type: 'graph',
        id: 'g2',
        component: 'toast.Controller',
        children: [
            {
                type: 'node:component',
                id: 'c',
                instancePath: '',
                componentType: 'toast.Controller',
                children: [{ type: 'port', id: 'c.p', portPath: 'armCmd' }],
            },
        ],
    };
}

describe('diagram live layer', () => {
    it('finds live values by exact path, by snake-case spelling, and below the prefix of a subcomponent shown alone', () => {
        const live = new LiveLayer();
        live.recordModel(cc('toast.ToastServiceRobot'), 'maa-cc', 'toast.ToastServiceRobot');
        expect(live.liveValue('ctrl.armCmd')).toBeUndefined();
        live.setLiveValues(
            new Map([
                ['ctrl.arm_cmd', '0.5'],
                ['distance', '3'],
            ]),
        );
        expect(live.liveValue('ctrl.armCmd')).toBe('0.5');
        expect(live.liveValue('distance')).toBe('3');
        expect(live.liveValue('armCmd')).toBeUndefined();
        expect(live.liveValue(undefined)).toBeUndefined();
        live.recordModel(controllerAlone(), 'maa-cc', 'toast.Controller');
        expect(live.liveValue('armCmd')).toBe('0.5');
        live.setLiveValues(new Map());
        expect(live.liveValue('armCmd')).toBeUndefined();
    });

    it('finds active states by instance path, for the shown component under its prefix, and by automaton type', () => {
        const live = new LiveLayer();
        live.recordModel(cc('toast.ToastServiceRobot'), 'maa-cc', 'toast.ToastServiceRobot');
        expect(live.activeStateOf('ctrl')).toBeUndefined();
        live.setActiveStates(
            new Map([
                ['ctrl', 'Toasting'],
                ['', 'Normal'],
            ]),
        );
        expect(live.activeStateOf('ctrl')).toBe('Toasting');
        expect(live.activeStateOf('')).toBe('Normal');
        expect(live.activeStateOf(undefined)).toBeUndefined();
        expect(live.activeStateForType('toast.Controller')).toBe('Toasting');
        live.recordModel(controllerAlone(), 'maa-cc', 'toast.Controller');
        expect(live.activeStateOf('')).toBe('Normal'); // an exact path wins
        live.setActiveStates(new Map([['ctrl', 'Toasting']]));
        expect(live.activeStateOf('')).toBe('Toasting');
        live.setActiveStates(new Map());
        expect(live.activeStateForType('toast.Controller')).toBeUndefined();
    });

    it('copies what it is given', () => {
        const live = new LiveLayer();
        const values = new Map([['distance', '1']]);
        live.setLiveValues(values);
        values.set('distance', '2');
        expect(live.liveValue('distance')).toBe('1');
    });
});

describe('diagram target memory', () => {
    const a: DiagramTarget = { uri: URI, diagramType: 'maa-cc' };
    const b: DiagramTarget = { uri: URI, diagramType: 'maa-cc', component: 'toast.Controller' };
    it('keys targets by type, file and component', () => {
        expect(targetKey(a)).not.toBe(targetKey(b));
        expect(targetKey({ ...a, diagramType: 'maa-automaton' })).not.toBe(targetKey(a));
        expect(targetKey({ ...a })).toBe(targetKey(a));
    });
    it('remembers expanded instances and feature selections per target', () => {
        const m = new TargetMemory();
        m.toggleExpanded(a, 'ctrl');
        m.toggleExpanded(a, 'arm');
        m.toggleExpanded(a, 'arm');
        expect([...m.expandedOf(a)]).toEqual(['ctrl']);
        expect([...m.expandedOf(b)]).toEqual([]);
        expect(m.selectionOf(a)).toBe(ALL_VARIATION_POINTS);
        m.setSelection(b, { all: false, chosen: { fast: true } });
        expect(m.selectionOf(b)).toEqual({ all: false, chosen: { fast: true } });
        expect(m.selectionOf(a)).toBe(ALL_VARIATION_POINTS);
    });
});

describe('diagram selection', () => {
    it('finds the innermost selectable element at a position (labels and the root do not count)', () => {
        expect(elementAt(cc('toast.ToastServiceRobot'), URI, { line: 5, character: 12 })).toBe('ctrl.p.armCmd');
        expect(elementAt(cc('toast.ToastServiceRobot'), URI, { line: 5, character: 25 })).toBe('ctrl');
        expect(elementAt(cc('toast.ToastServiceRobot'), URI, { line: 10, character: 0 })).toBe('root');
        expect(elementAt(cc('toast.ToastServiceRobot'), URI, { line: 30, character: 0 })).toBeUndefined();
        expect(elementAt(cc('toast.ToastServiceRobot'), 'file:///workspace/other.arc', { line: 5, character: 12 })).toBeUndefined();
    });

    it('hands the traces of a user selection on; its own selections and empty ones are ignored', () => {
        const got: string[][] = [];
        const own = new WeakSet<Action>();
        let schema: SchemaElement | undefined;
        const handler = selectionHandler(
            () => schema,
            (act) => own.has(act),
            (t) => got.push(t),
        );
        handler.handle(SelectAction.create({ selectedElementsIDs: ['ctrl'] }));
        expect(got).toEqual([]); // no model yet
        schema = cc('toast.ToastServiceRobot');
        handler.handle(SelectAction.create({ selectedElementsIDs: ['ctrl.p.armCmd', 'ctrl'] }));
        handler.handle(SelectAction.create({ selectedElementsIDs: [] }));
        const mine = SelectAction.create({ selectedElementsIDs: ['root'] });
        own.add(mine);
        handler.handle(mine);
        handler.handle({ kind: 'center' });
        expect(got).toEqual([[`${URI}?5:4-5:30`, `${URI}?5:10-5:16`]]);
        expect(tracesOf(schema, new Set(['nothing']))).toEqual([]);
    });
});

describe('diagram SVG export', () => {
    it('makes a standalone document', () => {
        expect(standaloneSvg('<svg width="1"></svg>')).toBe(
            '<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="1"></svg>',
        );
        const done = '<?xml version="1.0"?><svg xmlns="http://www.w3.org/2000/svg"/>';
        expect(standaloneSvg(done)).toBe(done);
    });
    it('names the file after the component and the view', () => {
        expect(svgFileName('toast.Controller', { uri: URI, diagramType: 'maa-automaton' })).toBe('Controller-automaton.svg');
        expect(svgFileName('toast.ToastServiceRobot', { uri: URI, diagramType: 'maa-cc' })).toBe('ToastServiceRobot.svg');
        expect(svgFileName(undefined, undefined)).toBe('diagram.svg');
    });
});
