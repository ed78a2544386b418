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
