/**
 * Pure helpers over the diagram server's model schema (plain JSON, docs/ide.md "Diagram
 * protocol"): type normalization for the client's registry, element walks, absolute bounds,
 * the lookup tables the simulate panel needs. No Sprotty, no DOM.
 */

export interface SchemaElement {
    type: string;
    id: string;
    children?: SchemaElement[];
    position?: { x: number; y: number };
    size?: { width: number; height: number };
    [key: string]: unknown;
}

/** The element types the client registers a model class and a view for. */
export const KNOWN_TYPES = new Set([
    'graph',
    'node:component',
    'port',
    'edge:connector',
    'node:state',
    'edge:transition',
    'label:text',
    'comp:default',
    'node:generic',
    'edge:generic',
]);

/**
 * The registered type to render an element of `type` with: the type itself when registered;
 * else by its kind (`label:badge` → `label:text`, `comp:header` → `comp:default`, other
 * `node:*`/`edge:*`/`port*` → generic ones). The original type is kept in `maaType`.
 */
export function registeredType(type: string): string {
    if (KNOWN_TYPES.has(type)) return type;
    const kind = type.split(':')[0];
    switch (kind) {
        case 'label':
            return 'label:text';
        case 'comp':
            return 'comp:default';
        case 'node':
            return 'node:generic';
        case 'edge':
            return 'edge:generic';
        case 'port':
            return 'port';
        case 'graph':
            return 'graph';
        default:
            return 'comp:default';
    }
}

/** Rewrites unknown element types in place (see {@link registeredType}); returns the root. */
export function normalizeSchemaTypes<T extends SchemaElement>(root: T): T {
    const visit = (el: SchemaElement): void => {
        const reg = registeredType(el.type);
        if (reg !== el.type) {
            el['maaType'] = el.type;
            el.type = reg;
        }
        el.children?.forEach(visit);
    };
    visit(root);
    return root;
}

/** Every element with its depth (root 0) and parent, depth first in document order. */
export function* walkSchema(root: SchemaElement): Generator<{ el: SchemaElement; depth: number; parent?: SchemaElement }> {
    const stack: { el: SchemaElement; depth: number; parent?: SchemaElement }[] = [{ el: root, depth: 0 }];
    while (stack.length > 0) {
        const item = stack.pop()!;
        yield item;
        const ch = item.el.children ?? [];
        for (let i = ch.length - 1; i >= 0; i--) stack.push({ el: ch[i]!, depth: item.depth + 1, parent: item.el });
    }
}

export interface Bounds {
    x: number;
    y: number;
    width: number;
    height: number;
}

/** The bounds of an element in diagram coordinates (positions of its ancestors added up). */
export function absoluteBounds(root: SchemaElement, id: string): Bounds | undefined {
    const path: SchemaElement[] = [];
    const find = (el: SchemaElement): boolean => {
        path.push(el);
        if (el.id === id) return true;
        for (const c of el.children ?? []) if (find(c)) return true;
        path.pop();
        return false;
    };
    if (!find(root)) return undefined;
    const target = path[path.length - 1]!;
    if (!target.size) return undefined;
    let x = 0;
    let y = 0;
    // the root's own scroll is not a position; its children are in diagram coordinates
    for (const el of path.slice(1)) {
        x += el.position?.x ?? 0;
        y += el.position?.y ?? 0;
    }
    return { x, y, width: target.size.width, height: target.size.height };
}

/** Whether `inner` lies completely within `outer`. */
export function boundsInside(inner: Bounds, outer: Bounds): boolean {
    return (
        inner.x >= outer.x &&
        inner.y >= outer.y &&
        inner.x + inner.width <= outer.x + outer.width &&
        inner.y + inner.height <= outer.y + outer.height
    );
}

/** The visible diagram area of a viewport (scroll in diagram coordinates, canvas in pixels). */
export function visibleArea(
    viewport: { scroll: { x: number; y: number }; zoom: number },
    canvas: { width: number; height: number },
): Bounds {
    return { x: viewport.scroll.x, y: viewport.scroll.y, width: canvas.width / viewport.zoom, height: canvas.height / viewport.zoom };
}

/** Port paths of every `port` element. */
export function portPathsOf(root: SchemaElement): string[] {
    const out: string[] = [];
    for (const { el } of walkSchema(root))
        if (el.type === 'port' && typeof el['portPath'] === 'string' && el['portPath']) out.push(el['portPath'] as string);
    return out;
}

