/**
 * The rules of the IDE diagram stylesheet (packages/ide-web/src/diagram/diagram.css, from its
 * "SVG" section to its end) as the IDE has them: the SVG the CLI writes carries them, so it looks
 * like the IDE's Export SVG. A test in packages/cli/test/diagram.test.ts compares this copy with the
 * stylesheet, so a change there fails until it is made here too.
 */
export const IDE_DIAGRAM_CSS = `/* ---- SVG ---- */
.maa-graph { font-family: system-ui, -apple-system, 'Segoe UI', sans-serif; font-size: 12px; background: var(--maa-d-bg, #fbfcfd); }
.maa-graph text { user-select: none; }

.maa-component > .maa-component-body { fill: var(--maa-d-comp-fill, #eef4fb); stroke: var(--maa-d-comp-stroke, #4a6a8f); stroke-width: 1.2; }
.maa-component.maa-root > .maa-component-body { fill: var(--maa-d-root-fill, #f8fafc); stroke: var(--maa-d-root-stroke, #2c3e50); stroke-width: 1.6; }
.maa-component .maa-component .maa-component > .maa-component-body { fill: var(--maa-d-inner-fill, #e3edf8); }
/* Elements of a variation point (\`varif\`): dashed outline; the tooltip names the condition. */
.maa-component.maa-variable > .maa-component-body, .maa-port.maa-variable > .maa-port-shape { stroke-dasharray: 4 3; }
.maa-component.maa-kind-automaton > .maa-component-body { fill: var(--maa-d-aut-fill, #eef7ee); stroke: var(--maa-d-aut-stroke, #3f7a45); }
.maa-component.maa-kind-robotarm > .maa-component-body { fill: var(--maa-d-arm-fill, #fbf3e6); stroke: var(--maa-d-arm-stroke, #9a6a1f); }
.maa-component.maa-kind-handwritten > .maa-component-body { fill: var(--maa-d-hw-fill, #f5eefa); stroke: var(--maa-d-hw-stroke, #7a4f96); }
.maa-component.maa-kind-compute > .maa-component-body { fill: var(--maa-d-fn-fill, #eef6f8); stroke: var(--maa-d-fn-stroke, #3d7f8c); }
.maa-component.mouseover > .maa-component-body { stroke-width: 2; }
.maa-component.selected > .maa-component-body { stroke: var(--maa-d-select, #1a73e8); stroke-width: 2.4; }
.maa-component-name { font-weight: 600; fill: var(--maa-d-fg, #1f2d3d); }
.maa-component-type { fill: var(--maa-d-muted, #5a6b7d); font-size: 11px; font-style: italic; }
.maa-label { fill: var(--maa-d-fg, #1f2d3d); }
.maa-label-type, .maa-label-component-type { fill: var(--maa-d-muted, #5a6b7d); font-style: italic; }

.maa-badge rect { fill: var(--maa-d-badge-fill, #fff); stroke: #8a99a8; stroke-width: 1; }
.maa-badge text { font-size: 9px; fill: var(--maa-d-badge-fg, #3d4b59); }
.maa-badge-automaton rect { stroke: var(--maa-d-aut-stroke, #3f7a45); }
.maa-badge-robotarm rect { stroke: var(--maa-d-arm-stroke, #9a6a1f); }
.maa-badge-handwritten rect { stroke: var(--maa-d-hw-stroke, #7a4f96); }
.maa-badge-compute rect { stroke: var(--maa-d-fn-stroke, #3d7f8c); }
.maa-badge-composed rect { stroke: var(--maa-d-comp-stroke, #4a6a8f); }

.maa-expand-toggle { cursor: pointer; }
.maa-expand-toggle rect { fill: var(--maa-d-badge-fill, #fff); stroke: var(--maa-d-comp-stroke, #4a6a8f); }
.maa-expand-toggle path { stroke: var(--maa-d-fg, #2c3e50); stroke-width: 1.5; fill: none; }
.maa-expand-toggle:hover rect { stroke: var(--maa-d-select, #1a73e8); }

.maa-port .maa-port-shape { stroke: var(--maa-d-port, #2c3e50); stroke-width: 1.2; }
.maa-port.maa-port-in .maa-port-shape { fill: var(--maa-d-port, #2c3e50); }
.maa-port.maa-port-out .maa-port-shape { fill: var(--maa-d-port-hollow, #fff); }
.maa-port.maa-port-live .maa-port-shape { stroke: var(--maa-d-live, #0b8043); }
.maa-port.maa-port-in.maa-port-live .maa-port-shape { fill: var(--maa-d-live, #0b8043); }
.maa-port.selected .maa-port-shape { stroke: var(--maa-d-select, #1a73e8); stroke-width: 2.2; }
.maa-port.mouseover .maa-port-shape { stroke-width: 2; }

.sprotty-edge > path:first-child { fill: none; stroke: var(--maa-d-edge, #4a5a6a); stroke-width: 1.3; }
.maa-arrow { fill: var(--maa-d-edge, #4a5a6a); stroke: none; }
.maa-connector.maa-connector-live > path:first-child { stroke: var(--maa-d-live, #0b8043); }
.maa-connector.maa-connector-live .maa-arrow { fill: var(--maa-d-live, #0b8043); }
.sprotty-edge.selected > path:first-child { stroke: var(--maa-d-select, #1a73e8); stroke-width: 2.2; }
.sprotty-edge.selected .maa-arrow { fill: var(--maa-d-select, #1a73e8); }
.maa-value-label rect { fill: var(--maa-d-value-fill, #fffbe6); stroke: var(--maa-d-value-stroke, #c9a227); stroke-width: 0.8; }
.maa-value { font: 10.5px ui-monospace, 'SFMono-Regular', Menlo, monospace; fill: var(--maa-d-value-fg, #3b3000); }

.maa-state > .maa-state-body { fill: var(--maa-d-state-fill, #fff); stroke: var(--maa-d-aut-stroke, #3f7a45); stroke-width: 1.3; }
.maa-state .maa-state > .maa-state-body { fill: var(--maa-d-aut-fill, #f6fbf6); }
.maa-state.selected > .maa-state-body { stroke: var(--maa-d-select, #1a73e8); stroke-width: 2.4; }
.maa-state.maa-state-active > .maa-state-body { fill: var(--maa-d-active-fill, #ffe9a8); stroke: var(--maa-d-active-stroke, #c77700); stroke-width: 2.6; }
.maa-state.maa-state-active-parent > .maa-state-body { stroke: var(--maa-d-active-stroke, #c77700); stroke-dasharray: 4 2; }
.maa-state-name { font-weight: 600; fill: var(--maa-d-fg, #1f2d3d); }
.maa-initial-marker circle, .maa-initial-arrow { fill: var(--maa-d-fg, #1f2d3d); }
.maa-initial-marker path { stroke: var(--maa-d-fg, #1f2d3d); stroke-width: 1.3; }
.maa-transition-label { font-size: 10.5px; fill: var(--maa-d-fg, #33475b); }
.maa-current-state rect { fill: var(--maa-d-active-fill, #ffe9a8); stroke: var(--maa-d-active-stroke, #c77700); stroke-width: 0.8; }
.maa-current-state text { font-size: 10.5px; fill: var(--maa-d-active-fg, #5a3a00); }
/* mode automata during a run: the current mode of a decomposed component, its subcomponents and connectors lit, the other modes' dimmed */
.maa-current-mode rect { fill: var(--maa-d-active-fill, #ffe9a8); stroke: var(--maa-d-active-stroke, #c77700); stroke-width: 0.8; }
.maa-current-mode text { font-size: 10.5px; fill: var(--maa-d-active-fg, #5a3a00); }
.maa-component.maa-mode-active > .maa-component-body { stroke: var(--maa-d-active-stroke, #c77700); stroke-width: 2.2; }
.maa-connector.maa-mode-active > path:first-child { stroke: var(--maa-d-active-stroke, #c77700); }
.maa-connector.maa-mode-active .maa-arrow { fill: var(--maa-d-active-stroke, #c77700); }
.maa-mode-inactive { opacity: 0.35; }

.maa-error > .maa-component-body, .maa-error > .maa-state-body, .maa-port.maa-error .maa-port-shape { stroke: #f14c4c !important; stroke-width: 2.4; }
.maa-error > .maa-component-body { stroke-dasharray: 6 3; }
.maa-warning > .maa-component-body, .maa-warning > .maa-state-body, .maa-port.maa-warning .maa-port-shape { stroke: #e8a300 !important; stroke-width: 2.2; }
.sprotty-edge.maa-error > path:first-child { stroke: #f14c4c; }
.sprotty-edge.maa-warning > path:first-child { stroke: #e8a300; }

/* labels sent by the diagram server */
.maa-label-name, .maa-label-state { font-weight: 600; }
.maa-label-type { fill: var(--maa-d-muted, #5a6b7d); font-style: italic; }
.maa-label-port { font-size: 10.5px; fill: var(--maa-d-muted, #5a6b7d); }
.maa-label-transition { font-size: 10.5px; }
.maa-label-badge text { font-size: 9px; fill: var(--maa-d-badge-fg, #3d4b59); font-weight: normal; }
`;

/**
 * The stylesheet for a standalone SVG: every `var(--name, fallback)` resolved to its fallback.
 * The IDE's export gets that light palette too (it renders outside the dark `.maa-diagram`
 * container), and SVG rasterizers know no custom properties.
 */
export function standaloneStylesheet(css: string = IDE_DIAGRAM_CSS): string {
    return css.replace(/var\(--[\w-]+,\s*([^()]*?)\s*\)/g, '$1');
}
