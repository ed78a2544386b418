import { AstUtils, GrammarUtils, UriUtils, type AstNode } from 'langium';
import { CodeActionKind, type CodeAction, type TextEdit } from 'vscode-languageserver-types';
import {
    allPorts,
    elementsOf,
    enclosingComponent,
    fixIn,
    fixWith,
    importEdits,
    importName,
    insertIntoBody,
    isIdentifier,
    sourceText,
    type AdlCodeActionProvider,
    type QuickFixContext,
} from '@maa/language-adl';
import type { CDEnum, ComponentType, Location, MoveArgument, RobotArm, RobotArmInput, RobotArmModel } from '../generated/ast.js';
import { RobotArmCodes } from '../codes.js';
import {
    enclosingRobotArm,
    INPUT_UNITS,
    inputsOf,
    isEmbedded,
    locationsOf,
    parseMeasure,
    programForCommand,
    programsOf,
    protocolPorts,
    robotArmComponent,
    RobotArmProtocol,
    type RobotArmBody,
} from '../robotarm-model.js';

/** At most this many alternatives per diagnostic. */
const MAX_ALTERNATIVES = 5;

/** A new location's pose when the quick fix creates one: base at 0deg, lift at mid height (the modeler adjusts it). */
export const NEW_LOCATION_POSE = '0deg 20cm';

/** RobotArm's quick fixes, keyed by its diagnostic codes (docs/robotarm.md, docs/diagnostics.md). */
export function registerRobotArmFixes(actions: AdlCodeActionProvider): void {
    actions.register(RobotArmCodes.UnresolvedName, fixUnresolvedName);
    actions.register(RobotArmCodes.InputInEmbedded, fixInputInEmbedded);
    actions.register(RobotArmCodes.MissingCmdPort, (ctx) => fixProtocolPort(ctx, 'cmd'));
    actions.register(RobotArmCodes.MissingStatusPort, (ctx) => fixProtocolPort(ctx, 'status'));
    actions.register(RobotArmCodes.NamingConvention, fixNamingConvention);
    actions.register(RobotArmCodes.InvalidUnit, fixMissingUnit);
    actions.register(RobotArmCodes.FileNameMismatch, fixFileName);
    actions.register(RobotArmCodes.PackageMismatch, fixPackage);
}

function containerOfType<T extends AstNode>(node: AstNode | undefined, ...types: string[]): T | undefined {
    return node ? AstUtils.getContainerOfType(node, (n): n is T => types.includes(n.$type)) : undefined;
}

/** The element after which a new input or location goes: the last of its kind, else the last input. */
function anchorFor(body: RobotArmBody, kind: 'input' | 'location'): AstNode | undefined {
    const inputs = inputsOf(body);
    const locations = locationsOf(body);
    if (kind === 'location') return locations[locations.length - 1] ?? inputs[inputs.length - 1];
    return inputs[inputs.length - 1];
}

/** The edit that adds a port declaration to a component, after its last port declaration. */
function addPortEdit(component: ComponentType, text: string): TextEdit | undefined {
    const lastPortDecl = [...elementsOf(asHost(component))].reverse().find((e) => e.$type === 'PortDeclaration');
    return component.body ? insertIntoBody(AstUtils.getDocument(component), component.body, text, lastPortDecl) : undefined;
}

/**
 * `robotarm/unresolved-name`: `move x;` names a pose, so create a location `x`; in a joint move
 * (`move x height;`) `x` is a joint value: create an input (`.ra`) or an incoming port (embedded).
 */
function fixUnresolvedName(ctx: QuickFixContext): CodeAction | undefined {
    const arg = containerOfType<MoveArgument>(ctx.node, 'MoveArgument');
    const body = arg && enclosingRobotArm(arg);
    const name = arg?.target?.$refText ?? '';
    if (!arg || !body || !isIdentifier(name)) return undefined;
    if (arg.$container.arguments.length === 1) {
        const edit = insertIntoBody(ctx.document, body, `location ${name} ${NEW_LOCATION_POSE};`, anchorFor(body, 'location'));
        return fixIn(`Create location '${name}'`, ctx.document, [edit]);
    }
    if (arg.$container.arguments.length !== 2) return undefined;
    if (isEmbedded(body)) {
        const component = robotArmComponent(body);
        if (!component || component !== (enclosingComponent(body) as unknown)) return undefined;
        return fixIn(`Create incoming port '${name}' in '${component.name}'`, ctx.document, [
            addPortEdit(component, `port in int ${name};`),
        ]);
    }
    return fixIn(`Create input '${name}'`, ctx.document, [
        insertIntoBody(ctx.document, body, `input int ${name};`, anchorFor(body, 'input')),
    ]);
}

/** The edit that removes a node, with its line when it stands alone on it. */
function removeEdit(ctx: QuickFixContext, node: AstNode): TextEdit | undefined {
    const cst = node.$cstNode;
    if (!cst) return undefined;
    const doc = ctx.document.textDocument;
    const { start, end } = cst.range;
    const before = doc.getText({ start: { line: start.line, character: 0 }, end: start });
    const after = doc.getText({ start: end, end: { line: end.line + 1, character: 0 } });
    if (before.trim() === '' && after.trim() === '')
        return { range: { start: { line: start.line, character: 0 }, end: { line: end.line + 1, character: 0 } }, newText: '' };
    return { range: cst.range, newText: '' };
}

