import { describe, expect, it } from 'vitest';
import { simEndpoints } from '../src/endpoints.js';

describe('simEndpoints', () => {
    it('uses the page origin without a base (the browser IDE)', () => {
        expect(simEndpoints(undefined, { protocol: 'http:', host: '127.0.0.1:3000' })).toEqual({
            api: '',
            rosbridge: 'ws://127.0.0.1:3000/sim/rosbridge',
            viser: '/sim/viser/',
        });
        expect(simEndpoints('', { protocol: 'https:', host: 'ide.example' }).rosbridge).toBe('wss://ide.example/sim/rosbridge');
    });

    it('puts every endpoint below an absolute base, keeping its path (the webview relay)', () => {
        const e = simEndpoints('http://127.0.0.1:40123/cap-abc/', { protocol: 'vscode-webview:', host: 'x' });
        expect(e).toEqual({
            api: 'http://127.0.0.1:40123/cap-abc',
            rosbridge: 'ws://127.0.0.1:40123/cap-abc/sim/rosbridge',
            viser: 'http://127.0.0.1:40123/cap-abc/sim/viser/',
        });
        expect(simEndpoints('https://tunnel.example/p', { protocol: 'x:', host: 'y' }).rosbridge).toBe(
            'wss://tunnel.example/p/sim/rosbridge',
        );
    });

    it('refuses a base that is not http(s)', () => {
        expect(() => simEndpoints('ftp://127.0.0.1/x', { protocol: 'http:', host: 'h' })).toThrow(/http\(s\)/);
        expect(() => simEndpoints('not a url', { protocol: 'http:', host: 'h' })).toThrow();
    });
});
