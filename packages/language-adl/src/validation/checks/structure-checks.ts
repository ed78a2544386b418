import { AstUtils, type AstNode, type ValidationAcceptor, type ValidationChecks } from 'langium';
import type { AdlAstType, ArcModel, BehaviorDeclaration, ComponentType, PortDeclaration, Stereotype } from '../../generated/ast.js';
import { isArcModel } from '../../generated/ast.js';
import type { AdlServices } from '../../adl-module.js';
import type { ModelRoots } from '../../model-roots.js';
import {
    behaviorsOf,
    isComposed,
    parentsOf,
    portHeader,
    subcomponentType,
    subcomponentsOf,
    timingsOf,
    elementsOf,
} from '../../components/component-model.js';
import { Codes } from '../codes.js';
import type { NamedKind, ReservedNames } from '../reserved-names.js';

const KNOWN_STEREOTYPES = new Set(['sync', 'timed', 'untimed', 'delayed', 'handwritten']);

/** Context conditions on the structure of component types (names, files, inheritance, behaviors). */
export class StructureChecks {
    private readonly roots: ModelRoots;
    private readonly reserved: ReservedNames;

    constructor(services: AdlServices) {
        this.roots = services.shared.maa.ModelRoots;
        this.reserved = services.shared.maa.ReservedNames;
    }

    readonly checks: ValidationChecks<AdlAstType> = {
        ArcModel: (m, accept) => this.checkFile(m, accept),
        ComponentType: (c, accept) => {
            this.checkNames(c, accept);
            this.checkParameters(c, accept);
            this.checkBehaviors(c, accept);
            this.checkInheritanceCycle(c, accept);
            this.checkSubcomponentCycle(c, accept);
            if (!isComposed(c)) {
                for (const e of elementsOf(c)) {
                    if (e.$type === 'Connector') {
                        accept(
                            'warning',
                            `Component '${c.name}' has no subcomponents, so connector '${e.$cstNode?.text ?? ''}' connects nothing; atomic components compute outputs in their behavior.`,
                            { node: e, code: Codes.ConnectorInAtomic },
                        );
                    }
                }
            }
        },
        PortDeclaration: (d, accept) => this.checkPortStereotypes(d, accept),
        Stereotype: (s, accept) => {
            for (const v of s.values) {
                if (!KNOWN_STEREOTYPES.has(v.name)) {
                    accept(
                        'warning',
                        `Unknown stereotype '${v.name}'; known are ${[...KNOWN_STEREOTYPES].map((k) => `<<${k}>>`).join(', ')}.`,
                        { node: v, property: 'name', code: Codes.UnknownStereotype },
                    );
                }
            }
        },
        BehaviorDeclaration: (b, accept) => {
            if (timingsOf(b.stereotype).length > 1) this.multipleTimings(b.stereotype!, 'behavior', accept);
        },
    };

    private checkFile(m: ArcModel, accept: ValidationAcceptor): void {
        const doc = m.$document;
        const c = m.component;
        if (!doc || !c || this.roots.isBuiltin(doc.uri)) return;
        const file = doc.uri.path.substring(doc.uri.path.lastIndexOf('/') + 1).replace(/\.arc$/, '');
        if (c.name && c.name !== file) {
            accept('error', `Component '${c.name}' must be declared in a file named '${c.name}.arc', not '${file}.arc'.`, {
                node: c,
                property: 'name',
                code: Codes.FileNameMismatch,
            });
        }
        const expected = this.roots.expectedPackage(doc.uri);
        if ((m.package ?? '') !== expected) {
            const msg = `The package of '${file}.arc' must be '${expected || '(the default package)'}' to match its folder, not '${m.package ?? '(the default package)'}'.`;
            if (m.package) accept('error', msg, { node: m, property: 'package', code: Codes.PackageMismatch });
            else accept('error', msg, { node: c, property: 'name', code: Codes.PackageMismatch });
        }
        if (c.instances.length > 0) {
            accept(
                'error',
                `Top-level component type '${c.name}' cannot be instantiated where it is declared ('${c.instances.map((i) => i.name).join("', '")}'); instantiate it inside another component.`,
                { node: c.instances[0]!, property: 'name', code: Codes.RootInstantiated },
            );
        }
    }