/**
 * `robotarm/input-in-embedded`: remove the input; when the component has no port of that name,
 * alternatively replace it by an incoming port of the input's type (what `move` then reads).
 */
function fixInputInEmbedded(ctx: QuickFixContext): CodeAction[] {
    const input = containerOfType<RobotArmInput>(ctx.node, 'RobotArmInput');
    const body = input?.$container;
    if (!input || !body || !isEmbedded(body)) return [];
    const remove = removeEdit(ctx, input);
    const out: CodeAction[] = [];
    const component = robotArmComponent(body);
    const type = sourceText(input.type);
    const hasPort = component !== undefined && allPorts(asHost(component)).some((p) => p.name === input.name);
    if (component && !hasPort && type && isIdentifier(input.name) && component === enclosingComponent(body)) {
        const a = fixIn(`Replace input '${input.name}' by 'port in ${type} ${input.name};'`, ctx.document, [
            addPortEdit(component, `port in ${type} ${input.name};`),
            remove,
        ]);
        if (a) out.push(a);
    }
    const r = fixIn(`Remove input '${input.name}'`, ctx.document, [remove]);
    if (r) out.push(r);
    return out;
}

/** A component of this grammar build as the host's model API sees it (the same AST, typed per build). */
function asHost(c: ComponentType): Parameters<typeof allPorts>[0] {
    return c as unknown as Parameters<typeof allPorts>[0];
}

/**
 * `robotarm/missing-cmd-port`, `robotarm/missing-status-port`: declare the port with an enum of
 * the model root that fits the protocol (for `cmd`: its constants select programs of the block;
 * for `status`: it has IDLE, BUSY and DONE), importing it where needed; a protocol port with the
 * wrong direction is turned around.
 */
function fixProtocolPort(ctx: QuickFixContext, which: 'cmd' | 'status'): CodeAction[] {
    const body = ctx.node && (ctx.node.$type === 'RobotArm' ? (ctx.node as RobotArm) : enclosingRobotArm(ctx.node));
    if (!body || !isEmbedded(body)) return [];
    const component = robotArmComponent(body);
    if (!component || component !== (enclosingComponent(body) as unknown)) return [];
    const direction = which === 'cmd' ? 'in' : 'out';
    const portName = which === 'cmd' ? RobotArmProtocol.commandPort : RobotArmProtocol.statusPort;
    const existing = protocolPorts(body)[which];
    if (existing) {
        if (existing.direction === direction || AstUtils.getDocument(existing.port) !== ctx.document) return [];
        const cst = GrammarUtils.findNodeForProperty(existing.port.$cstNode, 'direction');
        if (!cst) return [];
        const a = fixIn(`Make port '${portName}' ${direction === 'in' ? 'incoming' : 'outgoing'}`, ctx.document, [
            { range: cst.range, newText: direction },
        ]);
        return a ? [a] : [];
    }
    const resolver = ctx.services.maa.NameResolver;
    const seen = new Set<AstNode>();
    const candidates: Array<{ decl: CDEnum; score: number }> = [];
    for (const d of resolver.visible(component, 'type')) {
        if (d.type !== 'CDEnum' || !d.node || seen.has(d.node)) continue;
        seen.add(d.node);
        const decl = d.node as CDEnum;
        const constants = decl.constants.map((c) => c.name);
        if (which === 'status') {
            if (RobotArmProtocol.statusValues.every((v) => constants.includes(v))) candidates.push({ decl, score: -constants.length });
            continue;
        }
        const commands = constants.filter((c) => c !== RobotArmProtocol.noCommand);
        if (commands.length === 0 || !commands.every((c) => programForCommand(body, c))) continue;
        const covered = programsOf(body).filter((p) => commands.some((c) => programForCommand(body, c) === p)).length;
        candidates.push({ decl, score: covered });
    }
    candidates.sort((a, b) => b.score - a.score || a.decl.name.localeCompare(b.decl.name));
    const out: CodeAction[] = [];
    for (const { decl } of candidates.slice(0, MAX_ALTERNATIVES)) {
        const resolved = resolver.resolveType(component, decl.name);
        let type = decl.name;
        let imports: TextEdit[] = [];
        if (resolved && resolved.node !== decl) type = importName(decl) ?? decl.name;
        else if (!resolved) {
            const qn = importName(decl);
            if (!qn) continue;
            imports = importEdits(ctx.document, qn);
            if (imports.length === 0) type = qn;
        }
        const a = fixIn(`Declare 'port ${direction} ${type} ${portName};' in '${component.name}'`, ctx.document, [
            ...imports,
            addPortEdit(component, `port ${direction} ${type} ${portName};`),
        ]);
        if (a) out.push(a);
    }
    return out;
}

