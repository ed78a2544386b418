import { AstUtils, type AstNode } from 'langium';
import type {
    CDAttribute,
    CDClass,
    CDEnum,
    CDEnumConstant,
    CDMethod,
    ComponentType,
    Field,
    LocalVariable,
    Parameter,
    Port,
    Subcomponent,
    TypeParameter,
} from '../generated/ast.js';
import {
    isArcModel,
    isCDModel,
    isClassDiagram,
    isComponentType,
    isFieldDeclaration,
    isLocalVariableDeclaration,
} from '../generated/ast.js';
import {
    allPorts,
    behaviorTiming,
    enclosingComponent,
    portHeader,
    stereotypeNames,
    subcomponentType,
    type PortInfo,
} from '../components/component-model.js';
import { exportedNames, sourceText } from './node-info.js';

/**
 * How the LSP providers present the host's elements: one-line signatures (hover, completion
 * details), short details (outline, completion) and hover descriptions.
 */

/** The declaration of an element as one line of source, e.g. `port in int distance`. */
export function signature(node: AstNode): string | undefined {
    switch (node.$type) {
        case 'Port': {
            const p = node as Port;
            const h = portHeader(p);
            const stereo = stereotypeNames(h.declaration, h.stereotype);
            return `${stereo.length ? `<<${stereo.join(', ')}>> ` : ''}port ${h.direction} ${sourceText(h.type) || '?'} ${p.name}`;
        }
        case 'ComponentType':
            return componentSignature(node as ComponentType);
        case 'Subcomponent': {
            const s = node as Subcomponent;
            const t = subcomponentType(s);
            const typeText = t.ref ? sourceText(t.ref) : (t.decl?.name ?? '?');
            return `${typeText} ${s.name}${s.args.length ? `(${s.args.map((a) => sourceText(a)).join(', ')})` : ''}`;
        }
        case 'Field': {
            const f = node as Field;
            const decl = f.$container;
            return `${isFieldDeclaration(decl) ? sourceText(decl.type) : '?'} ${f.name}${f.init ? ` = ${sourceText(f.init)}` : ''}`;
        }
        case 'Feature':
            return `feature ${(node as unknown as { name: string }).name}`;
        case 'Parameter': {
            const p = node as Parameter;
            return `${sourceText(p.type)} ${p.name}${p.default ? ` = ${sourceText(p.default)}` : ''}`;
        }
        case 'LocalVariable': {
            const v = node as LocalVariable;
            const decl = v.$container;
            return `${isLocalVariableDeclaration(decl) ? sourceText(decl.type) : '?'} ${v.name}`;
        }
        case 'TypeParameter':
            return sourceText(node) || (node as TypeParameter).name;
        case 'CDClass': {
            const c = node as CDClass;
            const text = sourceText(c.$cstNode);
            const head = text.includes('{') ? text.substring(0, text.indexOf('{')).trim() : text.replace(/;$/, '');
            return head;
        }
        case 'CDEnum': {
            const e = node as CDEnum;
            return `enum ${e.name} { ${e.constants.map((c) => c.name).join(', ')} }`;
        }
        case 'CDEnumConstant':
            return `${(node.$container as CDEnum).name}.${(node as CDEnumConstant).name}`;
        case 'CDAttribute':
            return `${sourceText((node as CDAttribute).type)} ${(node as CDAttribute).name}`;
        case 'CDMethod':
            return sourceText(node as CDMethod).replace(/;$/, '');
        default:
            return undefined;
    }
}

export function componentSignature(c: ComponentType): string {
    const stereo = stereotypeNames(c.stereotype);
    const typeParams = c.typeParams.length ? `<${c.typeParams.map((t) => sourceText(t)).join(', ')}>` : '';
    const params = c.params.length || c.$cstNode?.text.includes('(') ? `(${c.params.map((p) => signature(p)).join(', ')})` : '';
    const parents = c.parents.length ? ` extends ${c.parents.map((p) => sourceText(p)).join(', ')}` : '';
    return `${stereo.length ? `<<${stereo.join(', ')}>> ` : ''}component ${c.name}${typeParams}${params}${parents}`;
}

/** A short detail for outline and completion lists, e.g. `in int` for a port. */
export function detail(node: AstNode): string | undefined {
    switch (node.$type) {
        case 'Port': {
            const h = portHeader(node as Port);
            const delayed = stereotypeNames(h.declaration, h.stereotype).includes('delayed') ? ' (delayed)' : '';
            return `${h.direction} ${sourceText(h.type)}${delayed}`;
        }
        case 'Subcomponent': {
            const t = subcomponentType(node as Subcomponent);
            return t.ref ? sourceText(t.ref) : t.decl?.name;
        }
        case 'Field': {
            const decl = node.$container;
            return isFieldDeclaration(decl) ? sourceText(decl.type) : undefined;
        }
        case 'Parameter':
            return sourceText((node as Parameter).type);
        case 'Feature':
            return 'boolean';
        case 'LocalVariable': {
            const decl = node.$container;
            return isLocalVariableDeclaration(decl) ? sourceText(decl.type) : undefined;
        }
        case 'ComponentType': {
            const c = node as ComponentType;
            return c.params.length ? `(${c.params.map((p) => signature(p)).join(', ')})` : exportedNames(c)[0];
        }
        case 'CDClass':
        case 'CDEnum':
            return exportedNames(node).sort((a, b) => a.length - b.length)[0];
        case 'CDEnumConstant':
            return (node.$container as CDEnum).name;
        case 'CDAttribute':
            return sourceText((node as CDAttribute).type);
        default:
            return undefined;
    }
}

