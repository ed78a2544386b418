import { inject, type AstNodeLocator, type Module } from 'langium';
import {
    DefaultDiagnosticMarkerProvider,
    DefaultTraceProvider,
    addDiagramHandler,
    type DiagnosticMarkerProvider,
    type LangiumSprottyServices,
    type LangiumSprottySharedServices,
    type TraceProvider,
} from 'langium-sprotty';
import { ServerActionHandlerRegistry } from 'sprotty-protocol';
import type { AdlLspSharedServices, HostLspServices } from '@maa/language-adl';
import { MaaDiagramGenerator } from './diagram-generator.js';
import { MaaLayoutEngine } from './layout.js';
import { MaaDiagramServerManager } from './server-manager.js';

/**
 * The diagram services of the language family: one container beside the family's language
 * services (whose containers are already built and cannot take new members), holding what
 * langium-sprotty's classes read from its `LangiumSprottyServices`.
 */
export interface MaaDiagramServices {
    readonly shared: AdlLspSharedServices;
    readonly workspace: { readonly AstNodeLocator: AstNodeLocator };
    readonly diagram: {
        readonly DiagramGenerator: MaaDiagramGenerator;
        readonly ModelLayoutEngine: MaaLayoutEngine;
        readonly ServerActionHandlerRegistry: ServerActionHandlerRegistry;
        readonly TraceProvider: TraceProvider;
        readonly DiagnosticMarkerProvider: DiagnosticMarkerProvider;
        readonly DiagramServerManager: MaaDiagramServerManager;
    };
}

/** langium-sprotty's classes take the whole service type but use only the members above. */
function sprotty(s: MaaDiagramServices): LangiumSprottyServices {
    return s as unknown as LangiumSprottyServices;
}

export function createMaaDiagramServices(family: HostLspServices): MaaDiagramServices {
    const module: Module<MaaDiagramServices, MaaDiagramServices> = {
        shared: () => family.shared,
        workspace: { AstNodeLocator: () => family.Arc.workspace.AstNodeLocator },
        diagram: {
            DiagramGenerator: (s) => new MaaDiagramGenerator(sprotty(s), s.diagram.ModelLayoutEngine),
            ModelLayoutEngine: () => new MaaLayoutEngine(),
            ServerActionHandlerRegistry: () => new ServerActionHandlerRegistry(),
            TraceProvider: (s) => new DefaultTraceProvider(sprotty(s)),
            DiagnosticMarkerProvider: (s) => new DefaultDiagnosticMarkerProvider(sprotty(s)),
            DiagramServerManager: (s) => new MaaDiagramServerManager(s),
        },
    };
    return inject(module);
}

/**
 * Adds the diagram server to a language server: `diagram/accept` and `diagram/didClose`
 * notifications on the family's connection (call before startLanguageServer).
 */
export function addMaaDiagramServer(family: HostLspServices): MaaDiagramServices {
    const services = createMaaDiagramServices(family);
    const connection = family.shared.lsp.Connection;
    if (connection) {
        // addDiagramHandler reads only `diagram.DiagramServerManager`.
        addDiagramHandler(connection, {
            diagram: { DiagramServerManager: services.diagram.DiagramServerManager },
        } as unknown as LangiumSprottySharedServices);
    }
    // The manager listens to the document builder from its construction on.
    void services.diagram.DiagramServerManager;
    return services;
}