/** Component type by instance path of every `node:component` (`""` is the shown component). */
export function instanceTypesOf(root: SchemaElement): Map<string, string> {
    const out = new Map<string, string>();
    for (const { el } of walkSchema(root)) {
        if (el.type === 'node:component' && typeof el['instancePath'] === 'string' && typeof el['componentType'] === 'string') {
            out.set(el['instancePath'] as string, el['componentType'] as string);
        }
    }
    return out;
}

/** The node of the shown component (instance path `""`), if any. */
export function shownComponentNode(root: SchemaElement): SchemaElement | undefined {
    for (const { el } of walkSchema(root))
        if (el.type === 'node:component' && (el['instancePath'] === '' || el['instancePath'] === undefined)) return el;
    return undefined;
}

/** The instance path whose automaton the automaton view of `componentType` shows live: the first instance of that type. */
export function instanceOfType(instanceTypes: ReadonlyMap<string, string>, componentType: string | undefined): string | undefined {
    if (!componentType) return undefined;
    const simple = componentType.split('.').pop();
    for (const [path, type] of instanceTypes) if (type === componentType) return path;
    for (const [path, type] of instanceTypes) if (type.split('.').pop() === simple) return path;
    return undefined;
}

/** How a state relates to the active state path: `Outer` is an ancestor of `Outer.Inner`. */
export function stateActivity(statePath: string | undefined, active: string | undefined): 'active' | 'ancestor' | 'none' {
    if (!statePath || !active) return 'none';
    if (statePath === active) return 'active';
    if (active.startsWith(`${statePath}.`)) return 'ancestor';
    // state paths may be given relative to the automaton's top (`Inner` for `Outer.Inner`)
    if (statePath.endsWith(`.${active}`)) return 'active';
    return 'none';
}

/** The live value of a port path: exact key first, then by snake-case spelling (`ctrl.armCmd` ~ `ctrl.arm_cmd`). */
export function lookupLiveValue(
    values: ReadonlyMap<string, string>,
    bySnake: ReadonlyMap<string, string>,
    portPath: string | undefined,
): string | undefined {
    if (!portPath) return undefined;
    return values.get(portPath) ?? bySnake.get(snakePath(portPath));
}

/** A port path with every segment in lower snake case. */
export function snakePath(path: string): string {
    return path
        .split('.')
        .map((s) =>
            s
                .replace(/([a-z0-9])([A-Z])/g, '$1_$2')
                .replace(/([A-Z]+)([A-Z][a-z])/g, '$1_$2')
                .toLowerCase(),
        )
        .join('.');
}

/**
 * Where a component sits in the other C&C diagrams seen so far: the first instance path (not
 * `""`) with that component type in the instance tables of other shown components. Live values
 * and states are keyed by paths from the application's root; when the diagram shows a
 * subcomponent's type on its own, its paths are relative to this prefix.
 */
export function instancePrefix(
    typeMaps: ReadonlyMap<string, ReadonlyMap<string, string>>,
    component: string | undefined,
): string | undefined {
    if (!component) return undefined;
    for (const [root, map] of typeMaps) {
        if (root === component) continue;
        for (const [path, type] of map) if (path && type === component) return path;
    }
    return undefined;
}

/** The active state of the automaton of `componentType`: an instance of that type (in any known table) that has one. */
export function activeStateForType(
    typeMaps: ReadonlyMap<string, ReadonlyMap<string, string>>,
    activeStates: ReadonlyMap<string, string>,
    componentType: string | undefined,
): string | undefined {
    if (!componentType || activeStates.size === 0) return undefined;
    for (const map of typeMaps.values()) {
        for (const [path, type] of map) if (type === componentType && activeStates.has(path)) return activeStates.get(path);
    }
    const simple = componentType.split('.').pop();
    for (const map of typeMaps.values()) {
        for (const [path, type] of map) if (type.split('.').pop() === simple && activeStates.has(path)) return activeStates.get(path);
    }
    return activeStates.size === 1 ? [...activeStates.values()][0] : undefined;
}

/**
 * The live state of a decomposed component with a mode automaton is its current mode: both
 * platforms publish it on `/maa/automaton_states` like an automaton's state, under the node path
 * of the component's instance (`/gearbox` for the root `gear.Gearbox`, `/selector_pair/b` for
 * instance `b`), so simulate/states.ts `parseAutomatonStates` maps it to that instance path.
 *
 * How an element of the C&C diagram declared in a mode (a subcomponent or connector with
 * `mode`) relates to the current mode of the component that declares it: `active` in that mode,
 * `inactive` in another one, `none` for elements outside modes or without a live mode.
 */
export function modeActivity(elementMode: string | undefined, currentMode: string | undefined): 'active' | 'inactive' | 'none' {
    if (!elementMode || !currentMode) return 'none';
    return elementMode === currentMode ? 'active' : 'inactive';
}
