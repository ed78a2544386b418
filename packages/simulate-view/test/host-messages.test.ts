import { describe, expect, it } from 'vitest';
import { parseFromWebview, parseToWebview } from '../src/host-messages.js';

describe('the messages between the extension and the simulate webview', () => {
    it('accepts the extension → webview messages', () => {
        expect(parseToWebview({ type: 'init', backendBase: 'http://127.0.0.1:1/c' })).toEqual({
            type: 'init',
            backendBase: 'http://127.0.0.1:1/c',
        });
        expect(parseToWebview({ type: 'start', app: 'a/A.arcapp', platform: 'timesync', extra: 1 })).toEqual({
            type: 'start',
            app: 'a/A.arcapp',
            platform: 'timesync',
        });
        expect(parseToWebview({ type: 'stop' })).toEqual({ type: 'stop' });
        expect(parseToWebview({ type: 'reset' })).toEqual({ type: 'reset' });
    });

    it('refuses malformed extension → webview messages', () => {
        for (const bad of [
            null,
            'init',
            [],
            { type: 'init' },
            { type: 'init', backendBase: 3 },
            { type: 'start', app: 'x' },
            { type: 'eval' },
        ]) {
            expect(parseToWebview(bad), JSON.stringify(bad)).toBeUndefined();
        }
    });

    it('accepts the webview → extension messages, copying only their fields', () => {
        expect(parseFromWebview({ type: 'ready' })).toEqual({ type: 'ready' });
        expect(parseFromWebview({ type: 'notify', severity: 'error', message: 'm' })).toEqual({
            type: 'notify',
            severity: 'error',
            message: 'm',
        });
        expect(parseFromWebview({ type: 'done', command: 'reset', ok: false })).toEqual({ type: 'done', command: 'reset', ok: false });
        expect(
            parseFromWebview({
                type: 'live-values',
                values: [
                    ['ctrl.arm', '3'],
                    ['ctrl.on', 'true'],
                ],
            }),
        ).toEqual({
            type: 'live-values',
            values: [
                ['ctrl.arm', '3'],
                ['ctrl.on', 'true'],
            ],
        });
        expect(parseFromWebview({ type: 'active-states', states: [] })).toEqual({ type: 'active-states', states: [] });
    });

    it('refuses malformed webview → extension messages', () => {
        const bad = [
            undefined,
            { type: 'notify', severity: 'fatal', message: 'm' },
            { type: 'notify', severity: 'info' },
            { type: 'done', command: 'explode', ok: true },
            { type: 'done', command: 'stop', ok: 'yes' },
            { type: 'live-values', values: [['a']] },
            { type: 'live-values', values: [['a', 1]] },
            { type: 'active-states', states: { a: 'b' } },
            { type: 'open', url: 'file:///etc/passwd' },
        ];
        for (const m of bad) expect(parseFromWebview(m), JSON.stringify(m)).toBeUndefined();
    });
});

describe('the reveal message (a selected transition → its source line and diagram highlight)', () => {
    const highlight = {
        component: 'toast.Controller',
        instancePath: 'ctrl',
        state: 'Serving',
        transition: { from: 'Toasting', to: 'Serving', index: 3 },
    };

    it('accepts a reveal with and without column and highlight, copying only its fields', () => {
        expect(parseFromWebview({ type: 'reveal', file: 'toast-service/Controller.arc', line: 12, extra: 1 })).toEqual({
            type: 'reveal',
            file: 'toast-service/Controller.arc',
            line: 12,
        });
        expect(parseFromWebview({ type: 'reveal', file: 'a/B.arc', line: 1, column: 5, highlight: { ...highlight, x: 1 } })).toEqual({
            type: 'reveal',
            file: 'a/B.arc',
            line: 1,
            column: 5,
            highlight,
        });
        expect(parseFromWebview({ type: 'reveal', file: 'B.arc', line: 2, highlight: { component: 'C', instancePath: '' } })).toEqual({
            type: 'reveal',
            file: 'B.arc',
            line: 2,
            highlight: { component: 'C', instancePath: '' },
        });
    });

    it('refuses a reveal outside the workspace or with a bad position or highlight', () => {
        const bad = [
            { type: 'reveal', file: '/etc/passwd', line: 1 },
            { type: 'reveal', file: '../secret.arc', line: 1 },
            { type: 'reveal', file: 'a/../../b.arc', line: 1 },
            { type: 'reveal', file: 'a//b.arc', line: 1 },
            { type: 'reveal', file: 'C:/x.arc', line: 1 },
            { type: 'reveal', file: 'a\\b.arc', line: 1 },
            { type: 'reveal', file: '', line: 1 },
            { type: 'reveal', file: 'a.arc', line: 0 },
            { type: 'reveal', file: 'a.arc', line: 1.5 },
            { type: 'reveal', file: 'a.arc', line: 1, column: -1 },
            { type: 'reveal', file: 'a.arc', line: 1, highlight: { component: 'C' } },
            { type: 'reveal', file: 'a.arc', line: 1, highlight: { ...highlight, transition: { from: 'a', to: 'b' } } },
            { type: 'reveal', file: 'a.arc', line: 1, highlight: { ...highlight, state: 3 } },
        ];
        for (const m of bad) expect(parseFromWebview(m), JSON.stringify(m)).toBeUndefined();
    });
});
