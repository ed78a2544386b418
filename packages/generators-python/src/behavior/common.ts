import type {
    BehaviorGenerationContext,
    ComponentView,
    DataTypeResult,
    FieldView,
    ParameterView,
    PortView,
    TypeView,
} from '@maa/generator-core';
import { dataTypeQualifiedName } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import { PythonTranslator, isInPort, isOutPort, pyName, type NameContext, type Node } from '../python/expressions.js';
import { checkOneBindingPerName, fromImport, fromStatements, localNameFor } from './import-names.js';
import type { AttributeView, PrologueView } from './views.js';

/** Names of the base class a generated attribute must not shadow. */
const RESERVED = new Set([
    'init',
    'step',
    'start',
    'on_message',
    'on_tick',
    'current_state',
    'set_delay_hook',
    'TIMING',
    'IN_PORTS',
    'OUT_PORTS',
    'DELAYED',
    'PARAMETERS',
    'self',
    'emit',
    'params',
    'inputs',
    'port',
    'value',
    'event',
]);

/** The attribute of a port, parameter or field in a behavior class. */
export function attr(name: string): string {
    const n = pyName(name);
    return RESERVED.has(n) || n.startsWith('_') ? `${n}_` : n;
}

/** `a.b.C` to `a/b/c` style module path parts: package folders plus snake-case module name. */
export function snake(name: string): string {
    return name
        .replace(/([a-z0-9])([A-Z])/g, '$1_$2')
        .replace(/([A-Z]+)([A-Z][a-z])/g, '$1_$2')
        .toLowerCase();
}

export function modulePath(packageName: string, moduleName: string): { module: string; file: string } {
    const parts = packageName ? packageName.split('.').map(pyName) : [];
    return { module: [...parts, moduleName].join('.'), file: [...parts, `${moduleName}.py`].join('/') };
}

/**
 * Keeps the imports of a generated module, sorted; the name '' stands for `import module` (as in
 * ros2's PyImports, which the mode managers hand to this builder).
 */
export class Imports {
    private readonly from = new Map<string, Set<string>>();
    /** @param lineLength where import lines wrap: 140 in timesync builds, 120 in ROS 2 packages (their ruff settings) */
    constructor(private readonly lineLength = 140) {}
    add(module: string, name: string): void {
        let set = this.from.get(module);
        if (!set) this.from.set(module, (set = new Set()));
        set.add(name);
    }
    /** Imports a model type and returns the name the module refers to it by (an alias where its own name is taken). */
    use(module: string, name: string): string {
        const local = localNameFor(this.from, module, name);
        this.add(module, local === name ? name : `${name} as ${local}`);
        return local;
    }
    lines(): string[] {
        checkOneBindingPerName(this.from);
        // isort sections: standard library, then the build's own packages (model packages and
        // run-time environments; ruff run inside the generated folder sees both as first-party).
        // Within a section, `import m` lines precede the `from m import ...` lines (isort's default).
        const groups: Array<{ straight: string[]; from: string[] }> = [
            { straight: [], from: [] },
            { straight: [], from: [] },
        ];
        const modules = [...this.from.keys()].sort((a, b) => cmp(a.toLowerCase(), b.toLowerCase()));
        for (const module of modules) {
            const names = this.from.get(module)!;
            const group = groups[STDLIB.has(module.split('.')[0]) ? 0 : 1];
            if (names.has('')) group.straight.push(`import ${module}`);
            for (const statement of fromStatements(names)) group.from.push(...fromImport(module, statement, this.lineLength));
        }
        return groups
            .map((g) => [...g.straight, ...g.from])
            .filter((g) => g.length)
            .flatMap((g, i) => (i === 0 ? g : ['', ...g]));
    }
}

const STDLIB = new Set(['collections', 'typing', 'enum', 'dataclasses', 'json', 'math', 'sys', 'importlib', 'struct', 'abc']);

function cmp(a: string, b: string): number {
    return a < b ? -1 : a > b ? 1 : 0;
}

/** Python's type for a Java primitive or boxed type (the one table; the data types add collections). */
export const PRIMITIVE_PY: Readonly<Record<string, string>> = {
    int: 'int',
    Integer: 'int',
    long: 'int',
    Long: 'int',
    short: 'int',
    Short: 'int',
    byte: 'int',
    Byte: 'int',
    char: 'int',
    Character: 'int',
    float: 'float',
    Float: 'float',
    double: 'float',
    Double: 'float',
    boolean: 'bool',
    Boolean: 'bool',
    String: 'str',
};

/** Resolves class-diagram types through the data type generator's result. */
export function typeRef(datatypes: DataTypeResult | undefined, imports: Imports, decl: Node): string {
    const mapping = isNamed(decl) ? datatypes?.types?.[dataTypeQualifiedName(decl)] : undefined;
    if (mapping?.module && mapping.name) {
        return imports.use(mapping.module, mapping.name);
    }
    return pyName(String(decl.name));
}

/** Whether a node has a name (declarations do; the translators' nodes are loosely typed). */
function isNamed(n: Node): n is Node & { name: string } {
    return typeof n.name === 'string';
}

/**
 * A data type by the name a qualified reference such as `pkg.Types.Color.RED` gives it (`pkg.Types.Color`):
 * the type of that qualified name, else the first whose name ends so (`Types.Color`, `Color`).
 */
