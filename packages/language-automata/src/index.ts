import { EmptyFileSystem, type DefaultSharedCoreModuleContext } from 'langium';
import { createHostServices, type GeneratedModules, type HostLanguageServices } from '@maa/language-adl';
import { AutomataLanguage } from './automata-language.js';
import { ArcGeneratedModule, AutomataGeneratedSharedModule, CdGeneratedModule } from './generated/module.js';

export * from './automata-language.js';
export * from './automaton-checks.js';
export * from './automaton-model.js';
export * from './codes.js';
export * from './modes/mode-codes.js';
export * from './modes/mode-model.js';
export * from './modes/mode-checks.js';
export * as ast from './generated/ast.js';

/** The Langium modules of this package's grammar build: the host languages plus `automaton { }`. */
export const AutomataGeneratedModules: GeneratedModules = {
    shared: AutomataGeneratedSharedModule,
    arc: ArcGeneratedModule,
    cd: CdGeneratedModule,
};

/**
 * Services of the host languages with the automaton language installed, built from this
 * package's own grammar build (for tests and tools that need no other behavior language; a
 * language family composes its own build and registers `AutomataLanguage` there).
 */
export function createAutomataServices(context: DefaultSharedCoreModuleContext = EmptyFileSystem): HostLanguageServices {
    return createHostServices(context, AutomataGeneratedModules, [AutomataLanguage]);
}
export * from './diagnostic-catalog/automaton-diagnostics.js';
