import { describe, expect, it } from 'vitest';
import {
    absoluteBounds,
    activeStateForType,
    instancePrefix,
    boundsInside,
    instanceOfType,
    instanceTypesOf,
    lookupLiveValue,
    normalizeSchemaTypes,
    portPathsOf,
    registeredType,
    shownComponentNode,
    snakePath,
    stateActivity,
    visibleArea,
    walkSchema,
    type SchemaElement,
} from '../src/schema.js';

function model(): SchemaElement {
    return {
        type: 'graph',
        id: 'g',
        component: 'toast.ToastServiceRobot',
        children: [
            {
                type: 'node:component',
                id: 'root',
                instancePath: '',
                componentType: 'toast.ToastServiceRobot',
                behaviorKind: 'composed',
                position: { x: 10, y: 20 },
                size: { width: 500, height: 300 },
                children: [
                    {
                        type: 'label:name',
                        id: 'root.label',
                        text: 'ToastServiceRobot',
                        position: { x: 5, y: 5 },
                        size: { width: 100, height: 14 },
                    },
                    {
                        type: 'port',
                        id: 'root.p.distance',
                        portPath: 'distance',
                        direction: 'in',
                        position: { x: -4, y: 40 },
                        size: { width: 8, height: 8 },
                    },
                    {
                        type: 'node:component',
                        id: 'ctrl',
                        instancePath: 'ctrl',
                        componentType: 'toast.Controller',
                        behaviorKind: 'automaton',
                        position: { x: 100, y: 50 },
                        size: { width: 120, height: 60 },
                        children: [
                            {
                                type: 'port',
                                id: 'ctrl.p.armCmd',
                                portPath: 'ctrl.armCmd',
                                direction: 'out',
                                position: { x: 116, y: 20 },
                                size: { width: 8, height: 8 },
                            },
                        ],
                    },
                    { type: 'edge:connector', id: 'e1', sourcePortPath: 'ctrl.armCmd' },
                    { type: 'comp:header', id: 'h' },
                ],
            },
        ],
    };
}

describe('schema helpers', () => {
    it('maps unknown types to registered ones and keeps the original', () => {
        expect(registeredType('node:component')).toBe('node:component');
        expect(registeredType('label:badge')).toBe('label:text');
        expect(registeredType('comp:header')).toBe('comp:default');
        expect(registeredType('node:pseudo')).toBe('node:generic');
        expect(registeredType('edge:x')).toBe('edge:generic');
        expect(registeredType('port:in')).toBe('port');
        const m = normalizeSchemaTypes(model());
        const label = [...walkSchema(m)].find((x) => x.el.id === 'root.label')!.el;
        expect(label.type).toBe('label:text');
        expect(label['maaType']).toBe('label:name');
        expect([...walkSchema(m)].find((x) => x.el.id === 'ctrl')!.el['maaType']).toBeUndefined();
    });
    it('walks depth first with depths', () => {
        const ids = [...walkSchema(model())].map((x) => `${x.el.id}@${x.depth}`);
        expect(ids.slice(0, 5)).toEqual(['g@0', 'root@1', 'root.label@2', 'root.p.distance@2', 'ctrl@2']);
        expect(ids).toContain('ctrl.p.armCmd@3');
    });
    it('adds up positions to absolute bounds', () => {
        expect(absoluteBounds(model(), 'ctrl.p.armCmd')).toEqual({ x: 226, y: 90, width: 8, height: 8 });
        expect(absoluteBounds(model(), 'e1')).toBeUndefined();
        expect(absoluteBounds(model(), 'missing')).toBeUndefined();
        const vis = visibleArea({ scroll: { x: 0, y: 0 }, zoom: 2 }, { width: 400, height: 200 });
        expect(vis).toEqual({ x: 0, y: 0, width: 200, height: 100 });
        expect(boundsInside({ x: 10, y: 10, width: 5, height: 5 }, vis)).toBe(true);
        expect(boundsInside({ x: 226, y: 90, width: 8, height: 8 }, vis)).toBe(false);
    });
    it('collects port paths, instance types and the shown component', () => {
        expect(portPathsOf(model())).toEqual(['distance', 'ctrl.armCmd']);
        expect([...instanceTypesOf(model())]).toEqual([
            ['', 'toast.ToastServiceRobot'],
            ['ctrl', 'toast.Controller'],
        ]);
        expect(shownComponentNode(model())?.id).toBe('root');
        expect(instanceOfType(instanceTypesOf(model()), 'toast.Controller')).toBe('ctrl');
        expect(instanceOfType(instanceTypesOf(model()), 'other.Controller')).toBe('ctrl');
        expect(instanceOfType(instanceTypesOf(model()), 'toast.Nope')).toBeUndefined();
    });
    it('relates states to the active state path', () => {
        expect(stateActivity('Toasting', 'Toasting')).toBe('active');
        expect(stateActivity('Outer', 'Outer.Inner')).toBe('ancestor');
        expect(stateActivity('Outer.Inner', 'Inner')).toBe('active');
        expect(stateActivity('Out', 'Outer.Inner')).toBe('none');
        expect(stateActivity(undefined, 'A')).toBe('none');
    });
    it('looks live values up by exact or snake-case path', () => {
        const values = new Map([
            ['ctrl.arm_cmd', '3'],
            ['distance', '22'],
        ]);
        const bySnake = new Map([...values].map(([k, v]) => [snakePath(k), v]));
        expect(lookupLiveValue(values, bySnake, 'ctrl.armCmd')).toBe('3');
        expect(lookupLiveValue(values, bySnake, 'distance')).toBe('22');
        expect(lookupLiveValue(values, bySnake, 'x')).toBeUndefined();
        expect(lookupLiveValue(values, bySnake, undefined)).toBeUndefined();
        expect(snakePath('sensorUnit.rawValue')).toBe('sensor_unit.raw_value');
    });
    it('finds a component in other diagrams and the state of its automaton', () => {
        const maps = new Map([
            ['toast.ToastServiceRobot', instanceTypesOf(model())],
            ['toast.Controller', new Map([['', 'toast.Controller']])],
        ]);
        expect(instancePrefix(maps, 'toast.Controller')).toBe('ctrl');
        expect(instancePrefix(maps, 'toast.ToastServiceRobot')).toBeUndefined();
        expect(instancePrefix(maps, undefined)).toBeUndefined();
        const states = new Map([
            ['ctrl', 'Toasting'],
            ['toasterCtrl', 'Off'],
        ]);
        expect(activeStateForType(maps, states, 'toast.Controller')).toBe('Toasting');
        expect(activeStateForType(maps, states, 'toast.Other')).toBeUndefined();
        expect(activeStateForType(maps, new Map([['x', 'A']]), 'toast.Other')).toBe('A');
        expect(activeStateForType(maps, new Map(), 'toast.Controller')).toBeUndefined();
    });
});
