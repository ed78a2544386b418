import {
    AstUtils,
    URI,
    type AstNode,
    type AstNodeDescription,
    type Module,
    type ReferenceInfo,
    type Scope,
    type ValidationAcceptor,
} from 'langium';
import type { Range } from 'vscode-languageserver-types';
import {
    LookupScope,
    type AdlDocumentValidator,
    type AdlLspServices,
    type AdlScopeProvider,
    type AdlServices,
    type DiagnosticCatalog,
    type LanguageRegistration,
} from '@maa/language-adl';
import type { Application } from '../generated/ast.js';
import type { RegisteredGenerator } from '../registry/registry.js';
import type { GeneratorDeclarationNode, GeneratorRegistryService } from '../registry/registry-service.js';
import type { AppFinding } from './app-checks.js';
import { APP_DIAGNOSTICS } from './app-diagnostics.js';
import { ArcAppModule, type ArcAppServices } from './arcapp-module.js';
import { AppCodes } from './codes.js';

/** A new declaration node for a registered generator (GeneratorRegistryService.declaration keeps one per generator). */
export function generatorDeclaration(g: RegisteredGenerator): GeneratorDeclarationNode {
    // `$comment` is what Langium's documentation provider shows in completion and hover.
    return {
        $type: 'GeneratorDeclaration',
        name: g.manifest.name,
        generator: g,
        $comment: generatorComment(g),
    } as GeneratorDeclarationNode;
}

/** A short JSDoc-style description of a registered generator. */
function generatorComment(g: RegisteredGenerator): string {
    const m = g.manifest;
    const what =
        m.kind === 'behavior'
            ? `behavior generator for \`${m.language}\``
            : m.kind === 'component'
              ? `component generator${m.supports.length > 0 ? ` (also translates ${m.supports.map((l) => `\`${l}\``).join(', ')})` : ''}`
              : 'data type generator';
    const lines = [
        `**${m.name}**: ${what}; output ${m.output.gpl}${m.output.rte ? `, run-time environment ${m.output.rte}` : ''}.`,
        ...(m.description ? ['', m.description] : []),
        '',
        `Checks: ${m.checks.length > 0 ? m.checks.join(', ') : 'none'}. Package: ${g.source.packageName}@${g.source.packageVersion}.`,
    ];
    return `/**\n${lines.map((l) => ` * ${l}`.trimEnd()).join('\n')}\n */`;
}

export function isGeneratorDeclarationNode(node: unknown): node is GeneratorDeclarationNode {
    return typeof node === 'object' && node !== null && (node as AstNode).$type === 'GeneratorDeclaration' && 'generator' in node;
}

/** The URI a registered generator's manifest lives at (a `maa-generator:` URI for inline registries). */
export function manifestUri(g: RegisteredGenerator): URI {
    const f = g.source.file;
    return f.startsWith('/') || /^[A-Za-z]:[\\/]/.test(f)
        ? URI.file(f)
        : URI.from({ scheme: 'maa-generator', path: `/${g.manifest.name}` });
}

function describe(registry: GeneratorRegistryService, g: RegisteredGenerator): AstNodeDescription {
    return {
        name: g.manifest.name,
        type: 'GeneratorDeclaration',
        documentUri: manifestUri(g),
        path: g.source.field,
        node: registry.declaration(g, generatorDeclaration),
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

function generatorScope(service: GeneratorRegistryService, context: ReferenceInfo): Scope {
    const registry = service.registryFor(AstUtils.getDocument(context.container).uri);
    return new LookupScope(
        (name) => {
            const g = registry.get(name);
            return g ? describe(service, g) : undefined;
        },
        () => registry.all().map((g) => describe(service, g)),
    );
}

/**
 * The application configuration language as registered in a language family (package.json
 * `maa.language.languages`, export `ArcAppLanguage`): `.arcapp` documents get the host's
 * scoping for the component name, the generator registry for generator names, codes for
 * unresolved names, and the `app/*` checks. Its container has the services of ArcAppModule
 * (the generator registry, the analysis of applications).
 */
export const ArcAppLanguage: LanguageRegistration & {
    readonly diagnostics: DiagnosticCatalog;
    readonly module: Module<AdlServices, object>;
} = {
    languageId: 'arcapp',
    diagnostics: APP_DIAGNOSTICS,
    module: ArcAppModule as unknown as Module<AdlServices, object>, // the family injects it into the .arcapp container (typed for every language)
    register(adl: AdlServices): void {
        const services = adl as ArcAppServices;
        const scopes = services.references.ScopeProvider as AdlScopeProvider;
        const resolver = services.maa.NameResolver;
        scopes.contributions.set(
            'Application.component',
            (ctx) =>
                new LookupScope(
                    (name) => resolver.resolveComponent(ctx.container, name),
                    () => resolver.visible(ctx.container, 'component'),
                ),
        );
        scopes.contributions.set('AppGeneratorRef.generator', (ctx) => generatorScope(services.generators.Registry, ctx));

        const validator = services.validation.DocumentValidator as AdlDocumentValidator;
        validator.linkCodes.set('Application.component', {
            code: AppCodes.UnknownComponent,
            message: (name) =>
                `Component type '${name}' cannot be resolved: name the architecture's top component by its qualified name (e.g. 'toast.ToastServiceRobot').`,
        });
        validator.linkCodes.set('AppGeneratorRef.generator', {
            code: AppCodes.UnknownGenerator,
            message: (name) =>
                `Generator '${name}' is not installed: no installed package declares it ('maa-gen generators' lists the installed generators).`,
        });

        services.validation.ValidationRegistry.register({
            Application: (app: AstNode, accept: ValidationAcceptor) => {
                for (const f of services.generators.Applications.analyze(app as Application).findings) report(f, accept);
            },
        });
    },
    registerLsp: registerArcAppLsp,
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
            : undefined,
    });
}

function modelLocation(node: AstNode): { uri: string; range: Range; display: string } | undefined {
    const cst = node.$cstNode;
    if (!cst) return undefined;
    const doc = AstUtils.getDocument(node);
    const file = doc.uri.path.substring(doc.uri.path.lastIndexOf('/') + 1);
    return { uri: doc.uri.toString(), range: cst.range, display: `${file}:${cst.range.start.line + 1}` };
}
