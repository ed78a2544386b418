/**
 * The Sprotty C&C and automaton diagram shared by the front ends (the browser IDE, the VS Code
 * extension's webview): `mountDiagram(container, host)` (contracts.ts).
 *
 * The model comes from the diagram server in the language server worker (langium-sprotty,
 * server-side ELK layout, docs/ide.md "Diagram protocol"); the client only renders it. Action
 * messages travel through the front end's {@link DiagramHost} channel (LSP notifications
 * `diagram/accept`) via `MaaDiagramProxy`, a `DiagramServerProxy` over that channel.
 *
 * The parts: the mounted diagram (mounted-diagram.ts) over the Sprotty container (container.ts:
 * proxy.ts, commands.ts, views.ts and its view files), the tool bar and the feature bar
 * (toolbar.ts, feature-bar.ts), the viewport (camera.ts), selection both ways (selection.ts),
 * what is remembered per target (target-memory.ts), the SVG export (svg-export.ts), and the live
 * layer of a simulation run (live-layer.ts), offered as contracts.ts `DiagramLiveLayer`.
 */
import 'reflect-metadata';
import 'sprotty/css/sprotty.css';
import './diagram.css';
// The diagram's SVG rules: one stylesheet with the SVG that maa-gen diagram writes.
import '@maa/language-server/diagram-svg.css';
import type { DiagramHost } from './contracts.js';
import { MountedDiagram, type MaaDiagramView } from './mounted-diagram.js';

export { parseTrace, findInnermostElement, normalizeUri, rangeContains } from './trace.js';
export { MaaDiagramProxy } from './proxy.js';
export { standaloneSvg, svgFileName } from './svg-export.js';
export { ClearHiddenCommand, RedrawCommand } from './commands.js';
export type { MaaDiagramView } from './mounted-diagram.js';
export { parseHighlight, type DiagramHighlight } from './highlight.js';
export type { DiagramHighlighter } from './contracts.js';
export type { DiagramHost, DiagramLiveLayer, DiagramTarget, DiagramView, Disposable, TextPosition, TextRange } from './contracts.js';

/** Mounts the diagram into `container`; the front end calls `show` with what to display. */
export function mountDiagram(container: HTMLElement, host: DiagramHost): MaaDiagramView {
    return new MountedDiagram(container, host);
}
