import { AstUtils, URI, type AstNode, type AstNodeDescription, type LangiumSharedCoreServices, type ReferenceInfo, type Scope, type ValidationAcceptor } from 'langium';
import type { Range } from 'vscode-languageserver-types';
import {
    LookupScope, type AdlDocumentValidator, type AdlLspServices, type AdlScopeProvider, type AdlServices, type DiagnosticCatalog, type LanguageRegistration
} from '@maa/language-adl';
import type { Application } from '../generated/ast.js';
import type { RegisteredGenerator } from '../registry/registry.js';
import { checkApplication, type AppFinding } from './app-checks.js';
import { APP_DIAGNOSTICS } from './app-diagnostics.js';
import { AppCodes } from './codes.js';
import { generatorRegistryFor } from './registry-provider.js';

/**
 * What a generator reference (`ros2.Components;`) resolves to: a node standing for the
 * registry entry (generators are described by manifests, not by model files). Its description
 * points at the manifest's file (`documentUri`) and JSON field (`path`), so references,
 * completion and hover work like for model elements; go-to-definition can use
 * `generatorDefinition` to jump into the manifest.
 */
export interface GeneratorDeclarationNode extends AstNode {
    readonly $type: 'GeneratorDeclaration';
    readonly name: string;
    readonly generator: RegisteredGenerator;
}

const declarations = new WeakMap<RegisteredGenerator, GeneratorDeclarationNode>();

export function generatorDeclaration(g: RegisteredGenerator): GeneratorDeclarationNode {
    let node = declarations.get(g);
    if (!node) {
        // `$comment` is what Langium's documentation provider shows in completion and hover.
        node = { $type: 'GeneratorDeclaration', name: g.manifest.name, generator: g, $comment: generatorComment(g) } as GeneratorDeclarationNode;
        declarations.set(g, node);
    }
    return node;
}

/** A short JSDoc-style description of a registered generator. */
function generatorComment(g: RegisteredGenerator): string {
    const m = g.manifest;
    const what = m.kind === 'behavior' ? `behavior generator for \`${m.language}\``
        : m.kind === 'component' ? `component generator${m.supports.length > 0 ? ` (also translates ${m.supports.map((l) => `\`${l}\``).join(', ')})` : ''}`
            : 'data type generator';
    const lines = [
        `**${m.name}**: ${what}; output ${m.output.gpl}${m.output.rte ? `, run-time environment ${m.output.rte}` : ''}.`,
        ...(m.description ? ['', m.description] : []),
        '',
        `Checks: ${m.checks.length > 0 ? m.checks.join(', ') : 'none'}. Package: ${g.source.packageName}@${g.source.packageVersion}.`
    ];
    return `/**\n${lines.map((l) => ` * ${l}`.trimEnd()).join('\n')}\n */`;
}

export function isGeneratorDeclarationNode(node: unknown): node is GeneratorDeclarationNode {
    return typeof node === 'object' && node !== null && (node as AstNode).$type === 'GeneratorDeclaration' && 'generator' in node;
}

/** The URI a registered generator's manifest lives at (a `maa-generator:` URI for inline registries). */
export function manifestUri(g: RegisteredGenerator): URI {
    const f = g.source.file;
    return f.startsWith('/') || /^[A-Za-z]:[\\/]/.test(f) ? URI.file(f) : URI.from({ scheme: 'maa-generator', path: `/${g.manifest.name}` });
}

function describe(g: RegisteredGenerator): AstNodeDescription {
    return {
        name: g.manifest.name,
        type: 'GeneratorDeclaration',
        documentUri: manifestUri(g),
        path: g.source.field,
        node: generatorDeclaration(g)
    };
}

/**
 * Where go-to-definition on a generator name should jump: the manifest file and the range of
 * its `"name": "..."` entry, given the text of that file (0-based positions).
 */
export function generatorDefinition(node: GeneratorDeclarationNode, manifestText: string): { uri: string; range: Range } {
    const g = node.generator;
    const escaped = g.manifest.name.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
    const m = new RegExp(`"name"\\s*:\\s*"(${escaped})"`).exec(manifestText);
    const offset = m ? m.index + m[0].lastIndexOf(m[1]!) : 0;
    const before = manifestText.substring(0, offset);
    const line = before.split('\n').length - 1;
    const character = offset - (before.lastIndexOf('\n') + 1);
    const length = m ? g.manifest.name.length : 0;
    return { uri: manifestUri(g).toString(), range: { start: { line, character }, end: { line, character: character + length } } };
}