    private checkNames(c: ComponentType, accept: ValidationAcceptor): void {
        const uri = AstUtils.getDocument(c).uri;
        const named: Array<{ node: AstNode & { name: string }; kind: NamedKind }> = [];
        const members: Array<{ node: AstNode & { name: string }; kind: NamedKind }> = [];
        for (const p of c.params) members.push({ node: p, kind: 'parameter' });
        for (const e of elementsOf(c)) {
            if (e.$type === 'PortDeclaration') for (const p of e.ports) members.push({ node: p, kind: 'port' });
            if (e.$type === 'FieldDeclaration') for (const f of e.fields) members.push({ node: f, kind: 'field' });
        }
        for (const s of subcomponentsOf(c)) members.push({ node: s, kind: 'subcomponent' });
        const typeParams = c.typeParams.map((t) => ({ node: t, kind: 'typeParameter' as const }));
        const innerTypes = elementsOf(c)
            .filter((e): e is ComponentType => e.$type === 'ComponentType')
            .map((t) => ({ node: t, kind: 'component' as const }));
        named.push(...members, ...typeParams);
        const isTop = isArcModel(c.$container);
        if (isTop) named.push({ node: c, kind: 'component' });

        for (const group of [members, typeParams, innerTypes]) {
            const seen = new Map<string, AstNode>();
            for (const { node, kind } of group) {
                if (!node.name) continue;
                if (seen.has(node.name)) {
                    accept('error', `Component '${c.name}' declares the name '${node.name}' more than once (${describe(kind)} here).`, {
                        node,
                        property: 'name',
                        code: Codes.DuplicateName,
                    });
                } else seen.set(node.name, node);
            }
        }
        // Inner component types are checked as components of their own (the ComponentType check runs for them too).
        for (const { node, kind } of named) {
            if (!node.name) continue;
            const reason = this.reserved.reason(kind, node.name, uri);
            if (reason)
                accept('error', `The ${describe(kind)} name '${node.name}' is reserved: ${reason}.`, {
                    node,
                    property: 'name',
                    code: Codes.ReservedName,
                });
            const upper = /^[A-Z]/.test(node.name);
            const wantsUpper = kind === 'component' || kind === 'typeParameter';
            if (/^[A-Za-z]/.test(node.name) && upper !== wantsUpper) {
                accept(
                    'warning',
                    `The ${describe(kind)} name '${node.name}' should start with ${wantsUpper ? 'an upper-case' : 'a lower-case'} letter.`,
                    { node, property: 'name', code: Codes.NamingConvention },
                );
            }
        }
        if (!isTop && c.name) {
            // Inner types: reserved names and the naming convention, reported on the inner type itself.
            const reason = this.reserved.reason('component', c.name, uri);
            if (reason)
                accept('error', `The component name '${c.name}' is reserved: ${reason}.`, {
                    node: c,
                    property: 'name',
                    code: Codes.ReservedName,
                });
            if (/^[a-z]/.test(c.name))
                accept('warning', `The component name '${c.name}' should start with an upper-case letter.`, {
                    node: c,
                    property: 'name',
                    code: Codes.NamingConvention,
                });
        }
    }

    private checkParameters(c: ComponentType, accept: ValidationAcceptor): void {
        let firstOptional: string | undefined;
        for (const p of c.params) {
            if (p.default) firstOptional ??= p.name;
            else if (firstOptional) {
                accept(
                    'error',
                    `Parameter '${p.name}' has no default value but follows parameter '${firstOptional}', which has one; parameters with defaults must come last.`,
                    { node: p, property: 'name', code: Codes.OptionalParamsLast },
                );
            }
        }
    }

    private checkBehaviors(c: ComponentType, accept: ValidationAcceptor): void {
        // A mode automaton (language-automata) configures subcomponents; it is no behavior of its own.
        const behaviors = behaviorsOf(c).filter(
            (b) => b.behavior?.$type !== 'InitBlock' && (b.behavior as AstNode | undefined)?.$type !== 'ModeAutomaton',
        );
        if (behaviors.length > 1) {
            const kinds = behaviors.map((b) => behaviorName(b));
            for (const b of behaviors.slice(1)) {
                accept(
                    'error',
                    `Component '${c.name}' has more than one behavior (${kinds.join(', ')}); an atomic component has at most one.`,
                    { node: b, code: Codes.MultipleBehaviors },
                );
            }
        }
    }

