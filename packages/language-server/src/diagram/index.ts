// The diagram server of the language family (langium-sprotty): the C&C and automaton views of
// docs/ide.md, laid out with ELK in the server. Browser-safe (used by the worker entry too).
export * from './model.js';
export * from './ids.js';
export * from './services.js';
export * from './server-manager.js';
export * from './diagram-server.js';
export * from './diagram-generator.js';
export * from './layout.js';
export { buildComponentDiagram, behaviorKind, allElements } from './cc-diagram.js';
export { buildAutomatonDiagram } from './automaton-diagram.js';
export { atomicSourcePath } from './source-ports.js';
export {
    standaloneDiagram,
    expandedToDepth,
    workspaceComponents,
    type StandaloneDiagramRequest,
    type WorkspaceComponent,
} from './standalone.js';
export { renderDiagramSvg, DEFAULT_ID_PREFIX, type SvgRenderOptions } from './svg/render.js';
export { IDE_DIAGRAM_CSS, standaloneStylesheet } from './svg/stylesheet.js';