function generatorScope(shared: LangiumSharedCoreServices, context: ReferenceInfo): Scope {
    const registry = generatorRegistryFor(shared, AstUtils.getDocument(context.container).uri);
    return new LookupScope((name) => {
        const g = registry.get(name);
        return g ? describe(g) : undefined;
    }, () => registry.all().map(describe));
}

/**
 * The application configuration language as registered in a language family (package.json
 * `maa.language.languages`, export `ArcAppLanguage`): `.arcapp` documents get the host's
 * scoping for the component name, the generator registry for generator names, codes for
 * unresolved names, and the `app/*` checks.
 */
export const ArcAppLanguage: LanguageRegistration & { readonly diagnostics: DiagnosticCatalog } = {
    languageId: 'arcapp',
    diagnostics: APP_DIAGNOSTICS,
    register(services: AdlServices): void {
        const scopes = services.references.ScopeProvider as AdlScopeProvider;
        const resolver = services.maa.NameResolver;
        scopes.contributions.set('Application.component', (ctx) => new LookupScope(
            (name) => resolver.resolveComponent(ctx.container, name),
            () => resolver.visible(ctx.container, 'component')));
        scopes.contributions.set('AppGeneratorRef.generator', (ctx) => generatorScope(services.shared, ctx));

        const validator = services.validation.DocumentValidator as AdlDocumentValidator;
        validator.linkCodes.set('Application.component', {
            code: AppCodes.UnknownComponent,
            message: (name) => `Component type '${name}' cannot be resolved: name the architecture's top component by its qualified name (e.g. 'toast.ToastServiceRobot').`
        });
        validator.linkCodes.set('AppGeneratorRef.generator', {
            code: AppCodes.UnknownGenerator,
            message: (name) => `Generator '${name}' is not installed: no installed package declares it ('maa-gen generators' lists the installed generators).`
        });

        services.validation.ValidationRegistry.register({
            Application: (app: AstNode, accept: ValidationAcceptor) => {
                const application = app as Application;
                const registry = generatorRegistryFor(services.shared, AstUtils.getDocument(app).uri);
                for (const f of checkApplication(application, registry)) report(f, accept);
            }
        });
    },
    registerLsp: registerArcAppLsp
};

/**
 * Editor support beyond the shared scope (completion and hover of generator names come from it):
 * go to definition on a generator name opens its manifest at the `"name"` entry.
 */
function registerArcAppLsp(services: AdlLspServices): void {
    const files = services.shared.workspace.FileSystemProvider;
    services.lsp.DefinitionProvider.targets.push(async (target) => {
        if (!isGeneratorDeclarationNode(target)) return undefined;
        const uri = manifestUri(target.generator);
        let text = '';
        try {
            if (uri.scheme === 'file') text = await files.readFile(uri);
        } catch {
            // unreadable manifest: jump to its start
        }
        return generatorDefinition(target, text);
    });
}

function report(f: AppFinding, accept: ValidationAcceptor): void {
    const related = f.modelNode ? modelLocation(f.modelNode) : undefined;
    const where = related ? ` (${related.display})` : '';
    accept(f.severity, where ? f.message.replace(/\.?$/, `${where}.`) : f.message, {
        node: f.node,
        property: f.property,
        code: f.code,
        relatedInformation: related
            ? [{ location: { uri: related.uri, range: related.range }, message: `violates ${f.rule} of generator '${f.generator}'` }]
            : undefined
    });
}

function modelLocation(node: AstNode): { uri: string; range: Range; display: string } | undefined {
    const cst = node.$cstNode;
    if (!cst) return undefined;
    const doc = AstUtils.getDocument(node);
    const file = doc.uri.path.substring(doc.uri.path.lastIndexOf('/') + 1);
    return { uri: doc.uri.toString(), range: cst.range, display: `${file}:${cst.range.start.line + 1}` };
}