    private checkPortStereotypes(d: PortDeclaration, accept: ValidationAcceptor): void {
        if (timingsOf(d.stereotype).length > 1) this.multipleTimings(d.stereotype!, 'port declaration', accept);
        for (const p of d.ports) {
            if (
                timingsOf(p.stereotype).length > 1 ||
                (p.stereotype && timingsOf(p.stereotype).length > 0 && timingsOf(d.stereotype).length > 0)
            ) {
                this.multipleTimings(p.stereotype!, `port '${p.name}'`, accept);
            }
            const h = portHeader(p);
            if (h.direction === 'in' && p.direction) {
                for (const s of [p.stereotype, p === d.ports[0] ? d.stereotype : undefined]) {
                    const v = s?.values.find((x) => x.name === 'delayed');
                    if (v)
                        accept('error', `Incoming port '${p.name}' cannot be <<delayed>>; only outgoing ports delay their messages.`, {
                            node: v,
                            code: Codes.DelayedInPort,
                        });
                }
            }
        }
    }

    private multipleTimings(s: Stereotype, what: string, accept: ValidationAcceptor): void {
        accept(
            'error',
            `The ${what} declares more than one timing (${timingsOf(s)
                .map((t) => `<<${t}>>`)
                .join(', ')}).`,
            { node: s, code: Codes.MultipleTimings },
        );
    }

    private checkInheritanceCycle(c: ComponentType, accept: ValidationAcceptor): void {
        for (const p of c.parents) {
            const parent = p.type?.ref?.ref; // no type: partially parsed
            if (!parent) continue;
            const path = this.inheritancePath(parent, c, new Set());
            if (path) {
                accept('error', `Component '${c.name}' extends itself through ${[c.name, ...path.map((x) => x.name)].join(' -> ')}.`, {
                    node: p,
                    code: Codes.CircularInheritance,
                });
            }
        }
    }

    private inheritancePath(from: ComponentType, target: ComponentType, seen: Set<ComponentType>): ComponentType[] | undefined {
        if (from === target) return [from];
        if (seen.has(from)) return undefined;
        seen.add(from);
        for (const p of parentsOf(from)) {
            const rest = this.inheritancePath(p.decl, target, seen);
            if (rest) return [from, ...rest];
        }
        return undefined;
    }

    private checkSubcomponentCycle(c: ComponentType, accept: ValidationAcceptor): void {
        for (const sub of subcomponentsOf(c)) {
            const t = subcomponentType(sub).decl;
            if (!t || sub.$container === c) continue;
            const path = this.containmentPath(t, c, new Set());
            if (path) {
                accept('error', `Component '${c.name}' contains itself: ${[c.name, ...path.map((x) => x.name)].join(' contains ')}.`, {
                    node: sub,
                    property: 'name',
                    code: Codes.SubcomponentCycle,
                });
            }
        }
    }

    private containmentPath(from: ComponentType, target: ComponentType, seen: Set<ComponentType>): ComponentType[] | undefined {
        if (from === target) return [from];
        if (seen.has(from)) return undefined;
        seen.add(from);
        for (const sub of subcomponentsOf(from)) {
            const t = subcomponentType(sub).decl;
            if (!t) continue;
            const rest = this.containmentPath(t, target, seen);
            if (rest) return [from, ...rest];
        }
        return undefined;
    }
}

function describe(kind: NamedKind): string {
    return kind === 'typeParameter' ? 'type parameter' : kind;
}

/** A behavior's name as written: the keyword that opens its block (`compute`, `automaton`, ...). */
function behaviorName(b: BehaviorDeclaration): string {
    return /^[A-Za-z_]\w*/.exec(b.behavior?.$cstNode?.text ?? '')?.[0] ?? b.behavior?.$type ?? 'behavior';
}