function code(language: string, text: string): string {
    return `\`\`\`${language}\n${text}\n\`\`\``;
}

function portLine(p: PortInfo, owner: ComponentType): string {
    const notes = [`${p.timing}${p.explicitTiming ? '' : behaviorTiming(p.owner) ? ' (from the behavior)' : ' (default)'}`];
    if (p.delayed) notes.push('delayed');
    if (p.owner !== owner) notes.push(`inherited from ${p.owner.name}`);
    return `- \`${p.direction} ${printPortType(p)} ${p.name}\` — ${notes.join(', ')}`;
}

function printPortType(p: PortInfo): string {
    return sourceText(portHeader(p.port).type) || '?';
}

function portsSection(c: ComponentType): string | undefined {
    const ports = allPorts(c);
    if (ports.length === 0) return undefined;
    return `**Ports**\n\n${ports.map((p) => portLine(p, c)).join('\n')}`;
}

function paramsSection(c: ComponentType): string | undefined {
    if (c.params.length === 0) return undefined;
    return `**Parameters**\n\n${c.params.map((p) => `- \`${signature(p)}\``).join('\n')}`;
}

/** The language of a node's document, for fenced code in hovers (`arc`, `cd`, ...). */
export type LanguageOf = (node: AstNode) => string;

/** The hover text of a host element (without its documentation comment). */
export function describe(node: AstNode, languageOf: LanguageOf): string | undefined {
    const sig = signature(node);
    if (sig === undefined) return undefined;
    const parts = [code(languageOf(node), sig)];
    switch (node.$type) {
        case 'Port': {
            const port = node as Port;
            const owner = enclosingComponent(port);
            const info = owner && allPorts(owner).find((p) => p.port === port);
            if (owner && info) {
                const what = info.direction === 'in' ? 'Incoming' : 'Outgoing';
                const timing = info.explicitTiming
                    ? `timing \`${info.timing}\``
                    : `timing \`${info.timing}\` (${behaviorTiming(owner) ? 'from the behavior' : 'default'})`;
                const facts = [`type \`${printPortType(info)}\``, timing];
                if (info.delayed) facts.push('delayed by one time slice');
                parts.push(`${what} port of component \`${owner.name}\`: ${facts.join(', ')}.`);
            }
            break;
        }
        case 'ComponentType': {
            const c = node as ComponentType;
            const where = isArcModel(c.$container)
                ? c.$container.package
                    ? `Component in package \`${c.$container.package}\``
                    : 'Component in the default package'
                : `Inner component of \`${enclosingComponent(c.$container)?.name ?? '?'}\``;
            parts.push(
                `${where}${c.body?.elements.some((e) => e.$type === 'ComponentInstantiation' || (isComponentType(e) && e.instances.length > 0)) ? ' (composed)' : ''}.`,
            );
            const sections = [paramsSection(c), portsSection(c)].filter((s): s is string => !!s);
            parts.push(...sections);
            break;
        }
        case 'Subcomponent': {
            const s = node as Subcomponent;
            const decl = subcomponentType(s).decl;
            if (decl) {
                const qn = exportedNames(decl)[0] ?? decl.name;
                parts.push(`Subcomponent of \`${enclosingComponent(s.$container)?.name ?? '?'}\`, an instance of \`${qn}\`.`);
                const ports = portsSection(decl);
                if (ports) parts.push(ports);
            }
            break;
        }
        case 'Field':
            parts.push(`Field of component \`${enclosingComponent(node)?.name ?? '?'}\`.`);
            break;
        case 'Feature':
            parts.push(
                `Feature of component \`${enclosingComponent(node)?.name ?? '?'}\`: selects variation points (\`varif\`); its value is fixed per configuration (\`constraint\`, the application's binding).`,
            );
            break;
        case 'Parameter':
            parts.push(
                `Configuration parameter of component \`${enclosingComponent(node)?.name ?? '?'}\`${(node as Parameter).default ? ' (optional)' : ''}.`,
            );
            break;
        case 'LocalVariable':
            parts.push('Local variable.');
            break;
        case 'CDClass':
        case 'CDEnum': {
            const qn = exportedNames(node).sort((a, b) => a.length - b.length)[0];
            const diagram = node.$container;
            parts.push(
                `${node.$type === 'CDEnum' ? 'Enumeration' : (node as CDClass).kind === 'interface' ? 'Interface' : 'Class'} \`${qn ?? (node as CDClass).name}\`${isClassDiagram(diagram) ? ` of class diagram \`${diagram.name}\`` : ''}.`,
            );
            if (node.$type === 'CDClass') {
                const attrs = (node as CDClass).members.filter((m): m is CDAttribute => m.$type === 'CDAttribute');
                if (attrs.length) parts.push(`**Attributes**\n\n${attrs.map((a) => `- \`${signature(a)}\``).join('\n')}`);
            }
            break;
        }
        case 'CDEnumConstant':
            parts.push(`Constant of enumeration \`${(node.$container as CDEnum).name}\`.`);
            break;
        case 'CDAttribute':
            parts.push(`Attribute of \`${(node.$container as CDClass).name}\`.`);
            break;
        default:
            break;
    }
    return parts.join('\n\n');
}

/** Whether a node is a model element of a class diagram (`.cd`) rather than of an `.arc` file. */
export function isCdElement(node: AstNode): boolean {
    return isCDModel(AstUtils.findRootNode(node));
}
