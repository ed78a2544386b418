import { GrammarUtils, type AstNode } from 'langium';
import { Formatting } from 'langium/lsp';
import { CompletionItemKind, SemanticTokenModifiers, SemanticTokenTypes, SymbolKind } from 'vscode-languageserver-types';
import { sourceText, type AdlFormatter, type AdlLspServices } from '@maa/language-adl';
import type { Mode, ModeAutomaton, ModeTransition } from '../generated/ast.js';
import {
    enclosingModeAutomaton,
    modeAutomatonComponent,
    modeAutomatonTiming,
    modeConnectors,
    modeSubcomponents,
    modeTransitionsOf,
} from './mode-model.js';

/**
 * Editor support of mode automata (installed with the automaton language's LSP part): outline
 * entries for the mode automaton, its modes (with their subcomponents and connectors below) and
 * transitions; modes styled like states (declarations and the references in transitions); `Tick`
 * as an event; formatting in MontiArc's style; hover for modes. Completion, go-to-definition,
 * references and rename of modes, and of subcomponents inside modes, follow from the scopes
 * (mode-language.ts); folding from the multi-line blocks.
 */
export function registerModeLsp(services: AdlLspServices): void {
    const kinds = services.shared.lsp.NodeKindProvider.kinds;
    kinds.set('ModeAutomaton', { symbol: SymbolKind.Namespace, completion: CompletionItemKind.Module });
    kinds.set('Mode', { symbol: SymbolKind.EnumMember, completion: CompletionItemKind.EnumMember });
    kinds.set('ModeTransition', { symbol: SymbolKind.Event, completion: CompletionItemKind.Event });

    const symbols = services.lsp.DocumentSymbolProvider.contributions;
    symbols.set('ModeAutomaton', (n) => ({
        name: 'mode automaton',
        detail: modeAutomatonTiming(n as ModeAutomaton),
        selection: GrammarUtils.findNodeForKeyword(n.$cstNode, 'automaton'),
    }));
    symbols.set('Mode', (n) => {
        const m = n as Mode;
        if (!m.name) return 'skip';
        return { name: m.name, detail: m.initial ? 'initial' : undefined };
    });
    symbols.set('ModeTransition', (n) => {
        const t = n as ModeTransition;
        const parts = [t.guard ? `[${sourceText(t.guard)}]` : undefined, t.tick ? 'Tick' : t.event?.$refText].filter(Boolean);
        return { name: `${t.source?.$refText ?? '?'} -> ${t.target?.$refText ?? '?'}`, detail: parts.join(' ') || undefined };
    });

    const tokens = services.lsp.SemanticTokenProvider;
    tokens.styles.set('Mode', { type: SemanticTokenTypes.namespace });
    tokens.highlighters.set('ModeTransition', (n, accept) => {
        if ((n as ModeTransition).tick)
            accept({ node: n, keyword: 'Tick', type: SemanticTokenTypes.event, modifier: SemanticTokenModifiers.defaultLibrary });
    });

    registerFormatting(services.lsp.Formatter);
    services.lsp.HoverProvider.contributions.set('Mode', (n) => describeMode(n as Mode, services.lsp.HoverProvider.languageOf(n)));
}

function registerFormatting(formatter: AdlFormatter): void {
    const rules = formatter.rules;
    rules.set('ModeAutomaton', (n, f) => {
        const on = f.on(n);
        on.keyword('mode').append(Formatting.oneSpace());
        on.keyword('automaton').append(Formatting.oneSpace());
        f.elementBlock(n);
    });
    rules.set('Mode', (n, f) => {
        const m = n as Mode;
        const on = f.on(m);
        if (m.initial) on.keyword('initial').append(Formatting.oneSpace());
        on.keyword('mode').append(Formatting.oneSpace());
        on.keyword('{').prepend(Formatting.oneSpace());
        f.elementBlock(m);
    });
    rules.set('ModeTransition', (n: AstNode, f: AdlFormatter) => {
        const t = n as ModeTransition;
        const on = f.on(t);
        on.keyword('->').surround(Formatting.oneSpace());
        if (t.guard) {
            on.keyword('[').prepend(Formatting.oneSpace());
            on.keyword('[').append(Formatting.noSpace());
            on.keyword(']').prepend(Formatting.noSpace());
        }
        if (t.event) on.property('event').prepend(Formatting.oneSpace());
        if (t.tick) on.keyword('Tick').prepend(Formatting.oneSpace());
        on.keyword('/').surround(Formatting.oneSpace());
        f.semicolons(t);
    });
}

function describeMode(m: Mode, language: string): string {
    const automaton = enclosingModeAutomaton(m);
    const component = automaton && modeAutomatonComponent(automaton);
    const lines = [`\`\`\`${language}\n${m.initial ? 'initial ' : ''}mode ${m.name}\n\`\`\``];
    lines.push(
        `${m.initial ? 'Initial mode' : 'Mode'} of the ${automaton ? modeAutomatonTiming(automaton) : ''} mode automaton of \`${component?.name ?? '?'}\`.`.replace(
            / {2,}/g,
            ' ',
        ),
    );
    const subs = modeSubcomponents(m);
    if (subs.length) lines.push(`**Subcomponents**: ${subs.map((s) => `\`${s.name}\``).join(', ')}`);
    const connectors = modeConnectors(m);
    if (connectors.length) lines.push(`**Connectors**: ${connectors.length}`);
    if (automaton) {
        const out = modeTransitionsOf(automaton).filter((t) => t.source?.ref === m);
        if (out.length) {
            lines.push(
                `**Transitions**\n\n${out
                    .map((t) => {
                        const on = t.tick ? ' Tick' : t.event ? ` ${t.event.$refText}` : '';
                        return `- \`-> ${t.target?.$refText ?? '?'}${t.guard ? ` [${sourceText(t.guard)}]` : ''}${on}\``;
                    })
                    .join('\n')}`,
            );
        }
    }
    return lines.join('\n\n');
}
