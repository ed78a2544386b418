import { AstUtils, GrammarUtils, UriUtils, type AstNode } from 'langium';
import { CodeActionKind, type CodeAction, type TextEdit } from 'vscode-languageserver-types';
import type { ComponentType, Subcomponent } from '../generated/ast.js';
import { isArcModel, isCDModel, isComponentType, isConnector, isPortAccess, isSubcomponent } from '../generated/ast.js';
import {
    allPorts,
    elementsOf,
    enclosingComponent,
    portHeader,
    subcomponentType,
    subcomponentsOf,
    type PortInfo,
} from '../components/component-model.js';
import { Codes } from '../validation/codes.js';
import { fixIn, fixWith, mergeEdits, type AdlCodeActionProvider, type QuickFixContext } from './code-actions.js';
import { importEdits } from './completion.js';
import { insertIntoBody, typeTextFor } from './edits.js';
import { importName, isIdentifier } from './node-info.js';

/** At most this many alternatives per diagnostic (connect-to suggestions can be many). */
const MAX_ALTERNATIVES = 8;

/** The host's quick fixes, keyed by the codes of ARCHITECTURE.md section 5. */
export function registerHostQuickFixes(actions: AdlCodeActionProvider): void {
    actions.register(Codes.NamingConvention, fixNamingConvention);
    actions.register(Codes.MissingPort, fixMissingPort);
    actions.register(Codes.FileNameMismatch, fixFileName);
    actions.register(Codes.CdFileNameMismatch, fixFileName);
    actions.register(Codes.PackageMismatch, fixPackage);
    actions.register(Codes.CdPackageMismatch, fixPackage);
    actions.register(Codes.UnusedInPort, fixUnusedInPort);
    actions.register(Codes.UnconnectedSubInPort, fixUnconnectedSubInPort);
    actions.register(Codes.UnresolvedType, (ctx) => fixImport(ctx, 'type'));
    actions.register(Codes.MissingComponentType, (ctx) => fixImport(ctx, 'component'));
}

function named(node: AstNode | undefined): (AstNode & { name: string }) | undefined {
    for (let n = node; n; n = n.$container) {
        if (typeof (n as { name?: unknown }).name === 'string') return n as AstNode & { name: string };
    }
    return undefined;
}

/** `arc/naming-convention`: rename to the convention (upper or lower first letter), with all uses. */
function fixNamingConvention(ctx: QuickFixContext): CodeAction | undefined {
    const node = named(ctx.node);
    if (!node) return undefined;
    const name = node.name;
    const wantsUpper = isComponentType(node) || node.$type === 'TypeParameter';
    const fixed = (wantsUpper ? name.charAt(0).toUpperCase() : name.charAt(0).toLowerCase()) + name.substring(1);
    if (fixed === name) return undefined;
    return fixWith(`Rename '${name}' to '${fixed}'`, ctx.services.lsp.RenameProvider.renameElement(node, fixed));
}

/**
 * `arc/missing-port`: create the port in the component that should have it (the connector's
 * component, or the type of the named subcomponent, possibly in another file), with the
 * direction the connector needs and the type of the connector's other end.
 */
function fixMissingPort(ctx: QuickFixContext): CodeAction | undefined {
    const access = AstUtils.getContainerOfType(ctx.node, isPortAccess);
    const connector = access && AstUtils.getContainerOfType(access, isConnector);
    if (!access || !connector) return undefined;
    const name = access.port.$refText;
    const isSource = connector.source === access;
    const other = isSource ? connector.targets.find((t) => t.port?.ref) : connector.source?.port?.ref ? connector.source : undefined;
    const otherPort = other?.port.ref;
    const sub = access.subcomponent?.ref;
    const owner = sub ? subcomponentType(sub).decl : enclosingComponent(connector);
    if (!owner || !otherPort || !isIdentifier(name)) return undefined;
    const direction = isSource ? (sub ? 'out' : 'in') : sub ? 'in' : 'out';
    const type = typeTextFor(portHeader(otherPort).type, owner, ctx.services.maa.NameResolver);
    if (!type) return undefined;
    const ownerDoc = AstUtils.getDocument(owner);
    const lastPortDecl = [...elementsOf(owner)].reverse().find((e) => e.$type === 'PortDeclaration');
    const edit = insertIntoBody(ownerDoc, owner.body, `port ${direction} ${type} ${name};`, lastPortDecl);
    return fixWith(
        `Create ${direction === 'in' ? 'incoming' : 'outgoing'} port '${name}' in '${owner.name}'`,
        mergeEdits({ uri: ownerDoc.uri.toString(), edit }),
    );
}

