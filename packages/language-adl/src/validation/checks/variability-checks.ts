import { WorkspaceCache, type AstNode, type ValidationAcceptor, type ValidationCheck, type ValidationChecks } from 'langium';
import type { AdlAstType, ComponentType, Expression } from '../../generated/ast.js';
import type { AdlServices } from '../../adl-module.js';
import { elementsOf, findPort, subcomponentType, subcomponentsOf } from '../../components/component-model.js';
import { ownFeatures } from '../../components/features.js';
import {
    configurationSpace,
    isVariable,
    MAX_VARIABLES,
    MAX_VARIANTS,
    type Assignment,
    type ConfigurationSpace,
} from '../../components/variability.js';
import { currentVariant, inSubcomponent, withVariant } from '../../components/variant-context.js';
import { Codes } from '../codes.js';
import { BOOLEAN } from '../../types/sym-type.js';
import { ExpressionChecks } from './expression-checks.js';

type ComponentCheck = ValidationCheck<ComponentType>;

/**
 * MontiArc's variable architectures (ARCHITECTURE.md section 5, `variability/*`): constraints
 * must admit a configuration, subcomponent features must be fixed by the enclosing component,
 * `constraint`/`varif` expressions must be side-effect free and checkable; and the structural
 * `arc/*` checks of a variable component hold in every configuration its constraints admit
 * (`perVariant`).
 */
export class VariabilityChecks {
    private readonly spaces: WorkspaceCache<ComponentType, ConfigurationSpace | undefined>;
    private readonly variable: WorkspaceCache<ComponentType, boolean>;

    private readonly expressions: ExpressionChecks;

    constructor(services: AdlServices) {
        this.spaces = new WorkspaceCache(services.shared);
        this.variable = new WorkspaceCache(services.shared);
        this.expressions = new ExpressionChecks(services);
    }

    /** The configurations of a variable component (undefined for a component without variability). */
    space(c: ComponentType): ConfigurationSpace | undefined {
        const memo = {
            get: (x: ComponentType) => (this.variable.has(x) ? this.variable.get(x) : undefined),
            set: (x: ComponentType, v: boolean) => this.variable.set(x, v),
        };
        return this.spaces.get(c, () => (isVariable(c, memo) ? configurationSpace(c) : undefined));
    }

    readonly checks: ValidationChecks<AdlAstType> = {
        ComponentType: (c, accept) => this.checkComponent(c, accept),
        ConstraintDeclaration: (d, accept) => this.checkExpression(d.expression, 'constraint', accept),
        VarIf: (v, accept) => this.checkExpression(v.condition, 'varif', accept),
    };

    /**
     * The given checks, with their `ComponentType` check run once per configuration of a
     * variable component (each distinct selection of variation points), diagnostics merged.
     */
    perVariant(checks: ValidationChecks<AdlAstType>): ValidationChecks<AdlAstType> {
        const inner = checks.ComponentType;
        if (!inner) return checks;
        const list = (Array.isArray(inner) ? inner : [inner]) as ComponentCheck[];
        const wrapped: ComponentCheck = (c, accept, cancel) => {
            const space = this.space(c);
            if (!space) {
                for (const check of list) check(c, accept, cancel);
                return;
            }
            if (space.tooLarge) {
                // Too many variables or variants (reported): the union view.
                for (const check of list) check(c, accept, cancel);
                return;
            }
            if (space.configurations.length === 0) return; // unsatisfiable constraints (reported)
            this.runPerConfiguration(space, accept, (collect) => {
                for (const check of list) check(c, collect, cancel);
            });
        };
        return { ...checks, ComponentType: wrapped as ValidationChecks<AdlAstType>['ComponentType'] };
    }

    private runPerConfiguration(space: ConfigurationSpace, accept: ValidationAcceptor, run: (collect: ValidationAcceptor) => void): void {
        const variants = space.variants;
        type Args = Parameters<ValidationAcceptor>;
        const found = new Map<string, { args: Args; count: number; first: Assignment }>();
        for (const a of variants) {
            const collect: ValidationAcceptor = (...args: Args) => {
                const [severity, message, info] = args;
                const key = `${severity}|${message}|${info.code ?? ''}|${nodeKey(info.node)}|${String(info.property ?? '')}|${String(info.index ?? '')}`;
                const entry = found.get(key);
                if (entry) entry.count++;
                else found.set(key, { args, count: 1, first: a });
            };
            withVariant(space.env(a), () => run(collect));
        }
        for (const { args, count, first } of found.values()) {
            const [severity, message, info] = args;
            accept(severity, count < variants.length ? `${message} (In the configuration ${describe(space, first)}.)` : message, info);
        }
    }