/** `robotarm/naming-convention`: rename to the convention (programs and robot arms upper case, the rest lower case). */
function fixNamingConvention(ctx: QuickFixContext): CodeAction | undefined {
    const node = containerOfType<AstNode & { name: string }>(ctx.node, 'Program', 'RobotArmDefinition', 'Location', 'RobotArmInput');
    if (!node?.name) return undefined;
    const upper = node.$type === 'Program' || node.$type === 'RobotArmDefinition';
    const fixed = (upper ? node.name.charAt(0).toUpperCase() : node.name.charAt(0).toLowerCase()) + node.name.substring(1);
    if (fixed === node.name) return undefined;
    return fixWith(`Rename '${node.name}' to '${fixed}'`, ctx.services.lsp.RenameProvider.renameElement(node, fixed));
}

/**
 * `robotarm/invalid-unit` for a value without a unit: add the unit in which values are read
 * (`deg` for a joint angle, `cm` for a gripper height, as for inputs and ports).
 */
function fixMissingUnit(ctx: QuickFixContext): CodeAction | undefined {
    const node = containerOfType<Location | MoveArgument>(ctx.node, 'Location', 'MoveArgument');
    if (!node) return undefined;
    const start = ctx.document.textDocument.offsetAt(ctx.diagnostic.range.start);
    let property: 'angle' | 'height' | 'value' | undefined;
    for (const p of ['angle', 'height', 'value'] as const) {
        const cst = GrammarUtils.findNodeForProperty(node.$cstNode, p);
        if (cst && cst.offset <= start && start < cst.end) property = p;
    }
    if (!property) return undefined;
    const cst = GrammarUtils.findNodeForProperty(node.$cstNode, property)!;
    const m = parseMeasure((node as unknown as Record<string, string | undefined>)[property]);
    if (!m || m.unit) return undefined;
    let dimension: 'angle' | 'height';
    if (property === 'value') {
        const args = (node as MoveArgument).$container.arguments;
        if (args.length !== 2) return undefined;
        dimension = args.indexOf(node as MoveArgument) === 0 ? 'angle' : 'height';
    } else dimension = property;
    const unit = INPUT_UNITS[dimension];
    return {
        title: `Add the unit '${unit}' (${cst.text}${unit})`,
        kind: CodeActionKind.QuickFix,
        edit: { changes: { [ctx.document.uri.toString()]: [{ range: { start: cst.range.end, end: cst.range.end }, newText: unit }] } },
    };
}

/** `robotarm/file-name-mismatch`: rename the robot arm after the file, or the file after the robot arm. */
function fixFileName(ctx: QuickFixContext): CodeAction[] {
    const root = ctx.document.parseResult.value as RobotArmModel;
    const robot = root.robot;
    if (root.$type !== 'RobotArmModel' || !robot?.name) return [];
    const base = UriUtils.basename(ctx.document.uri);
    const stem = base.endsWith('.ra') ? base.substring(0, base.length - 3) : base;
    const out: CodeAction[] = [];
    const name = GrammarUtils.findNodeForProperty(robot.$cstNode, 'name');
    if (isIdentifier(stem) && name) {
        const a = fixIn(`Rename '${robot.name}' to '${stem}'`, ctx.document, [{ range: name.range, newText: stem }]);
        if (a) out.push(a);
    }
    const newUri = UriUtils.joinPath(UriUtils.dirname(ctx.document.uri), `${robot.name}.ra`).toString();
    out.push({
        title: `Rename file to '${robot.name}.ra'`,
        kind: CodeActionKind.QuickFix,
        edit: { documentChanges: [{ kind: 'rename', oldUri: ctx.document.uri.toString(), newUri }] },
    });
    return out;
}

/** `robotarm/package-mismatch`: make the package declaration of a `.ra` file match its folder. */
function fixPackage(ctx: QuickFixContext): CodeAction | undefined {
    const root = ctx.document.parseResult.value as RobotArmModel;
    if (root.$type !== 'RobotArmModel') return undefined;
    const expected = ctx.services.shared.maa.ModelRoots.expectedPackage(ctx.document.uri);
    const packageCst = GrammarUtils.findNodeForProperty(root.$cstNode, 'package');
    if (root.package && packageCst) {
        if (expected) return fixIn(`Change package to '${expected}'`, ctx.document, [{ range: packageCst.range, newText: expected }]);
        const keyword = GrammarUtils.findNodeForKeyword(root.$cstNode, 'package');
        const semicolon = GrammarUtils.findNodeForKeyword(root.$cstNode, ';');
        if (!keyword || !semicolon) return undefined;
        const text = ctx.document.textDocument.getText();
        let end = semicolon.end;
        while (end < text.length && /\s/.test(text[end]!)) end++;
        return fixIn('Remove the package declaration (default package)', ctx.document, [
            { range: { start: keyword.range.start, end: ctx.document.textDocument.positionAt(end) }, newText: '' },
        ]);
    }
    if (!expected) return undefined;
    const start = { line: 0, character: 0 };
    return fixIn(`Add 'package ${expected};'`, ctx.document, [{ range: { start, end: start }, newText: `package ${expected};\n\n` }]);
}
