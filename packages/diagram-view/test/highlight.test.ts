// The highlight of a run's trace point (issue 19, maa.diagram.highlightTrace): the argument is
// checked, and the live layer finds the highlighted instance in C&C views (also of a subcomponent
// shown on its own, under its prefix) and the highlighted automaton by its component type.
import { describe, expect, it } from 'vitest';
import { parseHighlight } from '../src/highlight.js';
import { LiveLayer } from '../src/live-layer.js';
import type { SchemaElement } from '../src/schema.js';
import { fitText } from '../src/view-parts.js';

const app: SchemaElement = {
    type: 'graph',
    id: 'g',
    component: 'toast.ToastServiceRobot',
    children: [
        {
            type: 'node:component',
            id: 'root',
            instancePath: '',
            componentType: 'toast.ToastServiceRobot',
            children: [{ type: 'node:component', id: 'root.ctrl', instancePath: 'ctrl', componentType: 'toast.Controller', children: [] }],
        },
    ],
};
const controllerAlone: SchemaElement = {
    type: 'graph',
    id: 'g2',
    component: 'toast.Controller',
    children: [{ type: 'node:component', id: 'root', instancePath: '', componentType: 'toast.Controller', children: [] }],
};

const point = {
    component: 'toast.Controller',
    instancePath: 'ctrl',
    state: 'Serving',
    transition: { from: 'Toasting', to: 'Serving', index: 3 },
};

describe('parseHighlight', () => {
    it('accepts the contract’s argument, with and without state and transition, and undefined (clear)', () => {
        expect(parseHighlight(point)).toEqual(point);
        expect(parseHighlight({ component: 'toast.Controller', instancePath: '' })).toEqual({
            component: 'toast.Controller',
            instancePath: '',
        });
        expect(parseHighlight(undefined)).toBeUndefined();
        expect(parseHighlight(null)).toBeUndefined();
    });

    it('rejects anything else with what is wrong', () => {
        expect(() => parseHighlight('ctrl')).toThrow(/expected an object/);
        expect(() => parseHighlight({ instancePath: 'ctrl' })).toThrow(/component/);
        expect(() => parseHighlight({ component: 'a.B', instancePath: 3 })).toThrow(/instancePath/);
        expect(() => parseHighlight({ component: 'a.B', instancePath: '', state: 1 })).toThrow(/state/);
        expect(() => parseHighlight({ ...point, transition: { from: 'A', to: 'B', index: -1 } })).toThrow(/index/);
        expect(() => parseHighlight({ ...point, transition: { from: 'A', to: 'B', index: 1.5 } })).toThrow(/index/);
        expect(() => parseHighlight({ ...point, transition: { from: 'A', index: 1 } })).toThrow(/from and .to/);
    });
});

describe('the live layer’s highlight', () => {
    it('names the highlighted instance in a C&C view and the highlighted automaton by its type, until cleared', () => {
        const live = new LiveLayer();
        live.recordModel(app, 'maa-cc', 'toast.ToastServiceRobot');
        expect(live.highlightOf('ctrl')).toBeUndefined();
        live.setHighlight(parseHighlight(point));
        expect(live.highlightOf('ctrl')?.state).toBe('Serving');
        expect(live.highlightOf('')).toBeUndefined();
        expect(live.highlightOf(undefined)).toBeUndefined();
        expect(live.highlightForType('toast.Controller')?.transition?.index).toBe(3);
        expect(live.highlightForType('toast.ToasterController')).toBeUndefined();
        // The Controller's diagram on its own: its root is the instance `ctrl` of the application.
        live.recordModel(controllerAlone, 'maa-cc', 'toast.Controller');
        expect(live.highlightOf('')?.state).toBe('Serving');
        live.setHighlight(undefined);
        expect(live.highlightOf('')).toBeUndefined();
        expect(live.highlightForType('toast.Controller')).toBeUndefined();
    });
});

describe('fitText', () => {
    it('keeps a text that fits and cuts a longer one short with an ellipsis', () => {
        expect(fitText('12', 60, 6)).toBe('12');
        expect(fitText('0123456789ABCDEF', 60, 6)).toBe('012345678…');
        expect(fitText('0123456789ABCDEF', 60, 6).length).toBe(10);
    });
});