    private checkComponent(c: ComponentType, accept: ValidationAcceptor): void {
        this.checkFeatureNames(c, accept);
        const space = this.space(c);
        if (!space) return;
        if (space.tooLarge) {
            const why =
                space.variables.size > MAX_VARIABLES
                    ? `${space.variables.size} features, parameters and conditions decide its configurations (more than ${MAX_VARIABLES})`
                    : `its constraints admit more than ${MAX_VARIANTS} different selections of variation points`;
            accept(
                'warning',
                `Component '${c.name}' is not checked configuration by configuration: ${why}. It is checked with all variation points included.`,
                { node: c, property: 'name', code: Codes.VariabilityTooManyFeatures },
            );
            return;
        }
        if (space.configurations.length === 0) {
            accept(
                'error',
                `The constraints of component '${c.name}' (its own, inherited and those of its subcomponents) admit no configuration.`,
                { node: c, property: 'name', code: Codes.VariabilityConstraintUnsatisfied },
            );
            return;
        }
        this.checkSubcomponentFeatures(c, space, accept);
        // Connectors naming a port that a configuration lacks.
        this.runPerConfiguration(space, accept, (collect) => this.checkPortsExist(c, collect));
    }

    /** Every feature of a direct subcomponent is determined by the component's own features, parameters and conditions. */
    private checkSubcomponentFeatures(c: ComponentType, space: ConfigurationSpace, accept: ValidationAcceptor): void {
        const own = [...space.variables.values()].filter((v) => v.path.length === 0).map((v) => v.key);
        const subFeatures = [...space.variables.values()].filter((v) => v.kind === 'feature' && v.path.length === 1);
        if (subFeatures.length === 0) return;
        const valuesOf = new Map<string, Map<string, boolean>>();
        const free = new Set<string>();
        for (const a of space.configurations) {
            const key = own.map((k) => (space.value(a, k) ? '1' : '0')).join('');
            let values = valuesOf.get(key);
            if (!values) valuesOf.set(key, (values = new Map()));
            for (const v of subFeatures) {
                const prev = values.get(v.key);
                const now = space.value(a, v.key);
                if (prev === undefined) values.set(v.key, now);
                else if (prev !== now) free.add(v.key);
            }
        }
        for (const v of subFeatures) {
            if (!free.has(v.key)) continue;
            const sub = v.path[0]!;
            if (sub.$container && !isOwnedBy(sub, c)) continue; // an inherited subcomponent: reported at its declaration
            accept(
                'error',
                `Feature '${v.key}' of subcomponent '${sub.name}' is not fixed by the constraints of component '${c.name}'; add a constraint that determines it (e.g. 'constraint(${v.key});').`,
                { node: sub, property: 'name', code: Codes.VariabilitySubcomponentFeaturesUnconstrained },
            );
        }
    }

    private checkPortsExist(c: ComponentType, accept: ValidationAcceptor): void {
        if (!currentVariant()) return;
        for (const e of elementsOf(c)) {
            if (e.$type !== 'Connector') continue;
            for (const access of [e.source, ...e.targets]) {
                if (!access?.port?.ref) continue; // unresolved: reported by the linker
                const name = access.port.$refText;
                if (access.subcomponent) {
                    const subName = access.subcomponent.$refText;
                    const sub = subcomponentsOf(c).find((s) => s.name === subName);
                    if (!sub) {
                        accept('error', `Subcomponent '${subName}' does not exist in this configuration.`, {
                            node: access,
                            property: 'subcomponent',
                            code: Codes.MissingSubcomponent,
                        });
                        continue;
                    }
                    const { decl, subst } = subcomponentType(sub);
                    if (decl && !inSubcomponent(sub, () => findPort(decl, name, subst))) {
                        accept('error', `Port '${name}' does not exist in the type of subcomponent '${subName}' in this configuration.`, {
                            node: access,
                            property: 'port',
                            code: Codes.MissingPort,
                        });
                    }
                } else if (!findPort(c, name)) {
                    accept('error', `Port '${name}' does not exist in this configuration.`, {
                        node: access,
                        property: 'port',
                        code: Codes.MissingPort,
                    });
                }
            }
        }
    }

