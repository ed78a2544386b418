/** The view of labels: text placed by the server's layout, behavior badges, shortened labels with their full text. */
import { SLabelView, svg, type RenderingContext, type SLabelImpl } from 'sprotty';
import { BADGE_TEXT, textWidth, type VNode } from './view-parts.js';

export function labelView(): new () => SLabelView {
    return class LabelView extends SLabelView {
        override render(label: Readonly<SLabelImpl>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(label, context)) return undefined;
            const type = (label as unknown as { maaType?: string }).maaType ?? label.type;
            const cls = `maa-${type.replace(/[^A-Za-z0-9_-]/g, '-')}`;
            const h = label.size.height > 0 ? label.size.height : 16;
            const w = label.size.width > 0 ? label.size.width : textWidth(label.text, 7) + 4;
            // the server lays out label boxes (top left); without client layout there is no
            // baseline alignment, so the text's baseline goes about three quarters down the box
            const aligned = !!label.alignment && (label.alignment.x !== 0 || label.alignment.y !== 0);
            const y = aligned ? 0 : Math.round(h * 0.75);
            if (type === 'label:badge') {
                const kind = label.text;
                return svg(
                    'g',
                    { class: { 'maa-badge': true, [`maa-badge-${kind}`]: true, 'maa-label': true, [cls]: true } },
                    svg('title', {}, `behavior: ${BADGE_TEXT[kind] ?? kind}`),
                    svg('rect', { x: 0, y: 1, width: w, height: h - 2, rx: (h - 2) / 2, ry: (h - 2) / 2 }),
                    svg('text', { x: w / 2, y: y - 1, 'text-anchor': 'middle' }, BADGE_TEXT[kind] ?? kind),
                );
            }
            // a shortened label (a long transition label) carries its whole text for a tooltip
            const fullText = (label as unknown as { fullText?: unknown }).fullText;
            const full = typeof fullText === 'string' && fullText !== label.text ? fullText : undefined;
            if (full === undefined) return svg('text', { class: { 'sprotty-label': true, 'maa-label': true, [cls]: true }, y }, label.text);
            return svg(
                'text',
                {
                    class: { 'sprotty-label': true, 'maa-label': true, 'maa-label-shortened': true, [cls]: true },
                    y,
                    'data-full-text': full,
                },
                svg('title', {}, full),
                label.text,
            );
        }
    };
}
