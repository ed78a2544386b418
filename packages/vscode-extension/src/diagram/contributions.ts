/**
 * The diagram's part of the manifest (src/contributions.ts adds it): its commands, the editor
 * title button of component files and the Open Automaton View button of an automaton, and the
 * icon files of the family's languages and of the diagram panel.
 */
import { diagramIcon, type IconFile, type LanguageIcon, languageIcon } from './icons.js';

export const DIAGRAM_COMMANDS = [
    { command: 'maa.openDiagram', title: 'MontiArc: Open Diagram', category: 'MontiArc', icon: '$(type-hierarchy-sub)' },
    { command: 'maa.openAutomatonView', title: 'MontiArc: Open Automaton View', category: 'MontiArc', icon: '$(workflow)' },
    { command: 'maa.exportDiagramSvg', title: 'MontiArc: Export Diagram as SVG', category: 'MontiArc' },
] as const;

/**
 * Component files (the languages with a diagram), where the running entry registered the diagram
 * (`maa.diagramAvailable`, set by registerDiagram: an entry without it shows no dead buttons).
 */
const HAS_DIAGRAM = "resourceLangId == 'arc' && maa.diagramAvailable";

/** The editor title buttons: Open Diagram on component files, Open Automaton View while the cursor is in an automaton. */
export const DIAGRAM_TITLE_MENU = [
    { command: 'maa.openDiagram', when: HAS_DIAGRAM, group: 'navigation' },
    { command: 'maa.openAutomatonView', when: `${HAS_DIAGRAM} && maa.cursorInAutomaton`, group: 'navigation' },
] as const;

/** The commands in the command palette only where they apply. */
export const DIAGRAM_PALETTE = [
    { command: 'maa.openDiagram', when: "editorLangId == 'arc' && maa.diagramAvailable" },
    { command: 'maa.openAutomatonView', when: "editorLangId == 'arc' && maa.diagramAvailable && maa.cursorInAutomaton" },
    { command: 'maa.exportDiagramSvg', when: 'maa.diagramOpen' },
] as const;

/** The diagram's settings (`maa.diagram.*`), merged into the manifest's configuration (contributions.ts). */
export const DIAGRAM_SETTINGS = {
    'maa.diagram.openOnStart': {
        type: 'boolean',
        default: false,
        markdownDescription:
            'Opens the diagram beside the first component file (`.arc`) shown once the extension has started. The browser IDE sets it, so its start page shows the model and its diagram.',
    },
} as const;

/** Whether the diagram opens by itself at start (`maa.diagram.openOnStart`; anything but `true` is no). */
export function openOnStart(get: (key: string) => unknown): boolean {
    return get('maa.diagram.openOnStart') === true;
}

/** A language's manifest `icon` entry. */
export function languageIconOf(language: { id: string; fileExtensions: readonly string[] }): LanguageIcon {
    return languageIcon(language.id, language.fileExtensions[0] ?? language.id).icon;
}

/** Every icon file: each language's variants and the diagram panel's. */
export function iconFiles(languages: ReadonlyArray<{ id: string; fileExtensions: readonly string[] }>): IconFile[] {
    return [...languages.flatMap((l) => languageIcon(l.id, l.fileExtensions[0] ?? l.id).files), ...diagramIcon().files];
}
