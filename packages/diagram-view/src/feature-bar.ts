/**
 * The feature bar above the C&C diagram of a variable component (configuration.ts): "All
 * variation points" and a checkbox per feature; hidden for every other diagram.
 */
import {
    chooseFeature,
    configurationStatus,
    featureChecked,
    showAll,
    type FeatureSelection,
    type GraphFeatureInfo,
} from './configuration.js';

function checkbox(text: string, testid: string, checked: boolean, title: string, onChange: (checked: boolean) => void): HTMLLabelElement {
    const label = document.createElement('label');
    label.className = 'maa-diagram-feature';
    label.title = title;
    const input = document.createElement('input');
    input.type = 'checkbox';
    input.checked = checked;
    input.dataset['testid'] = testid;
    input.addEventListener('change', () => onChange(input.checked));
    label.append(input, text);
    return label;
}

export class FeatureBar {
    readonly element = document.createElement('div');

    /** `select` gets the selection the user chose. */
    constructor(private readonly select: (selection: FeatureSelection) => void) {
        this.element.className = 'maa-diagram-features';
        this.element.dataset['testid'] = 'diagram-features';
        this.element.hidden = true;
    }

    /** Shows the features of `info` (none: hidden) with the current selection. */
    update(info: GraphFeatureInfo, selection: FeatureSelection | undefined): void {
        this.element.hidden = info.features.length === 0;
        if (this.element.hidden || !selection) {
            this.element.replaceChildren();
            return;
        }
        const items: HTMLElement[] = [
            checkbox(
                'All variation points',
                'diagram-features-all',
                selection.all,
                'Show every variation point (varif) with its condition',
                (all) => this.select(showAll(selection, all)),
            ),
        ];
        for (const f of info.features) {
            const box = checkbox(
                f,
                `diagram-feature-${f}`,
                featureChecked(info, selection, f),
                `Feature ${f}: checked shows a configuration with it, unchecked one without`,
                (value) => this.select(chooseFeature(selection, f, value)),
            );
            if (selection.all) box.classList.add('maa-diagram-feature-inactive');
            items.push(box);
        }
        const status = document.createElement('span');
        status.className = 'maa-diagram-features-status';
        status.textContent = configurationStatus(info, selection);
        items.push(status);
        this.element.replaceChildren(...items);
    }
}
