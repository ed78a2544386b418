import { NodeFileSystem } from 'langium/node';
import { checkRoots, type CheckDiagnostic, type CheckOptions, type RootSpec } from '@maa/language-adl';
import { createMaaServices } from './family.js';

/**
 * Checks model roots with the whole language family: the checking path of `maa-gen check`,
 * the conformance suite and the benchmark. Each call uses fresh services, so roots of one call
 * never see documents of another.
 */
export async function checkModelRoots(roots: readonly RootSpec[], options: CheckOptions = {}): Promise<CheckDiagnostic[]> {
    const services = createMaaServices(NodeFileSystem);
    return checkRoots(services, roots, options);
}
