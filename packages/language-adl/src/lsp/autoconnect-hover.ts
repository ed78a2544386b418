import { CstUtils, type LangiumDocument } from 'langium';
import type { Hover, HoverParams } from 'vscode-languageserver-protocol';
import type { AutoConnect } from '../generated/ast.js';
import { impliedConnectors, type ImpliedEnd } from '../components/autoconnect.js';
import { enclosingComponent } from '../components/component-model.js';

/**
 * Hover on an `autoconnect` declaration: what its kind means and the connectors it implies in
 * its component (the ones the checks, the diagram and the generators see).
 */
export function autoConnectHover(document: LangiumDocument, params: HoverParams): Hover | undefined {
    const root = document.parseResult?.value?.$cstNode;
    if (!root) return undefined;
    const leaf = CstUtils.findLeafNodeAtOffset(root, document.textDocument.offsetAt(params.position));
    const node = leaf?.astNode;
    if (node?.$type !== 'AutoConnect') return undefined;
    const decl = node as AutoConnect;
    const c = enclosingComponent(decl);
    const meaning: Record<AutoConnect['kind'], string> = {
        port: 'connects every port that no connector feeds from the one port of the same name and type',
        type: 'connects every port that no connector feeds from the only port of the same type',
        off: 'implies no connectors',
    };
    const implied = c ? impliedConnectors(c).filter((i) => i.declaration === decl) : [];
    const end = (e: ImpliedEnd): string => (e.sub ? `${e.sub.name}.${e.info.name}` : e.info.name);
    const lines = ['```arc', `autoconnect ${decl.kind};`, '```', '', `\`autoconnect ${decl.kind}\` ${meaning[decl.kind]}.`];
    if (decl.kind !== 'off') {
        lines.push(
            '',
            implied.length > 0
                ? `Implied connectors: ${implied.map((i) => `\`${end(i.source)} -> ${end(i.target)}\``).join(', ')}.`
                : 'It implies no connectors here.',
        );
    }
    return { contents: { kind: 'markdown', value: lines.join('\n') } };
}
