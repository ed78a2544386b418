import type { DefaultSharedCoreModuleContext } from 'langium';
import type { DefaultSharedModuleContext } from 'langium/lsp';
import { createHostLspServices, createHostServices, type HostLanguageServices, type HostLspServices } from '@maa/language-adl';
import { BEHAVIOR_LANGUAGES, FAMILY_LANGUAGES } from './generated/behavior-languages.js';
import { ArcGeneratedModule, CdGeneratedModule, MaaGeneratedSharedModule } from './generated/module.js';

/**
 * The language family of this workbench: the host language (`.arc`), class diagrams (`.cd`)
 * and every behavior language listed in this package's `maa.family` (package.json), composed
 * into one grammar (one AST reflection) and one set of services with one shared scope.
 */
export function createMaaServices(context: DefaultSharedCoreModuleContext): HostLanguageServices {
    return createHostServices(context, { shared: MaaGeneratedSharedModule, arc: ArcGeneratedModule, cd: CdGeneratedModule }, BEHAVIOR_LANGUAGES, FAMILY_LANGUAGES);
}

/**
 * The same family with the language-server services (Langium's LSP defaults and the host's
 * AdlLspModule, plus every registered language's `registerLsp` contributions): for the node and
 * browser entry points and for tests of LSP features. Model roots come from the workspace folders.
 */
export function createMaaLspServices(context: DefaultSharedModuleContext): HostLspServices {
    return createHostLspServices(context, { shared: MaaGeneratedSharedModule, arc: ArcGeneratedModule, cd: CdGeneratedModule }, BEHAVIOR_LANGUAGES, FAMILY_LANGUAGES);
}

export function behaviorLanguages(): readonly string[] {
    return BEHAVIOR_LANGUAGES.map((b) => b.name);
}