/** `arc/file-name-mismatch`: rename the component (and its uses) or the file. */
function fixFileName(ctx: QuickFixContext): CodeAction[] {
    const root = ctx.document.parseResult.value;
    const element = isArcModel(root) ? root.component : isCDModel(root) ? root.diagram : undefined;
    if (!element?.name) return [];
    const ext = isArcModel(root) ? '.arc' : '.cd';
    const base = UriUtils.basename(ctx.document.uri);
    const fileStem = base.endsWith(ext) ? base.substring(0, base.length - ext.length) : base;
    const out: CodeAction[] = [];
    if (isIdentifier(fileStem)) {
        const renamed = isComponentType(element)
            ? ctx.services.lsp.RenameProvider.renameElement(element, fileStem)
            : mergeEdits({ uri: ctx.document.uri.toString(), edit: nameEdit(element, fileStem) });
        const a = fixWith(`Rename '${element.name}' to '${fileStem}'`, renamed);
        if (a) out.push(a);
    }
    const newUri = UriUtils.joinPath(UriUtils.dirname(ctx.document.uri), `${element.name}${ext}`).toString();
    out.push({
        title: `Rename file to '${element.name}${ext}'`,
        kind: CodeActionKind.QuickFix,
        edit: { documentChanges: [{ kind: 'rename', oldUri: ctx.document.uri.toString(), newUri }] },
    });
    return out;
}

function nameEdit(node: AstNode, text: string): TextEdit | undefined {
    const cst = GrammarUtils.findNodeForProperty(node.$cstNode, 'name');
    return cst ? { range: cst.range, newText: text } : undefined;
}

/** `arc/package-mismatch`: make the package declaration match the folder. */
function fixPackage(ctx: QuickFixContext): CodeAction | undefined {
    const root = ctx.document.parseResult.value;
    if (!isArcModel(root) && !isCDModel(root)) return undefined;
    const expected = ctx.services.shared.maa.ModelRoots.expectedPackage(ctx.document.uri);
    const packageCst = GrammarUtils.findNodeForProperty(root.$cstNode, 'package');
    const doc = ctx.document.textDocument;
    if (root.package && packageCst) {
        if (expected) return fixIn(`Change package to '${expected}'`, ctx.document, [{ range: packageCst.range, newText: expected }]);
        // The default package: remove the declaration and the blank line after it.
        const keyword = GrammarUtils.findNodeForKeyword(root.$cstNode, 'package');
        const semicolon = GrammarUtils.findNodeForKeyword(root.$cstNode, ';');
        if (!keyword || !semicolon) return undefined;
        const text = doc.getText();
        let end = semicolon.end;
        while (end < text.length && /\s/.test(text[end]!)) end++;
        return fixIn('Remove the package declaration (default package)', ctx.document, [
            { range: { start: keyword.range.start, end: doc.positionAt(end) }, newText: '' },
        ]);
    }
    if (!expected) return undefined;
    const start = { line: 0, character: 0 };
    return fixIn(`Add 'package ${expected};'`, ctx.document, [{ range: { start, end: start }, newText: `package ${expected};\n\n` }]);
}

/** The ports of a component's subcomponents that no connector targets. */
function unconnectedSubInPorts(c: ComponentType): Array<{ sub: Subcomponent; port: PortInfo }> {
    const connectors = elementsOf(c).filter(isConnector);
    const targeted = new Set<string>();
    for (const con of connectors)
        for (const t of con.targets) if (t.subcomponent) targeted.add(`${t.subcomponent.$refText}.${t.port.$refText}`);
    const out: Array<{ sub: Subcomponent; port: PortInfo }> = [];
    for (const sub of subcomponentsOf(c)) {
        const { decl, subst } = subcomponentType(sub);
        if (!decl) continue;
        for (const p of allPorts(decl, subst))
            if (p.direction === 'in' && !targeted.has(`${sub.name}.${p.name}`)) out.push({ sub, port: p });
    }
    return out;
}

function connectorAnchor(c: ComponentType): AstNode | undefined {
    const elements = elementsOf(c);
    return (
        [...elements].reverse().find(isConnector) ??
        [...elements].reverse().find((e) => e.$type === 'ComponentInstantiation' || isComponentType(e)) ??
        elements[elements.length - 1]
    );
}

function connectorEdit(c: ComponentType, text: string): CodeAction['edit'] {
    const doc = AstUtils.getDocument(c);
    return mergeEdits({ uri: doc.uri.toString(), edit: insertIntoBody(doc, c.body, text, connectorAnchor(c)) });
}

