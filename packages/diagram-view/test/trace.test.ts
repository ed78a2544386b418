import { describe, expect, it } from 'vitest';
import { findInnermostElement, normalizeUri, parseTrace, rangeContains } from '../src/trace.js';

describe('parseTrace', () => {
    it('parses the encoded form langium-sprotty writes', () => {
        const t = parseTrace('file:///workspace/toast/My%20Controller.arc?3%3A2-10%3A4#%2Fcomponents%400');
        expect(t).toEqual({
            uri: 'file:///workspace/toast/My Controller.arc',
            range: { start: { line: 3, character: 2 }, end: { line: 10, character: 4 } },
            fragment: '/components@0',
        });
    });
    it('parses the plain form of the contract', () => {
        const t = parseTrace('file:///workspace/toast/Controller.arc?0:0-0:12');
        expect(t?.range).toEqual({ start: { line: 0, character: 0 }, end: { line: 0, character: 12 } });
        expect(t?.fragment).toBe('');
    });
    it('rejects strings without a valid range', () => {
        expect(parseTrace(undefined)).toBeUndefined();
        expect(parseTrace('')).toBeUndefined();
        expect(parseTrace('file:///a.arc')).toBeUndefined();
        expect(parseTrace('file:///a.arc?x')).toBeUndefined();
        expect(parseTrace('file:///a.arc?5:0-4:0')).toBeUndefined();
    });
});

describe('normalizeUri', () => {
    it('decodes escapes, lowercases scheme and drive, drops query and fragment', () => {
        expect(normalizeUri('FILE:///c%3A/x%20y.arc?1#2')).toBe('file:///c:/x y.arc');
        expect(normalizeUri('file:///workspace/a.arc')).toBe('file:///workspace/a.arc');
    });
});

describe('containment', () => {
    const r = { start: { line: 2, character: 4 }, end: { line: 5, character: 1 } };
    it('includes both ends', () => {
        expect(rangeContains(r, { line: 2, character: 4 })).toBe(true);
        expect(rangeContains(r, { line: 5, character: 1 })).toBe(true);
        expect(rangeContains(r, { line: 3, character: 0 })).toBe(true);
        expect(rangeContains(r, { line: 2, character: 3 })).toBe(false);
        expect(rangeContains(r, { line: 5, character: 2 })).toBe(false);
        expect(rangeContains(r, { line: 6, character: 0 })).toBe(false);
    });
});

describe('findInnermostElement', () => {
    const uri = 'file:///workspace/toast/TR.arc';
    const els = [
        { id: 'graph', trace: `${uri}?0:0-40:1`, depth: 0 },
        { id: 'ctrl', trace: `${uri}?10:2-20:3`, depth: 1 },
        { id: 'ctrl.arm', trace: `${uri}?12:4-12:20`, depth: 2 },
        { id: 'ctrl.label', trace: `${uri}?12:4-12:20`, depth: 3 },
        { id: 'other', trace: 'file:///workspace/toast/Other.arc?0:0-99:0', depth: 1 },
        { id: 'untraced' },
    ];
    it('picks the smallest containing range in the same document', () => {
        expect(findInnermostElement(els, uri, { line: 15, character: 0 })?.id).toBe('ctrl');
        expect(findInnermostElement(els, uri, { line: 30, character: 0 })?.id).toBe('graph');
        expect(findInnermostElement(els, 'file:///workspace/toast/Other.arc', { line: 1, character: 0 })?.id).toBe('other');
    });
    it('prefers the deeper element on equal ranges', () => {
        expect(findInnermostElement(els, uri, { line: 12, character: 5 })?.id).toBe('ctrl.label');
    });
    it('matches encoded and plain URIs', () => {
        const enc = [{ id: 'x', trace: 'file:///workspace/a%20b.arc?1%3A0-2%3A0' }];
        expect(findInnermostElement(enc, 'file:///workspace/a b.arc', { line: 1, character: 3 })?.id).toBe('x');
    });
    it('gives undefined outside every range', () => {
        expect(findInnermostElement(els, uri, { line: 50, character: 0 })).toBeUndefined();
        expect(findInnermostElement(els, 'file:///workspace/none.arc', { line: 1, character: 0 })).toBeUndefined();
    });
});