    /** Two features of one name, or a feature named like a parameter. */
    private checkFeatureNames(c: ComponentType, accept: ValidationAcceptor): void {
        const seen = new Set(c.params.map((p) => p.name));
        for (const f of ownFeatures(c)) {
            if (seen.has(f.name)) {
                accept('error', `The name '${f.name}' is declared more than once in component '${c.name}'.`, {
                    node: f,
                    property: 'name',
                    code: Codes.DuplicateName,
                });
            }
            seen.add(f.name);
        }
    }

    /** `constraint`/`varif` conditions: no assignments or increments, only checkable (propositional and arithmetic) expressions. */
    private checkExpression(e: Expression | undefined, where: 'constraint' | 'varif', accept: ValidationAcceptor): void {
        if (!e) return;
        this.expressions.expectType(e, BOOLEAN, accept, Codes.ExprTypeMismatch, `The condition of a ${where}`);
        const visit = (n: AstNode): void => {
            switch (n.$type) {
                case 'AssignmentExpression':
                    accept('error', `The condition of a ${where} must not assign ('${(n as { op?: string }).op ?? '='}').`, {
                        node: n,
                        code: Codes.AssignmentInArgument,
                    });
                    break;
                case 'PrefixExpression':
                case 'PostfixExpression': {
                    const op = (n as { op?: string }).op;
                    if (op === '++' || op === '--')
                        accept('error', `The condition of a ${where} must not change a value ('${op}').`, {
                            node: n,
                            code: Codes.AssignmentInArgument,
                        });
                    break;
                }
                case 'CallExpression':
                case 'ArrayAccessExpression':
                    accept(
                        'error',
                        `The condition of a ${where} can only use features, parameters, literals and boolean, comparison and arithmetic operators; '${n.$cstNode?.text ?? ''}' cannot be checked for satisfiability.`,
                        { node: n, code: Codes.VariabilityExpressionNotCheckable },
                    );
                    return;
                default:
                    break;
            }
            for (const child of childExpressions(n)) visit(child);
        };
        visit(e);
    }
}

function childExpressions(n: AstNode): AstNode[] {
    const result: AstNode[] = [];
    for (const [k, v] of Object.entries(n)) {
        if (k.startsWith('$')) continue;
        if (Array.isArray(v))
            for (const x of v) {
                if (isNode(x)) result.push(x);
            }
        else if (isNode(v)) result.push(v);
    }
    return result;
}

function isNode(x: unknown): x is AstNode {
    return typeof x === 'object' && x !== null && typeof (x as { $type?: unknown }).$type === 'string';
}

function isOwnedBy(node: AstNode, c: ComponentType): boolean {
    for (let n: AstNode | undefined = node.$container; n; n = n.$container) {
        if (n.$type === 'ComponentType') return n === c;
    }
    return false;
}

const ids = new WeakMap<AstNode, number>();
let nextId = 0;
function nodeKey(n: AstNode): number {
    let id = ids.get(n);
    if (id === undefined) ids.set(n, (id = nextId++));
    return id;
}

/** The features (and boolean parameters) of a configuration, e.g. `f = true, sub.ff = false`. */
function describe(space: ConfigurationSpace, a: Assignment): string {
    const parts = [...space.variables.values()]
        .filter((v) => v.kind !== 'atom')
        .map((v) => `${v.key} = ${space.value(a, v.key) ? 'true' : 'false'}`);
    const atoms = [...space.variables.values()]
        .filter((v) => v.kind === 'atom')
        .map((v) => `(${v.key.substring(v.key.indexOf('#') + 1)}) = ${space.value(a, v.key) ? 'true' : 'false'}`);
    return [...parts, ...atoms].join(', ') || 'without features';
}