/** `arc/unused-in-port`: forward the port to an unconnected incoming port of a subcomponent. */
function fixUnusedInPort(ctx: QuickFixContext): CodeAction[] {
    const c = enclosingComponent(ctx.node ?? ctx.document.parseResult.value) ?? (isComponentType(ctx.node) ? ctx.node : undefined);
    if (!c) return [];
    const name = /port '([^']+)'/.exec(ctx.diagnostic.message)?.[1] ?? named(ctx.node)?.name;
    const port = allPorts(c).find((p) => p.name === name && p.direction === 'in');
    if (!port) return [];
    const rel = ctx.services.maa.TypeRelations;
    const candidates = unconnectedSubInPorts(c)
        .filter(({ port: q }) => rel.isAssignable(q.type, port.type))
        .sort((a, b) => Number(b.port.name === port.name) - Number(a.port.name === port.name));
    return candidates
        .slice(0, MAX_ALTERNATIVES)
        .map(({ sub, port: q }) => ({
            title: `Connect '${port.name}' to '${sub.name}.${q.name}'`,
            kind: CodeActionKind.QuickFix,
            edit: connectorEdit(c, `${port.name} -> ${sub.name}.${q.name};`),
        }))
        .filter((a) => a.edit);
}

/**
 * `arc/unconnected-sub-in-port`: connect the port from a fitting incoming port of the component
 * or outgoing port of another subcomponent, or create an incoming port for it and connect that.
 */
function fixUnconnectedSubInPort(ctx: QuickFixContext): CodeAction[] {
    const sub = AstUtils.getContainerOfType(ctx.node, isSubcomponent);
    const c = sub && enclosingComponent(sub.$container);
    if (!sub || !c) return [];
    const name = /port '([^']+)'/.exec(ctx.diagnostic.message)?.[1];
    const open = unconnectedSubInPorts(c).filter((u) => u.sub === sub && (!name || u.port.name === name));
    const rel = ctx.services.maa.TypeRelations;
    const out: CodeAction[] = [];
    for (const { port: q } of open) {
        const sources: Array<{ text: string; exact: boolean }> = [];
        for (const p of allPorts(c)) {
            if (p.direction === 'in' && rel.isAssignable(q.type, p.type)) sources.push({ text: p.name, exact: p.name === q.name });
        }
        for (const other of subcomponentsOf(c)) {
            if (other === sub) continue;
            const { decl, subst } = subcomponentType(other);
            for (const p of decl ? allPorts(decl, subst) : []) {
                if (p.direction === 'out' && rel.isAssignable(q.type, p.type))
                    sources.push({ text: `${other.name}.${p.name}`, exact: p.name === q.name });
            }
        }
        sources.sort((a, b) => Number(b.exact) - Number(a.exact));
        for (const s of sources.slice(0, MAX_ALTERNATIVES)) {
            const edit = connectorEdit(c, `${s.text} -> ${sub.name}.${q.name};`);
            if (edit) out.push({ title: `Connect '${s.text}' to '${sub.name}.${q.name}'`, kind: CodeActionKind.QuickFix, edit });
        }
        if (!allPorts(c).some((p) => p.name === q.name)) {
            const doc = AstUtils.getDocument(c);
            const type = typeTextFor(portHeader(q.port).type, c, ctx.services.maa.NameResolver);
            const lastPortDecl = [...elementsOf(c)].reverse().find((e) => e.$type === 'PortDeclaration');
            const portEdit = type ? insertIntoBody(doc, c.body, `port in ${type} ${q.name};`, lastPortDecl) : undefined;
            const conEdit = insertIntoBody(doc, c.body, `${q.name} -> ${sub.name}.${q.name};`, connectorAnchor(c));
            if (portEdit && conEdit) {
                out.push({
                    title: `Create incoming port '${q.name}' and connect it to '${sub.name}.${q.name}'`,
                    kind: CodeActionKind.QuickFix,
                    edit: { changes: { [doc.uri.toString()]: [portEdit, conEdit] } },
                });
            }
        }
    }
    return out;
}

/** `arc/unresolved-type`, `arc/missing-component-type`: import a model element of that name. */
function fixImport(ctx: QuickFixContext, kind: 'type' | 'component'): CodeAction[] {
    const name = ctx.document.textDocument.getText(ctx.diagnostic.range).trim();
    if (!name || name.includes('.') || !ctx.node) return [];
    const seen = new Set<AstNode>();
    const out: CodeAction[] = [];
    for (const d of ctx.services.maa.NameResolver.visible(ctx.node, kind)) {
        if (!d.node || seen.has(d.node) || !d.name.endsWith(`.${name}`)) continue;
        seen.add(d.node);
        const qn = importName(d.node);
        if (!qn) continue;
        const a = fixIn(`Import '${qn}'`, ctx.document, importEdits(ctx.document, qn));
        if (a) out.push(a);
    }
    return out.slice(0, MAX_ALTERNATIVES);
}
