import { PYTHON_KEYWORDS as ADL_PYTHON_KEYWORDS, PYTHON_SOFT_KEYWORDS } from '@maa/language-adl';
/**
 * Naming conventions and escaping for generated code; the shared Nunjucks environment offers
 * them as filters (`{{ c.name | snake_case }}`), generator code can call them directly.
 */

/** Splits a name into words: `ToastServiceRobot` -> Toast, Service, Robot; `HTTPServer2go` -> HTTP, Server2go. */
export function words(name: string): string[] {
    return name
        .replace(/([a-z0-9])([A-Z])/g, '$1 $2')
        .replace(/([A-Z]+)([A-Z][a-z])/g, '$1 $2')
        .split(/[^A-Za-z0-9]+/)
        .filter((w) => w.length > 0);
}

/** `ToastServiceRobot` -> `toast_service_robot` */
export function snakeCase(name: string): string {
    return words(name)
        .map((w) => w.toLowerCase())
        .join('_');
}

/** `toast_service robot` -> `ToastServiceRobot` */
export function pascalCase(name: string): string {
    return words(name)
        .map((w) => w.charAt(0).toUpperCase() + w.slice(1))
        .join('');
}

/** `ToastServiceRobot` -> `toastServiceRobot` */
export function camelCase(name: string): string {
    const p = pascalCase(name);
    return p.charAt(0).toLowerCase() + p.slice(1);
}

/** `toastServiceRobot` -> `TOAST_SERVICE_ROBOT` */
export function constantCase(name: string): string {
    return words(name)
        .map((w) => w.toUpperCase())
        .join('_');
}

/** `ToastServiceRobot` -> `toast-service-robot` */
export function kebabCase(name: string): string {
    return words(name)
        .map((w) => w.toLowerCase())
        .join('-');
}

/** Indents every non-empty line by `width` spaces (or the given string), the first line included. */
export function indentLines(text: string, width: number | string = 4): string {
    const pad = typeof width === 'number' ? ' '.repeat(width) : width;
    return text
        .split('\n')
        .map((l) => (l.length > 0 ? pad + l : l))
        .join('\n');
}

/** What a generated Python identifier must not be: a keyword, soft ones included. */
const PYTHON_KEYWORDS = new Set([...ADL_PYTHON_KEYWORDS, ...PYTHON_SOFT_KEYWORDS]);

/** A Python identifier for a name: keywords get a trailing underscore. */
export function pythonIdentifier(name: string): string {
    const id = name.replace(/[^A-Za-z0-9_]/g, '_').replace(/^(\d)/, '_$1');
    return PYTHON_KEYWORDS.has(id) ? `${id}_` : id;
}

/** A Python string literal (double quotes, escapes as Python reads them). */
export function pythonString(value: unknown): string {
    return JSON.stringify(String(value)).replace(
        /[\u007f-\u009f\u2028\u2029]/g,
        (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, '0')}`,
    );
}

/** Escapes text for XML content and attribute values (package.xml, launch files). */
export function xmlEscape(value: unknown): string {
    return String(value).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;').replace(/'/g, '&apos;');
}
