import { AstUtils, GrammarUtils, type AstNode } from 'langium';
import { Formatting } from 'langium/lsp';
import {
    CodeActionKind,
    CompletionItemKind,
    SemanticTokenModifiers,
    SemanticTokenTypes,
    SymbolKind,
    type CodeAction,
} from 'vscode-languageserver-types';
import {
    enclosingComponent,
    fixIn,
    insertIntoBody,
    sourceText,
    type AdlFormatter,
    type AdlLspServices,
    type QuickFixContext,
} from '@maa/language-adl';
import type { Automaton, InternalTransition, State, Transition } from '../generated/ast.js';
import {
    automatonTiming,
    enclosingAutomaton,
    initialStates,
    isHierarchical,
    isAnyTransition,
    sourceOf,
    stateActions,
    substates,
    triggerOf,
    type AnyTransition,
} from '../automaton-model.js';
import { AutomatonCodes } from '../codes.js';

/**
 * The automaton language's LSP contributions (BehaviorLanguage.registerLsp): outline entries for
 * automata, states and transitions; the token style of states (declarations, transition sources
 * and targets); `Tick` as an event; formatting rules in MontiArc's automaton style; hover for
 * states; quick fixes for `automaton/missing-state` and `automaton/no-initial-state`.
 * Completion, go-to-definition, references and rename of states and events follow from the
 * scopes the language registers (AutomataLanguage.register).
 */
export function registerAutomatonLsp(services: AdlLspServices): void {
    const kinds = services.shared.lsp.NodeKindProvider.kinds;
    kinds.set('Automaton', { symbol: SymbolKind.Namespace, completion: CompletionItemKind.Module });
    kinds.set('State', { symbol: SymbolKind.EnumMember, completion: CompletionItemKind.EnumMember });
    kinds.set('Transition', { symbol: SymbolKind.Event, completion: CompletionItemKind.Event });
    kinds.set('InternalTransition', { symbol: SymbolKind.Event, completion: CompletionItemKind.Event });

    registerSymbols(services);
    registerTokens(services);
    registerFormatting(services.lsp.Formatter);
    services.lsp.HoverProvider.contributions.set('State', (n) => describeState(n as State, services.lsp.HoverProvider.languageOf(n)));
    services.lsp.CodeActionProvider.register(AutomatonCodes.MissingState, createMissingState);
    services.lsp.CodeActionProvider.register(AutomatonCodes.NoInitialState, markInitial);
}

function registerSymbols(services: AdlLspServices): void {
    const symbols = services.lsp.DocumentSymbolProvider.contributions;
    symbols.set('Automaton', (n) => ({
        name: 'automaton',
        detail: automatonTiming(n as Automaton),
        selection: GrammarUtils.findNodeForKeyword(n.$cstNode, 'automaton'),
    }));
    symbols.set('State', (n) => {
        const s = n as State;
        if (!s.name) return 'skip';
        const facts = [s.initial ? 'initial' : undefined, isHierarchical(s) ? 'hierarchical' : undefined].filter(Boolean);
        return { name: s.name, detail: facts.join(', ') || undefined };
    });
    const transition = (n: AstNode): { name: string; detail?: string } => {
        const t = n as AnyTransition;
        const name = t.$type === 'InternalTransition' ? '-> (internal)' : `${t.source?.$refText ?? '?'} -> ${t.target?.$refText ?? '?'}`;
        const parts = [t.guard ? `[${sourceText(t.guard)}]` : undefined, t.tick ? 'Tick' : t.event?.$refText].filter(Boolean);
        return { name, detail: parts.join(' ') || undefined };
    };
    symbols.set('Transition', transition);
    symbols.set('InternalTransition', transition);
    symbols.set('StateAction', () => 'skip');
}

function registerTokens(services: AdlLspServices): void {
    const tokens = services.lsp.SemanticTokenProvider;
    tokens.styles.set('State', { type: SemanticTokenTypes.namespace });
    const tick = (n: AstNode, accept: Parameters<NonNullable<ReturnType<typeof tokens.highlighters.get>>>[1]): void => {
        if ((n as AnyTransition).tick)
            accept({ node: n, keyword: 'Tick', type: SemanticTokenTypes.event, modifier: SemanticTokenModifiers.defaultLibrary });
    };
    tokens.highlighters.set('Transition', tick);
    tokens.highlighters.set('InternalTransition', tick);
}

