import type { ValidationAcceptor } from 'langium';
import {
    Codes,
    elementsOf,
    findPort,
    isErroneous,
    printType,
    subcomponentType,
    type ast as adl,
    type PortInfo,
    type TypeRelations,
} from '@maa/language-adl';
import type { Mode } from '../generated/ast.js';
import { modeAutomatonComponent, enclosingModeAutomaton, modeConnectors } from './mode-model.js';

interface End {
    readonly access: adl.PortAccess;
    readonly info: PortInfo;
    readonly sub?: adl.Subcomponent;
}

/**
 * The connector rules of the host (directions, types, one sender per port) for the connectors
 * a mode declares: the host checks the connectors of the component body; a mode's connectors
 * are checked here, and together with the body's when counting senders, since in that mode both
 * are active (two modes may each drive the same port).
 */
export class ModeConnectorChecks {
    constructor(private readonly rel: TypeRelations) {}

    check(m: Mode, accept: ValidationAcceptor): void {
        const a = enclosingModeAutomaton(m);
        const c = a && (modeAutomatonComponent(a) as adl.ComponentType | undefined);
        if (!c) return;
        const own = modeConnectors(m) as unknown as adl.Connector[]; // the composed AST's Connector is the host's
        const shared = elementsOf(c).filter((e): e is adl.Connector => e.$type === 'Connector');
        const senders = new Map<string, adl.PortAccess>();
        for (const con of shared) {
            for (const t of con.targets) senders.set(key(t), t);
        }
        for (const con of own) {
            if (!con.source) continue; // partially parsed
            const source = end(c, con.source);
            let sourceOk = true;
            if (source && !(source.sub ? source.info.direction === 'out' : source.info.direction === 'in')) {
                sourceOk = false;
                accept(
                    'error',
                    `Connector source '${text(source)}' must be an incoming port of the component or an outgoing port of a subcomponent, but it is ${source.sub ? 'an incoming port of subcomponent' : 'an outgoing port of component'} '${source.sub?.name ?? source.info.owner.name}'.`,
                    { node: source.access, code: Codes.SourceDirectionMismatch },
                );
            }
            for (const access of con.targets) {
                if (senders.has(key(access))) {
                    accept(
                        'error',
                        `Port '${access.$cstNode?.text ?? ''}' receives messages from more than one connector in mode '${m.name}'; every port has at most one sender in each mode.`,
                        { node: access, code: Codes.MultipleSenders },
                    );
                } else senders.set(key(access), access);
                const target = end(c, access);
                if (!target) continue;
                if (!(target.sub ? target.info.direction === 'in' : target.info.direction === 'out')) {
                    accept(
                        'error',
                        `Connector target '${text(target)}' must be an outgoing port of the component or an incoming port of a subcomponent, but it is ${target.sub ? 'an outgoing port of subcomponent' : 'an incoming port of component'} '${target.sub?.name ?? target.info.owner.name}'.`,
                        { node: target.access, code: Codes.TargetDirectionMismatch },
                    );
                    continue;
                }
                if (!source || !sourceOk) continue;
                const st = source.info.type;
                const tt = target.info.type;
                if (!isErroneous(st) && !isErroneous(tt) && !this.rel.isAssignable(tt, st)) {
                    accept(
                        'error',
                        `Connector '${text(source)} -> ${text(target)}' connects a port of type ${printType(st)} to a port of type ${printType(tt)}; ${printType(st)} is not assignable to ${printType(tt)}.`,
                        { node: target.access, code: Codes.ConnectorTypeMismatch },
                    );
                }
            }
        }
    }
}

function key(access: adl.PortAccess): string {
    return `${access.subcomponent?.$refText ?? ''}.${access.port?.$refText ?? ''}`;
}

function end(c: adl.ComponentType, access: adl.PortAccess): End | undefined {
    const name = access.port?.$refText ?? ''; // no port: partially parsed
    if (access.subcomponent) {
        const sub = access.subcomponent.ref;
        if (!sub) return undefined;
        const { decl, subst } = subcomponentType(sub);
        const info = decl && findPort(decl, name, subst);
        return info ? { access, info, sub } : undefined;
    }
    const info = findPort(c, name);
    return info ? { access, info } : undefined;
}

function text(e: End): string {
    return e.access.$cstNode?.text ?? `${e.sub ? `${e.sub.name}.` : ''}${e.info.name}`;
}