export function typeBySimpleName(datatypes: DataTypeResult | undefined, imports: Imports, name: string): string | undefined {
    const keys = Object.keys(datatypes?.types ?? {}).sort();
    const key = keys.includes(name) ? name : keys.find((q) => q.endsWith(`.${name}`));
    const mapping = key ? datatypes?.types?.[key] : undefined;
    if (!mapping?.module || !mapping.name) return undefined;
    return imports.use(mapping.module, mapping.name);
}

/** A Python annotation for a model type. */
export function pyType(t: TypeView, datatypes: DataTypeResult | undefined, imports: Imports): string {
    const prim = PRIMITIVE_PY[t.typeName];
    if (prim) return prim;
    if (t.type.kind === 'object' && t.type.args.length === 0) {
        const decl = t.type.decl;
        if (AstBuiltin(decl)) return 'object';
        return typeRef(datatypes, imports, decl);
    }
    return 'object';
}

function AstBuiltin(decl: Node): boolean {
    let root: Node = decl;
    while (root.$container) root = root.$container as Node;
    return (root.$document?.uri?.scheme ?? '') === 'builtin';
}

/** What a behavior class needs about its component. */
export interface ClassSpec {
    readonly className: string;
    readonly timing: string;
    readonly ports: readonly PortView[];
    readonly parameters: readonly ParameterView[];
    readonly fields: readonly FieldView[];
    readonly datatypes?: DataTypeResult;
}

export function specFrom(ctx: BehaviorGenerationContext, component: ComponentView, timing: string): ClassSpec {
    return {
        className: `${component.name}Behavior`,
        timing,
        ports: ctx.ports ?? component.ports,
        parameters: ctx.parameters ?? component.parameters,
        fields: ctx.fields ?? component.fields,
        datatypes: ctx.datatypes,
    };
}

/** A translator whose names are the attributes of a behavior class. */
export function behaviorTranslator(spec: ClassSpec, imports: Imports): PythonTranslator {
    const names: NameContext = {
        name(target, ref) {
            switch (target.$type) {
                case 'Port':
                case 'Field':
                case 'Parameter':
                    if (isOutPort(target)) return `self._last.get(${JSON.stringify(target.name)})`;
                    return `self.${attr(target.name)}`;
                case 'LocalVariable':
                    return pyName(target.name);
                case 'CDEnumConstant':
                    return `${typeRef(spec.datatypes, imports, target.$container as Node)}.${pyName(target.name)}`;
                case 'CDType':
                case 'CDClass':
                case 'CDInterface':
                case 'CDEnum':
                    return typeRef(spec.datatypes, imports, target);
                default:
                    throw new GenerationError(
                        `'${target.name ?? target.$type}' (${target.$type}) cannot be used here by the Python generators`,
                        ref,
                    );
            }
        },
        send(target, value) {
            return isOutPort(target) ? `self._emit(${JSON.stringify(target.name)}, ${value})` : undefined;
        },
        type: (decl) => typeRef(spec.datatypes, imports, decl),
        typeBySimpleName: (name) => typeBySimpleName(spec.datatypes, imports, name),
    };
    return new PythonTranslator(names);
}

/** The class header, class variables and `__init__` of a behavior class (templates/behavior/prologue.njk). */
export function prologueView(spec: ClassSpec, imports: Imports, doc: string, extraInit: readonly string[] = []): PrologueView {
    const tr = behaviorTranslator(spec, imports);
    imports.add('maa_behavior', 'Behavior');
    imports.add('maa_behavior', 'Emit');
    imports.add('collections.abc', 'Mapping');
    const ins = spec.ports.filter((p) => p.direction === 'in');
    const outs = spec.ports.filter((p) => p.direction === 'out');
    const attributes: AttributeView[] = [
        ...spec.parameters.map((p) => ({
            name: attr(p.name),
            type: pyType(p, spec.datatypes, imports),
            value: `self._params.get(${JSON.stringify(p.name)}, ${p.default ? tr.expr(p.default) : 'None'})`,
            ignoreType: true,
        })),
        ...spec.fields.map((f) => ({
            name: attr(f.name),
            type: pyType(f, spec.datatypes, imports),
            value: tr.expr(f.init),
            ignoreType: false,
        })),
        ...ins.map((p) => ({ name: attr(p.name), type: `${pyType(p, spec.datatypes, imports)} | None`, value: 'None', ignoreType: false })),
    ];
    return {
        className: spec.className,
        doc,
        timing: spec.timing,
        inPorts: ins.map((p) => p.name),
        outPorts: outs.map((p) => p.name),
        delayed: outs.filter((p) => p.delayed).map((p) => p.name),
        attributes,
        extraInit,
    };
}

/** Statements that copy a sync slice's inputs to the in-port attributes. */
export function readInputs(spec: ClassSpec): string[] {
    return spec.ports
        .filter((p) => p.direction === 'in')
        .map((p) => {
            const def = primitiveDefault(p);
            return `self.${attr(p.name)} = ${def === 'None' ? `inputs.get(${JSON.stringify(p.name)})` : `self._in(inputs, ${JSON.stringify(p.name)}, ${def})`}  # type: ignore[assignment]`;
        });
}

/** Java's default of a primitive type (what a sync slice reads from a port without message), else `None`. */
export function primitiveDefault(t: TypeView): string {
    switch (t.typeName) {
        case 'int':
        case 'long':
        case 'short':
        case 'byte':
        case 'char':
            return '0';
        case 'float':
        case 'double':
            return '0.0';
        case 'boolean':
            return 'False';
        default:
            return 'None';
    }
}

export function indent(lines: readonly string[], n: number): string[] {
    const pad = ' '.repeat(n);
    return lines.map((l) => (l.length ? pad + l : l));
}

export { isInPort, isOutPort };
