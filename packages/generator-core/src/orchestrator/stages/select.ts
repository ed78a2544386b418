import { selectGenerators, type PlatformSelection } from '../../app/app-checks.js';
import type { AppPlatform } from '../../generated/ast.js';
import { outcome, type StageResult } from '../run.js';
import type { Checked } from './check.js';
import type { Loaded } from './load.js';

/** The generators of every platform to generate, resolved in the registry and sorted into their roles. */
export interface Selected {
    readonly selections: ReadonlyMap<AppPlatform, PlatformSelection>;
}

/**
 * Select: resolve the generators each platform names (the check stage has made sure that every
 * name resolves and that each platform has exactly one component and one data type generator).
 */
export function select(loaded: Loaded, checked: Checked): StageResult<Selected> {
    const selections = new Map<AppPlatform, PlatformSelection>();
    for (const p of checked.platforms) selections.set(p, selectGenerators(p, loaded.registry));
    return outcome({ selections });
}
