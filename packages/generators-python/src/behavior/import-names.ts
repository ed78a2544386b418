import { GenerationError } from '@maa/generator-core/node';

/**
 * The names the imports of a generated module bind, shared by the two import builders (the
 * behavior generators' `Imports` and ros2's `PyImports`): both keep module -> names, where the name
 * '' stands for `import module` and `X as Y` imports X under the name Y.
 */
export type ImportMap = ReadonlyMap<string, ReadonlySet<string>>;

/** The name an import binds and what it stands for: `import a.b` binds `a`, `from m import X as Y` binds Y to `m.X`. */
function binding(module: string, name: string): { local: string; origin: string } {
    if (name === '') {
        const top = module.split('.')[0]!;
        return { local: top, origin: top };
    }
    const [imported, alias] = name.split(' as ');
    return { local: alias ?? imported!, origin: `${module}.${imported}` };
}

/** Every bound name with what it stands for (more than one: a later import would shadow an earlier one). */
function bindings(imports: ImportMap): Map<string, Set<string>> {
    const bound = new Map<string, Set<string>>();
    for (const [module, names] of imports) {
        for (const name of names) {
            const { local, origin } = binding(module, name);
            const origins = bound.get(local) ?? new Set<string>();
            bound.set(local, origins.add(origin));
        }
    }
    return bound;
}

/**
 * The name under which a module's model type is imported: its own name unless that name is bound to
 * something else (a type of the same name from another class diagram, a run-time name such as
 * `Relay`), then `<module with underscores>_<name>` (numbered while that is taken too). The same
 * type gets the same name every time.
 */
export function localNameFor(imports: ImportMap, module: string, name: string): string {
    const names = imports.get(module);
    if (names?.has(name)) return name;
    const aliased = [...(names ?? [])].find((n) => n.startsWith(`${name} as `));
    if (aliased) return binding(module, aliased).local;
    const bound = bindings(imports);
    if (!bound.has(name)) return name;
    const base = `${module.replace(/\./g, '_')}_${name}`;
    let local = base;
    for (let i = 2; bound.has(local); i++) local = `${base}_${i}`;
    return local;
}

/**
 * Refuses imports that bind one name twice (Python would silently keep the later one): a run-time
 * name added after a model type of the same name took it. Model types give way by `localNameFor`.
 */
export function checkOneBindingPerName(imports: ImportMap): void {
    for (const [local, origins] of bindings(imports)) {
        if (origins.size > 1) {
            throw new GenerationError(
                `a generated module would import the name '${local}' twice (${[...origins].sort().join(', ')}); rename the model type`,
            );
        }
    }
}

function compare(a: string, b: string): number {
    return a < b ? -1 : a > b ? 1 : 0;
}

/** isort's order of imported names (ruff's `order-by-type`): constants, classes, then the rest, each case-insensitively. */
export function compareMembers(a: string, b: string): number {
    const rank = (n: string): number => (/^[A-Z0-9_]+$/.test(n) && n.length > 1 ? 0 : /^[A-Z]/.test(n) ? 1 : 2);
    return rank(a) - rank(b) || compare(a.toLowerCase(), b.toLowerCase()) || compare(a, b);
}

/**
 * The `from module import ...` statements of one module's names ('' left out): each aliased name
 * (`X as Y`) alone, the others together in isort's order; the statements ordered as isort orders
 * them, by their first name.
 */
export function fromStatements(names: Iterable<string>): string[][] {
    const all = [...names].filter((n) => n !== '');
    const plain = all.filter((n) => !n.includes(' as ')).sort(compareMembers);
    const statements = all.filter((n) => n.includes(' as ')).map((n) => [n]);
    if (plain.length > 0) statements.push(plain);
    const first = (s: string[]): string[] => s[0]!.split(' as ');
    return statements.sort((a, b) => {
        const [x, xs = ''] = first(a);
        const [y, ys = ''] = first(b);
        return compareMembers(x!, y!) || compare(xs, ys);
    });
}

/** `from m import a, b`, wrapped as isort wraps it (one name a line) when longer than the line length. */
export function fromImport(module: string, names: readonly string[], lineLength: number): string[] {
    const line = `from ${module} import ${names.join(', ')}`;
    if (line.length <= lineLength) return [line];
    return [`from ${module} import (`, ...names.map((n) => `    ${n},`), ')'];
}
