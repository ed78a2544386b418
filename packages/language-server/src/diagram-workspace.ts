import { NodeFileSystem } from 'langium/node';
import { checkRoots, type CheckDiagnostic, type HostLspServices } from '@maa/language-adl';
import { createMaaDiagramServices, type MaaDiagramServices } from './diagram/services.js';
import { createMaaLspServices } from './family.js';

/**
 * A model root loaded from the file system for diagrams outside the IDE (`maa-gen diagram`):
 * the family's services with the diagram services beside them, every model file of the root
 * built and validated as `maa-gen check` does it (so the diagram marks the same errors), and
 * those diagnostics.
 */
export interface DiagramWorkspace {
    readonly family: HostLspServices;
    readonly diagrams: MaaDiagramServices;
    readonly diagnostics: readonly CheckDiagnostic[];
}

export async function loadDiagramWorkspace(root: string, onProgress?: (message: string) => void): Promise<DiagramWorkspace> {
    const family = createMaaLspServices(NodeFileSystem);
    const diagnostics = await checkRoots(family, [{ root }], onProgress ? { onProgress } : {});
    return { family, diagrams: createMaaDiagramServices(family), diagnostics };
}