function registerFormatting(formatter: AdlFormatter): void {
    const rules = formatter.rules;
    rules.set('Automaton', (n, f) => {
        f.on(n).keyword('automaton').append(Formatting.oneSpace());
        f.elementBlock(n);
    });
    rules.set('State', (n, f) => {
        const s = n as State;
        const on = f.on(s);
        if (s.final) on.keyword('final').append(Formatting.oneSpace());
        if (s.initial) on.keyword('initial').append(Formatting.oneSpace());
        on.keyword('state').append(Formatting.oneSpace());
        if (s.initialAction) on.node(s.initialAction).append(Formatting.oneSpace());
        on.keywords(';').prepend(Formatting.noSpace());
        if (GrammarUtils.findNodeForKeyword(s.$cstNode, '{')) {
            on.keyword('{').prepend(Formatting.oneSpace());
            f.elementBlock(s);
        }
    });
    rules.set('StateAction', (n, f) => {
        f.keywordSpacing(n, { around: ['/'] });
        f.semicolons(n);
    });
    const transition = (n: AstNode, f: AdlFormatter): void => {
        const t = n as Transition | InternalTransition;
        const on = f.on(t);
        if (t.$type === 'Transition') on.keyword('->').surround(Formatting.oneSpace());
        else on.keyword('->').append(Formatting.oneSpace());
        if (t.guard) {
            // After `->` of an internal transition the guard follows directly (spacing above).
            if (t.$type === 'Transition') on.keyword('[').prepend(Formatting.oneSpace());
            on.keyword('[').append(Formatting.noSpace());
            on.keyword(']').prepend(Formatting.noSpace());
        }
        if (t.event) on.property('event').prepend(Formatting.oneSpace());
        if (t.tick) on.keyword('Tick').prepend(Formatting.oneSpace());
        on.keyword('/').surround(Formatting.oneSpace());
        f.semicolons(t);
    };
    rules.set('Transition', transition);
    rules.set('InternalTransition', transition);
}

function describeState(s: State, language: string): string {
    const automaton = enclosingAutomaton(s);
    const component = automaton && enclosingComponent(automaton);
    const parent = s.$container.$type === 'State' ? (s.$container as State) : undefined;
    const lines = [`\`\`\`${language}\n${s.initial ? 'initial ' : ''}state ${s.name}\n\`\`\``];
    const role = `${s.initial ? 'Initial state' : 'State'} ${parent ? `(substate of \`${parent.name}\`) ` : ''}of the ${automaton ? automatonTiming(automaton) : ''} automaton of \`${component?.name ?? '?'}\`.`;
    lines.push(role.replace(/ {2,}/g, ' '));
    const subs = substates(s);
    if (subs.length) lines.push(`**Substates**: ${subs.map((x) => `\`${x.name}\``).join(', ')}`);
    const actions = (['entry', 'exit', 'do'] as const).filter((k) => stateActions(s, k).length > 0);
    if (actions.length) lines.push(`**Actions**: ${actions.join(', ')}`);
    if (automaton) {
        const out = AstUtils.streamAllContents(automaton)
            .filter(isAnyTransition)
            .filter((t) => sourceOf(t) === s)
            .toArray();
        if (out.length) {
            lines.push(
                `**Transitions**\n\n${out
                    .map((t) => {
                        const trigger = triggerOf(t);
                        const on = trigger.kind === 'tick' ? ' Tick' : trigger.kind === 'port' ? ` ${trigger.name}` : '';
                        const target =
                            t.$type === 'InternalTransition' ? t.$container.name : (t.target?.ref?.name ?? t.target?.$refText ?? '?');
                        return `- \`-> ${target}${t.guard ? ` [${sourceText(t.guard)}]` : ''}${on}\``;
                    })
                    .join('\n')}`,
            );
        }
    }
    return lines.join('\n\n');
}

/** `automaton/missing-state`: declare the state at the level of the transition. */
function createMissingState(ctx: QuickFixContext): CodeAction | undefined {
    const t = ctx.node && AstUtils.getContainerOfType(ctx.node, isAnyTransition);
    if (t?.$type !== 'Transition') return undefined;
    const name = ctx.document.textDocument.getText(ctx.diagnostic.range).trim();
    if (!/^[_a-zA-Z$][\w$]*$/.test(name)) return undefined;
    const level = t.$container as Automaton | State;
    const states = substates(level);
    const anchor = states[states.length - 1];
    const edit = insertIntoBody(ctx.document, level, `state ${name};`, anchor);
    return fixIn(`Create state '${name}'`, ctx.document, [edit]);
}

/** `automaton/no-initial-state`: mark a state of the level `initial`. */
function markInitial(ctx: QuickFixContext): CodeAction[] {
    const node = ctx.node;
    const automaton = node && (node.$type === 'Automaton' ? (node as Automaton) : enclosingAutomaton(node));
    if (!automaton) return [];
    const state = AstUtils.getContainerOfType(node, (n): n is State => n.$type === 'State');
    const level: Automaton | State = state && isHierarchical(state) && initialStates(state).length === 0 ? state : automaton;
    return substates(level)
        .slice(0, 5)
        .flatMap((s) => {
            const keyword = GrammarUtils.findNodeForKeyword(s.$cstNode, 'state');
            if (!keyword) return [];
            return [
                {
                    title: `Make '${s.name}' the initial state`,
                    kind: CodeActionKind.QuickFix,
                    edit: {
                        changes: {
                            [ctx.document.uri.toString()]: [
                                { range: { start: keyword.range.start, end: keyword.range.start }, newText: 'initial ' },
                            ],
                        },
                    },
                },
            ];
        });
}
