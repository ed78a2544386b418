import type { Imports } from '../../behavior/common.js';
import { checkOneBindingPerName, fromImport, fromStatements, localNameFor } from '../../behavior/import-names.js';

/** The line length of the generated ROS 2 packages (their ruff settings, test/ros2/ruff-generated.toml). */
export const ROS2_LINE_LENGTH = 120;

function compare(a: string, b: string): number {
    return a < b ? -1 : a > b ? 1 : 0;
}

/**
 * The Python imports of one generated file: module -> names, where the name '' stands for
 * `import module`. The one builder of ros2.Components; the node files render it in isort order
 * (`lines`), the mode managers hand it to the behavior generators' `Imports` (`into`), which
 * their transition code adds to and which renders their sections.
 */
export class PyImports {
    private readonly modules = new Map<string, Set<string>>();

    add(module: string, name: string): this {
        const names = this.modules.get(module) ?? new Set<string>();
        this.modules.set(module, names);
        names.add(name);
        return this;
    }

    addAll(module: string, names: Iterable<string>): this {
        for (const name of names) this.add(module, name);
        return this;
    }

    /** Imports a model type and returns the name the file refers to it by (an alias where its own name is taken). */
    use(module: string, name: string): string {
        const local = localNameFor(this.modules, module, name);
        this.add(module, local === name ? name : `${name} as ${local}`);
        return local;
    }

    /** The import lines in isort order (ruff `I`), see importLines. */
    lines(): string[] {
        checkOneBindingPerName(this.modules);
        return importLines(this.modules);
    }

    /** Adds every import to the behavior generators' builder. */
    into(target: Imports): Imports {
        for (const [module, names] of this.modules) for (const name of names) target.add(module, name);
        return target;
    }
}

/**
 * One import block in isort order (ruff `I`): `import m` lines, then `from m import ...` lines, each
 * sorted by module; names: constants, classes, then functions. The name '' stands for `import m`;
 * an aliased name (`X as Y`) gets a statement of its own (fromStatements); long lines wrap at 120.
 */
export function importLines(imports: ReadonlyMap<string, ReadonlySet<string>>): string[] {
    const modules = [...imports.keys()].sort((a, b) => compare(a.toLowerCase(), b.toLowerCase()));
    const plain = modules.filter((m) => imports.get(m)!.has('')).map((m) => `import ${m}`);
    const from = modules.flatMap((m) => fromStatements(imports.get(m)!).flatMap((names) => fromImport(m, names, ROS2_LINE_LENGTH)));
    return [...plain, ...from];
}
