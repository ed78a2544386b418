/** The diagram as a standalone SVG document, and its download. */
import type { DiagramTarget } from './contracts.js';

/** Sprotty's exported SVG as a document of its own: the SVG namespace and an XML declaration. */
export function standaloneSvg(svg: string): string {
    let text = svg;
    if (!/xmlns="http:\/\/www\.w3\.org\/2000\/svg"/.test(text)) text = text.replace(/<svg\b/, '<svg xmlns="http://www.w3.org/2000/svg"');
    if (!text.startsWith('<?xml')) text = `<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n${text}`;
    return text;
}

/** The download's file name: the component's simple name, `-automaton` for an automaton view. */
export function svgFileName(component: string | undefined, target: DiagramTarget | undefined): string {
    const comp = (component ?? 'diagram').split('.').pop();
    return `${comp}${target?.diagramType === 'maa-automaton' ? '-automaton' : ''}.svg`;
}

/** Offers `text` as a file download. */
export function downloadText(text: string, fileName: string, type = 'image/svg+xml'): void {
    const blob = new Blob([text], { type });
    const url = URL.createObjectURL(blob);
    const a = document.createElement('a');
    a.href = url;
    a.download = fileName;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10_000);
}
