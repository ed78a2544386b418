/**
 * What a simulation run shows on the diagram (the data behind contracts.ts `DiagramLiveLayer`):
 * live values by port path and active states or modes by instance path. The instance tables of
 * every C&C diagram seen so far place a subcomponent's diagram shown on its own inside the
 * application (its paths are then relative to its instance path) and find the instance whose
 * automaton an automaton view shows. Pure: no Sprotty, no DOM.
 */
import type { DiagramHighlight } from './highlight.js';
import { activeStateForType, instancePrefix, instanceTypesOf, lookupLiveValue, snakePath, type SchemaElement } from './schema.js';

export class LiveLayer {
    private values: ReadonlyMap<string, string> = new Map();
    private valuesBySnake: ReadonlyMap<string, string> = new Map();
    private states: ReadonlyMap<string, string> = new Map();
    private highlighted: DiagramHighlight | undefined;
    /** Instance types of every C&C diagram seen, by shown component. */
    private readonly typeMaps = new Map<string, Map<string, string>>();
    /** The instance path of the shown component in another known diagram (see `instancePrefix`). */
    private prefix: string | undefined;

    /** A new model of `shown` arrived; only C&C diagrams (not `maa-automaton`) have instance tables. */
    recordModel(root: SchemaElement, diagramType: string | undefined, shown: string): void {
        if (diagramType === 'maa-automaton') return;
        this.typeMaps.set(shown, instanceTypesOf(root));
        this.prefix = instancePrefix(this.typeMaps, shown);
    }

    setLiveValues(values: ReadonlyMap<string, string>): void {
        this.values = new Map(values);
        this.valuesBySnake = new Map([...values].map(([k, v]) => [snakePath(k), v]));
    }

    setActiveStates(states: ReadonlyMap<string, string>): void {
        this.states = new Map(states);
    }

    /** The trace point to highlight (`undefined` clears). */
    setHighlight(highlight: DiagramHighlight | undefined): void {
        this.highlighted = highlight;
    }

    /** The highlight of an instance of the shown C&C diagram (`""`: the shown component), relative to the prefix too. */
    highlightOf(instancePath: string | undefined): DiagramHighlight | undefined {
        const h = this.highlighted;
        if (!h || instancePath === undefined) return undefined;
        if (h.instancePath === instancePath) return h;
        const prefixed = this.prefix === undefined ? undefined : instancePath ? `${this.prefix}.${instancePath}` : this.prefix;
        return prefixed !== undefined && h.instancePath === prefixed ? h : undefined;
    }

    /** The highlight of the automaton of `componentType` (the automaton view), if it is that component's. */
    highlightForType(componentType: string | undefined): DiagramHighlight | undefined {
        return componentType !== undefined && this.highlighted?.component === componentType ? this.highlighted : undefined;
    }

    /** The live value of a port path of the shown diagram (any spelling; relative to the prefix too). */
    liveValue(portPath: string | undefined): string | undefined {
        if (!portPath || this.values.size === 0) return undefined;
        return (
            lookupLiveValue(this.values, this.valuesBySnake, portPath) ??
            (this.prefix ? lookupLiveValue(this.values, this.valuesBySnake, `${this.prefix}.${portPath}`) : undefined)
        );
    }

    /** The active state or mode of an instance of the shown diagram (`""`: the shown component). */
    activeStateOf(instancePath: string | undefined): string | undefined {
        if (instancePath === undefined || this.states.size === 0) return undefined;
        return (
            this.states.get(instancePath) ??
            (this.prefix ? this.states.get(instancePath ? `${this.prefix}.${instancePath}` : this.prefix) : undefined)
        );
    }

    /** The active state of the automaton of `componentType` (an instance of the type that has one). */
    activeStateForType(componentType: string | undefined): string | undefined {
        if (this.states.size === 0) return undefined;
        return activeStateForType(this.typeMaps, this.states, componentType);
    }
}
