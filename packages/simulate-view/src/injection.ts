/**
 * Input injection: a text field and a Send button on the inspector row of a root port (fed from
 * outside the application); the text becomes a message of the topic's type (an enum literal its
 * ordinal) and is published over rosbridge.
 */
import type { RosConnection } from './ros/index.js';
import { el, errorText } from './dom.js';
import type { EnumLiterals } from './enums.js';
import { formatRosValue, parseInjectedValue } from './format.js';

export interface InjectionTarget {
    topic: string;
    /** The listed type (asked again from rosapi before sending). */
    type: string;
    /** What the notification calls it (the port path). */
    label: string;
}

/** The inject cell's field and button; `send` gets the text. */
export function injectControls(topic: string, type: string, send: (text: string) => void): HTMLElement[] {
    const input = el('input', {
        type: 'text',
        placeholder: type.startsWith('std_msgs/') ? 'value' : 'JSON message',
        class: 'maa-inject-input',
        'data-testid': 'inject-input',
        'data-topic': topic,
    });
    const button = el('button', { type: 'button', class: 'maa-sim-button', 'data-testid': 'inject-send', 'data-topic': topic }, 'Send');
    button.addEventListener('click', () => send(input.value));
    input.addEventListener('keydown', (e) => {
        if (e.key === 'Enter') send(input.value);
    });
    return [input, button];
}

/** Publishes `text` on the target's topic; the result is reported through `notify`. */
export async function inject(
    conn: RosConnection,
    target: InjectionTarget,
    text: string,
    enums: EnumLiterals,
    notify: (severity: 'info' | 'error', message: string) => void,
): Promise<void> {
    try {
        let type = target.type;
        try {
            type = (await conn.topicType(target.topic)) || type;
        } catch {
            /* keep the listed type */
        }
        if (!type) throw new Error(`the type of ${target.topic} is unknown`);
        const literals = enums.literals(type);
        const ordinal = literals ? literals.indexOf(text.trim()) : -1;
        const msg = ordinal >= 0 ? { value: ordinal } : parseInjectedValue(type, text);
        conn.publish(target.topic, type, msg);
        notify('info', `Sent ${formatRosValue(msg, 60)} to ${target.label}`);
    } catch (e) {
        notify('error', `Inject on ${target.topic}: ${errorText(e)}`);
    }
}
