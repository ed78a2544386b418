/**
 * The feature control above the C&C diagram of a variable component (docs/ide.md): "All
 * variation points" (the default) or one configuration, chosen by a checkbox per feature. The
 * user's choices go to the server as the `features` option of the RequestModelAction; the
 * server shows the first admitted configuration that agrees with them (features the user did not
 * touch take that configuration's value) and names it in the graph's `configuration`, or sets
 * `configurationRejected` when the constraints admit none.
 */

export interface FeatureSelection {
    /** Whether every variation point is shown (no configuration asked for). */
    readonly all: boolean;
    /** The feature values the user chose (the others are left to the server). */
    readonly chosen: Readonly<Record<string, boolean>>;
}

export const ALL_VARIATION_POINTS: FeatureSelection = { all: true, chosen: {} };

/** What the graph of a C&C diagram says about features (language-server diagram/model.ts MaaGraph). */
export interface GraphFeatureInfo {
    readonly features: readonly string[];
    /** The values of the shown configuration, if one is shown. */
    readonly configuration?: Readonly<Record<string, boolean>>;
    readonly rejected: boolean;
}

/** Reads the feature properties of a diagram root; no features for anything malformed. */
export function graphFeatureInfo(root: Readonly<Record<string, unknown>> | undefined): GraphFeatureInfo {
    const raw = root?.['features'];
    const features = Array.isArray(raw) ? raw.filter((f): f is string => typeof f === 'string') : [];
    const conf = root?.['configuration'];
    let configuration: Record<string, boolean> | undefined;
    if (conf && typeof conf === 'object' && !Array.isArray(conf)) {
        configuration = {};
        for (const [k, v] of Object.entries(conf as Record<string, unknown>)) if (typeof v === 'boolean') configuration[k] = v;
    }
    return { features, ...(configuration ? { configuration } : {}), rejected: root?.['configurationRejected'] === true };
}

/**
 * The `features` option of the next request: undefined for all variation points, else the chosen
 * values of the features the shown graph lists (all chosen values while no graph of the target is known).
 */
export function featuresOption(selection: FeatureSelection, features: readonly string[]): Record<string, boolean> | undefined {
    if (selection.all) return undefined;
    const known = new Set(features);
    const option: Record<string, boolean> = {};
    for (const [f, v] of Object.entries(selection.chosen)) if (known.has(f) || features.length === 0) option[f] = v;
    return option;
}

/** The selection after switching between "All variation points" and one configuration (the choices are kept). */
export function showAll(selection: FeatureSelection, all: boolean): FeatureSelection {
    return { all, chosen: selection.chosen };
}

/** The selection after the user sets a feature's checkbox: one configuration, with that value chosen. */
export function chooseFeature(selection: FeatureSelection, feature: string, value: boolean): FeatureSelection {
    return { all: false, chosen: { ...selection.chosen, [feature]: value } };
}

/** Whether a feature's checkbox is checked: the shown configuration's value, else the user's choice, else unchecked. */
export function featureChecked(info: GraphFeatureInfo, selection: FeatureSelection, feature: string): boolean {
    return info.configuration?.[feature] ?? selection.chosen[feature] ?? false;
}

/** The control's status text: empty for all variation points, else what is shown. */
export function configurationStatus(info: GraphFeatureInfo, selection: FeatureSelection): string {
    if (selection.all || info.features.length === 0) return '';
    if (info.rejected) return 'no admitted configuration has these values: all variation points shown';
    return '';
}
