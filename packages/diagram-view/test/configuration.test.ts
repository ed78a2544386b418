// The feature control above the C&C diagram (src/diagram/configuration.ts): what it reads from
// the server's graph and what it asks for.
import { describe, expect, it } from 'vitest';
import {
    ALL_VARIATION_POINTS,
    chooseFeature,
    configurationStatus,
    featureChecked,
    featuresOption,
    graphFeatureInfo,
    showAll,
} from '../src/configuration.js';

describe('graphFeatureInfo', () => {
    it('reads the features, the shown configuration and a rejection', () => {
        const info = graphFeatureInfo({ features: ['dim', 'eco'], configuration: { dim: true, eco: false } });
        expect(info).toEqual({ features: ['dim', 'eco'], configuration: { dim: true, eco: false }, rejected: false });
        expect(graphFeatureInfo({ features: ['dim'], configurationRejected: true }).rejected).toBe(true);
    });

    it('gives no features for a graph without them or malformed properties', () => {
        expect(graphFeatureInfo(undefined)).toEqual({ features: [], rejected: false });
        expect(graphFeatureInfo({ features: 'dim', configuration: ['x'] })).toEqual({ features: [], rejected: false });
        expect(graphFeatureInfo({ features: ['dim', 3], configuration: { dim: 'yes', eco: true } })).toEqual({
            features: ['dim'],
            configuration: { eco: true },
            rejected: false,
        });
    });
});

describe('the selection', () => {
    const features = ['dim', 'eco'];

    it('asks for nothing by default: every variation point', () => {
        expect(featuresOption(ALL_VARIATION_POINTS, features)).toBeUndefined();
    });

    it('a feature checkbox switches to one configuration with that value; the others are left to the server', () => {
        const s = chooseFeature(ALL_VARIATION_POINTS, 'eco', true);
        expect(s.all).toBe(false);
        expect(featuresOption(s, features)).toEqual({ eco: true });
        expect(featuresOption(chooseFeature(s, 'dim', false), features)).toEqual({ eco: true, dim: false });
    });

    it('"All variation points" keeps the choices for the next time one configuration is shown', () => {
        const one = chooseFeature(ALL_VARIATION_POINTS, 'dim', true);
        const all = showAll(one, true);
        expect(featuresOption(all, features)).toBeUndefined();
        expect(featuresOption(showAll(all, false), features)).toEqual({ dim: true });
    });

    it('sends only features the graph lists, all of them while no graph is known', () => {
        const s = chooseFeature(chooseFeature(ALL_VARIATION_POINTS, 'dim', true), 'gone', false);
        expect(featuresOption(s, features)).toEqual({ dim: true });
        expect(featuresOption(s, [])).toEqual({ dim: true, gone: false });
    });
});

describe('the checkboxes and the status', () => {
    it("show the server's configuration, else the choice, else unchecked", () => {
        const s = chooseFeature(ALL_VARIATION_POINTS, 'dim', true);
        const shown = graphFeatureInfo({ features: ['dim', 'eco'], configuration: { dim: true, eco: true } });
        expect(featureChecked(shown, s, 'eco')).toBe(true);
        const rejected = graphFeatureInfo({ features: ['dim', 'eco'], configurationRejected: true });
        expect(featureChecked(rejected, s, 'dim')).toBe(true);
        expect(featureChecked(rejected, s, 'eco')).toBe(false);
    });

    it('the status names a rejected selection only', () => {
        const s = chooseFeature(ALL_VARIATION_POINTS, 'dim', true);
        expect(configurationStatus(graphFeatureInfo({ features: ['dim'], configuration: { dim: true } }), s)).toBe('');
        expect(configurationStatus(graphFeatureInfo({ features: ['dim'], configurationRejected: true }), s)).toMatch(
            /no admitted configuration/,
        );
        expect(configurationStatus(graphFeatureInfo({ features: ['dim'], configurationRejected: true }), ALL_VARIATION_POINTS)).toBe('');
    });
});
