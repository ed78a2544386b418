import { AstUtils, GrammarUtils, type AstNode, type CstNode } from 'langium';
import type { SemanticTokenAcceptor } from 'langium/lsp';
import { CompletionItemKind, SemanticTokenModifiers, SemanticTokenTypes, SymbolKind, type Range } from 'vscode-languageserver-types';
import { sourceText, type AdlLspServices, type TokenStyle } from '@maa/language-adl';
import type { Location, MoveArgument, Program, RobotArm, RobotArmDefinition, RobotArmInput } from '../generated/ast.js';
import { inputsOf, locationsOf, programsOf, type RobotArmBody } from '../robotarm-model.js';
import { registerRobotArmFixes } from './robotarm-fixes.js';
import { registerRobotArmFormatting } from './robotarm-formatting.js';
import { describeInput, describeLocation, describeProgram, describeRobotArm } from './robotarm-hover.js';

/**
 * The RobotArm language's LSP contributions, for both forms: the embedded `robotarm { }` block
 * (`RobotArmLanguage.registerLsp`, into the services of `arc`) and standalone `.ra` files
 * (`RobotArmFileLanguage.registerLsp`, into the services of `ra`):
 * - outline: the robot arm with its inputs, locations and programs (steps are no symbols);
 * - icons for outline and completion;
 * - semantic tokens: locations, inputs and programs at their declarations and after `move`;
 *   the constants `top`/`bottom`; the number and the unit of every measure. A `move` target
 *   that is a port is a reference to the port and is colored like every other use of a port
 *   (the host's style);
 * - formatting (robotarm-formatting.ts), hover (robotarm-hover.ts), quick fixes
 *   (robotarm-fixes.ts).
 * Completion, go-to-definition, find references and rename of `move` targets (locations,
 * inputs, the component's incoming ports) follow from the scope the language registers.
 */
export function registerRobotArmLsp(services: AdlLspServices): void {
    const kinds = services.shared.lsp.NodeKindProvider.kinds;
    kinds.set('RobotArm', { symbol: SymbolKind.Namespace, completion: CompletionItemKind.Module });
    kinds.set('RobotArmDefinition', { symbol: SymbolKind.Class, completion: CompletionItemKind.Module });
    kinds.set('RobotArmInput', { symbol: SymbolKind.Variable, completion: CompletionItemKind.Variable });
    kinds.set('Location', { symbol: SymbolKind.Constant, completion: CompletionItemKind.Constant });
    kinds.set('Program', { symbol: SymbolKind.Function, completion: CompletionItemKind.Function });

    registerSymbols(services);
    registerTokens(services);
    registerRobotArmFormatting(services.lsp.Formatter);
    const hover = services.lsp.HoverProvider;
    const fence = (n: AstNode): string => hover.languageOf(n);
    hover.contributions.set('RobotArm', (n) => describeRobotArm(n as RobotArm, fence(n)));
    hover.contributions.set('RobotArmDefinition', (n) => describeRobotArm(n as RobotArmDefinition, fence(n)));
    hover.contributions.set('Location', (n) => describeLocation(n as Location, fence(n)));
    hover.contributions.set('RobotArmInput', (n) => describeInput(n as RobotArmInput, fence(n)));
    hover.contributions.set('Program', (n) => describeProgram(n as Program, fence(n)));
    registerRobotArmFixes(services.lsp.CodeActionProvider);
}

function count(n: number, what: string): string {
    return `${n} ${what}${n === 1 ? '' : 's'}`;
}

function bodySummary(body: RobotArmBody): string | undefined {
    const parts = [
        inputsOf(body).length ? count(inputsOf(body).length, 'input') : undefined,
        locationsOf(body).length ? count(locationsOf(body).length, 'location') : undefined,
        programsOf(body).length ? count(programsOf(body).length, 'program') : undefined,
    ].filter((p): p is string => !!p);
    return parts.join(', ') || undefined;
}

