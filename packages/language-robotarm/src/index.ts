import { EmptyFileSystem, type DefaultSharedCoreModuleContext } from 'langium';
import { createHostServices, type FamilyLanguage, type GeneratedModules, type HostLanguageServices } from '@maa/language-adl';
import { RobotArmFileLanguage, RobotArmLanguage } from './robotarm-language.js';
import { ArcGeneratedModule, CdGeneratedModule, RobotArmFileGeneratedModule, RobotArmGeneratedSharedModule } from './generated/module.js';

export * from './robotarm-language.js';
export * from './robotarm-checks.js';
export * from './robotarm-model.js';
export * from './codes.js';
export * from './diagnostic-catalog/robotarm-diagnostics.js';
export * as ast from './generated/ast.js';

/** The Langium modules of this package's grammar build: the host languages plus `robotarm { }`. */
export const RobotArmGeneratedModules: GeneratedModules = {
    shared: RobotArmGeneratedSharedModule,
    arc: ArcGeneratedModule,
    cd: CdGeneratedModule,
};

/** The standalone `.ra` language of this package's grammar build, with its generated module. */
export const RobotArmFileFamilyLanguage: FamilyLanguage = { ...RobotArmFileLanguage, generated: RobotArmFileGeneratedModule };

/**
 * Services of the host languages with RobotArm installed (the embedded block and `.ra` files),
 * built from this package's own grammar build (for tests and tools that need no other behavior
 * language; a language family composes its own build and registers `RobotArmLanguage` and
 * `RobotArmFileLanguage` there).
 */
export function createRobotArmServices(context: DefaultSharedCoreModuleContext = EmptyFileSystem): HostLanguageServices {
    return createHostServices(context, RobotArmGeneratedModules, [RobotArmLanguage], [RobotArmFileFamilyLanguage]);
}
