import { CstUtils, type AstNode, type LangiumDocument, type MaybePromise } from 'langium';
import type { CodeActionProvider } from 'langium/lsp';
import type { CodeActionParams } from 'vscode-languageserver-protocol';
import {
    CodeActionKind,
    type CodeAction,
    type Command,
    type Diagnostic,
    type TextEdit,
    type WorkspaceEdit,
} from 'vscode-languageserver-types';
import type { AdlLspServices } from './lsp-module.js';

/** What a quick fix gets: the diagnostic it fixes, its document and the node at its start. */
export interface QuickFixContext {
    readonly document: LangiumDocument;
    readonly diagnostic: Diagnostic;
    /** The innermost AST node at the start of the diagnostic's range. */
    readonly node: AstNode | undefined;
    /** The services of the document's language. */
    readonly services: AdlLspServices;
}

/** Computes the fixes for one diagnostic (none, one or several alternatives). */
export type QuickFix = (context: QuickFixContext) => MaybePromise<CodeAction | CodeAction[] | undefined>;

/**
 * Quick fixes keyed by diagnostic code (`arc/missing-port`, `automaton/missing-state`, ...).
 * Any language of the family registers fixes for its codes with `register`; a code may have
 * several fixes, each may offer several alternatives.
 */
export class AdlCodeActionProvider implements CodeActionProvider {
    private readonly fixes = new Map<string, QuickFix[]>();

    constructor(private readonly services: AdlLspServices) {}

    register(code: string, fix: QuickFix): void {
        const list = this.fixes.get(code) ?? [];
        list.push(fix);
        this.fixes.set(code, list);
    }

    /** The codes that have quick fixes. */
    codes(): string[] {
        return [...this.fixes.keys()].sort();
    }

    async getCodeActions(document: LangiumDocument, params: CodeActionParams): Promise<Array<Command | CodeAction>> {
        if (params.context.only && !params.context.only.some((k) => CodeActionKind.QuickFix.startsWith(k))) return [];
        const result: CodeAction[] = [];
        for (const diagnostic of params.context.diagnostics) {
            const fixes = this.fixes.get(String(diagnostic.code ?? ''));
            if (!fixes) continue;
            const context: QuickFixContext = { document, diagnostic, node: this.nodeAt(document, diagnostic), services: this.services };
            const actions: CodeAction[] = [];
            for (const fix of fixes) {
                try {
                    const r = await fix(context);
                    if (r) actions.push(...(Array.isArray(r) ? r : [r]));
                } catch (e) {
                    console.error(`quick fix for ${String(diagnostic.code)} failed:`, e);
                }
            }
            for (const a of actions) {
                a.kind ??= CodeActionKind.QuickFix;
                a.diagnostics ??= [diagnostic];
            }
            if (actions.length === 1) actions[0]!.isPreferred ??= true;
            result.push(...actions);
        }
        return result;
    }

    private nodeAt(document: LangiumDocument, diagnostic: Diagnostic): AstNode | undefined {
        const cst = document.parseResult.value.$cstNode;
        if (!cst) return undefined;
        const leaf = CstUtils.findLeafNodeAtOffset(cst, document.textDocument.offsetAt(diagnostic.range.start));
        return leaf?.astNode;
    }
}

/** A quick fix that edits one document. */
export function fixIn(title: string, document: LangiumDocument, edits: Array<TextEdit | undefined>): CodeAction | undefined {
    const list = edits.filter((e): e is TextEdit => !!e);
    if (list.length === 0) return undefined;
    return { title, kind: CodeActionKind.QuickFix, edit: { changes: { [document.uri.toString()]: list } } };
}

/** A quick fix that applies a workspace edit. */
export function fixWith(title: string, edit: WorkspaceEdit | undefined): CodeAction | undefined {
    return edit ? { title, kind: CodeActionKind.QuickFix, edit } : undefined;
}

/** Merges text edits for several documents into one workspace edit. */
export function mergeEdits(...parts: Array<{ uri: string; edit: TextEdit | undefined }>): WorkspaceEdit | undefined {
    const changes: Record<string, TextEdit[]> = {};
    for (const { uri, edit } of parts) if (edit) (changes[uri] ??= []).push(edit);
    return Object.keys(changes).length ? { changes } : undefined;
}
