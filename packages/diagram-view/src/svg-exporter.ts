/**
 * Sprotty's SVG export without CSS custom properties. The exporter copies onto every element each
 * computed style that differs from a bare copy; inside a VS Code webview every element inherits
 * the workbench's ~700 `--vscode-*` variables, which made a diagram of 150 elements a 6 MB file
 * (and too large to save in the browser IDE). The variables' effect is already in the computed
 * values of the real properties (`fill`, `stroke`, `font-*`), so the copy leaves them out.
 */
import { injectable } from 'inversify';
import { SvgExporter } from 'sprotty';

/** Whether a computed style's property is a CSS custom property (`--name`). */
export function isCustomProperty(name: string): boolean {
    return name.startsWith('--');
}

@injectable()
export class StandaloneSvgExporter extends SvgExporter {
    protected override copyStyles(source: Element, target: Element, skippedProperties: string[]): void {
        const sourceStyle = getComputedStyle(source);
        const targetStyle = getComputedStyle(target);
        const differing: string[] = [];
        for (let i = 0; i < sourceStyle.length; i++) {
            const name = sourceStyle.item(i);
            if (isCustomProperty(name) || skippedProperties.includes(name)) continue;
            const value = sourceStyle.getPropertyValue(name);
            if (targetStyle.getPropertyValue(name) !== value) differing.push(`${name}:${value};`);
        }
        if (differing.length > 0) target.setAttribute('style', differing.join(''));
        source.childNodes.forEach((child, i) => {
            const copy = target.childNodes[i];
            if (child instanceof Element && copy instanceof Element) this.copyStyles(child, copy, []);
        });
    }
}