function registerSymbols(services: AdlLspServices): void {
    const symbols = services.lsp.DocumentSymbolProvider.contributions;
    symbols.set('RobotArm', (n) => ({
        name: 'robotarm',
        detail: bodySummary(n as RobotArm),
        selection: GrammarUtils.findNodeForKeyword(n.$cstNode, 'robotarm'),
    }));
    symbols.set('RobotArmDefinition', (n) => {
        const d = n as RobotArmDefinition;
        if (!d.name) return 'skip';
        return { name: d.name, detail: ['robot arm', bodySummary(d)].filter(Boolean).join(': ') };
    });
    symbols.set('RobotArmInput', (n) => {
        const i = n as RobotArmInput;
        return i.name ? { name: i.name, detail: `input ${sourceText(i.type)}` } : 'skip';
    });
    symbols.set('Location', (n) => {
        const l = n as Location;
        return l.name ? { name: l.name, detail: `${measureText(l, 'angle')} ${measureText(l, 'height')}` } : 'skip';
    });
    symbols.set('Program', (n) => {
        const p = n as Program;
        return p.name ? { name: p.name, detail: count(p.steps.length, 'step') } : 'skip';
    });
    // Steps are the content of a program, not its structure.
    symbols.set('Move', () => 'skip');
    symbols.set('GripperStep', () => 'skip');
}

/** A measure as written, whitespace collapsed (`120deg`, `100 mm`). */
export function measureText(node: AstNode, property: string): string {
    const cst = GrammarUtils.findNodeForProperty(node.$cstNode, property);
    return cst ? sourceText(cst) : String((node as unknown as Record<string, unknown>)[property] ?? '');
}

/** Token styles of RobotArm's declarations (and of every `move` that names them). */
const TOKEN_STYLES: ReadonlyArray<[string, TokenStyle]> = [
    ['RobotArmDefinition', { type: SemanticTokenTypes.class }],
    ['Program', { type: SemanticTokenTypes.function }],
    // A location is a named, fixed pose; `top` and `bottom` are the arm's own (defaultLibrary).
    ['Location', { type: SemanticTokenTypes.variable, modifiers: [SemanticTokenModifiers.readonly] }],
    // Inputs are the programs' parameters, read when a move starts.
    ['RobotArmInput', { type: SemanticTokenTypes.parameter }],
];

function registerTokens(services: AdlLspServices): void {
    const tokens = services.lsp.SemanticTokenProvider;
    for (const [type, style] of TOKEN_STYLES) tokens.styles.set(type, style);
    tokens.highlighters.set('Location', (n, accept) => {
        highlightMeasure(n, 'angle', accept);
        highlightMeasure(n, 'height', accept);
    });
    tokens.highlighters.set('MoveArgument', (n, accept) => {
        const a = n as MoveArgument;
        if (a.constant) {
            // `top` and `bottom`: constants of the arm (its lift positions).
            accept({
                node: a,
                property: 'constant',
                type: SemanticTokenTypes.variable,
                modifier: [SemanticTokenModifiers.readonly, SemanticTokenModifiers.defaultLibrary],
            });
        } else if (a.value !== undefined) {
            highlightMeasure(a, 'value', accept);
        }
    });
}

/**
 * The number of a measure as `number`, its unit as a built-in `type` (the lexer splits `120deg`
 * into the tokens `120d` and `eg`, so both parts are found in the text).
 */
function highlightMeasure(node: AstNode, property: string, accept: SemanticTokenAcceptor): void {
    const cst: CstNode | undefined = GrammarUtils.findNodeForProperty(node.$cstNode, property);
    if (!cst) return;
    const m = /^(-?\s*(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)(\s*)([_a-zA-Z$][\w$]*)?/.exec(cst.text);
    if (!m) return;
    const doc = AstUtils.getDocument(node).textDocument;
    const range = (start: number, length: number): Range => ({
        start: doc.positionAt(cst.offset + start),
        end: doc.positionAt(cst.offset + start + length),
    });
    accept({ range: range(0, m[1]!.length), type: SemanticTokenTypes.number });
    if (m[3])
        accept({
            range: range(m[1]!.length + m[2]!.length, m[3].length),
            type: SemanticTokenTypes.type,
            modifier: SemanticTokenModifiers.defaultLibrary,
        });
}
