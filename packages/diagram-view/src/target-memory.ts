/**
 * What the diagram remembers per target (diagram type, file, component): the expanded
 * subcomponents and the feature selection of a variable component. Pure.
 */
import type { DiagramTarget } from './contracts.js';
import { ALL_VARIATION_POINTS, type FeatureSelection } from './configuration.js';

export function targetKey(t: DiagramTarget): string {
    return `${t.diagramType}|${t.uri}|${t.component ?? ''}`;
}

export class TargetMemory {
    private readonly expanded = new Map<string, Set<string>>();
    private readonly selections = new Map<string, FeatureSelection>();

    /** The expanded instance paths of the target (a live set: changes are remembered). */
    expandedOf(t: DiagramTarget): Set<string> {
        const k = targetKey(t);
        let s = this.expanded.get(k);
        if (!s) {
            s = new Set();
            this.expanded.set(k, s);
        }
        return s;
    }

    /** Expands a collapsed instance path, collapses an expanded one. */
    toggleExpanded(t: DiagramTarget, instancePath: string): void {
        const s = this.expandedOf(t);
        if (s.has(instancePath)) s.delete(instancePath);
        else s.add(instancePath);
    }

    /** The feature selection of the target; all variation points until one is chosen. */
    selectionOf(t: DiagramTarget): FeatureSelection {
        return this.selections.get(targetKey(t)) ?? ALL_VARIATION_POINTS;
    }

    setSelection(t: DiagramTarget, selection: FeatureSelection): void {
        this.selections.set(targetKey(t), selection);
    }
}
