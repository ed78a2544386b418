// The one model-root rule (src/workspace/model-root.ts): marker, package folders, file folder.
import { describe, expect, it } from 'vitest';
import { declaredPackage, resolveModelRoot } from '../src/workspace/model-root.js';

const markers = (...folders: string[]) => {
    const asked: string[] = [];
    return {
        asked,
        hasMarker: (f: string) => {
            asked.push(f);
            return folders.includes(f);
        },
    };
};

describe('resolveModelRoot', () => {
    it('finds the nearest folder with a maa.json from the file folder upwards', () => {
        const m = markers('/w/proj', '/w');
        expect(resolveModelRoot('/w/proj/apps/A.arcapp', m)).toBe('/w/proj');
        expect(m.asked).toEqual(['/w/proj/apps', '/w/proj']);
        expect(resolveModelRoot('/w/proj/A.arcapp', markers('/w/proj'))).toBe('/w/proj');
        expect(resolveModelRoot('/w/x/A.arcapp', markers('/w'))).toBe('/w');
        expect(resolveModelRoot('/A.arcapp', markers('/'))).toBe('/');
    });

    it('looks no higher than stopAt, and gives a file outside stopAt its own folder', () => {
        const m = markers('/w');
        expect(resolveModelRoot('/w/proj/apps/A.arcapp', { ...m, stopAt: '/w/proj' })).toBe('/w/proj/apps');
        expect(m.asked).toEqual(['/w/proj/apps', '/w/proj']);
        expect(resolveModelRoot('/w/proj/apps/A.arcapp', { ...markers('/w/proj'), stopAt: '/w/proj/' })).toBe('/w/proj');
        expect(resolveModelRoot('/elsewhere/A.arcapp', { ...markers('/elsewhere'), stopAt: '/w' })).toBe('/elsewhere');
        // Workspace-relative folders: '' is the workspace folder.
        expect(resolveModelRoot('proj/apps/A.arcapp', { ...markers('proj'), stopAt: '' })).toBe('proj');
        expect(resolveModelRoot('proj/apps/A.arcapp', { ...markers(''), stopAt: '' })).toBe('');
        expect(resolveModelRoot('A.arcapp', { ...markers(), stopAt: '' })).toBe('');
        // The package rule gives no root above stopAt either.
        expect(resolveModelRoot('/w/toast/C.arc', { ...markers(), stopAt: '/w/toast', packageName: 'toast' })).toBe('/w/toast');
    });

    it('takes the folder above the package folders when the package matches them', () => {
        expect(resolveModelRoot('/w/models/toast/ctrl/C.arc', { ...markers(), packageName: 'toast.ctrl' })).toBe('/w/models');
        expect(resolveModelRoot('/toast/C.arc', { ...markers(), packageName: 'toast' })).toBe('/');
        expect(resolveModelRoot('C:/m/toast/C.arc', { ...markers(), packageName: 'm.toast' })).toBe('C:/');
        expect(resolveModelRoot('toast/ctrl/C.arc', { ...markers(), stopAt: '', packageName: 'toast.ctrl' })).toBe('');
    });

    it('falls back to the file folder without a marker or a matching package', () => {
        expect(resolveModelRoot('/w/models/C.arc', markers())).toBe('/w/models');
        expect(resolveModelRoot('/w/models/other/C.arc', { ...markers(), packageName: 'toast' })).toBe('/w/models/other');
        expect(resolveModelRoot('/C.arc', { ...markers(), packageName: 'a.b.c.d' })).toBe('/');
        expect(resolveModelRoot('/w/toast/ctrl/C.arc', { ...markers(), packageName: 'other.ctrl' })).toBe('/w/toast/ctrl');
    });

    it('prefers a maa.json over the package rule', () => {
        expect(resolveModelRoot('/w/proj/models/toast/C.arc', { ...markers('/w/proj'), packageName: 'toast' })).toBe('/w/proj');
        // Even a marker above the root the package would give.
        expect(resolveModelRoot('/w/proj/toast/C.arc', { ...markers('/w'), packageName: 'toast' })).toBe('/w');
    });
});

describe('declaredPackage', () => {
    it('reads the package declaration at the start of a file', () => {
        expect(declaredPackage('package toast.ctrl;\ncomponent C {}')).toBe('toast.ctrl');
        expect(declaredPackage('\uFEFF// header\n/* more */\npackage  toast . ctrl ;')).toBe('toast.ctrl');
        expect(declaredPackage('component C {}')).toBeUndefined();
        expect(declaredPackage('component C {}\npackage late;')).toBeUndefined();
    });
});
