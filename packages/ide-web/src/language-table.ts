/**
 * Which Monaco language a workspace file is in: the family's file languages come from the
 * language facts the grammar composer writes (`@maa/language-server/language-facts`), so a new
 * language of the family is recognised without a change here; plain files (Python, JSON, stream
 * tests, ...) are listed below. No Monaco import, so tests and the worker can use it.
 */
import { LANGUAGE_FACTS, type LanguageFact } from '@maa/language-server/language-facts';

export interface FamilyLanguage {
    id: string;
    extensions: string[];
    aliases: string[];
}

/** The family's languages with files of their own (behavior languages live inside `.arc` files). */
export const FAMILY_LANGUAGES: readonly FamilyLanguage[] = LANGUAGE_FACTS.languages
    .filter((l) => l.kind === 'file')
    .map((l) => ({ id: l.id, extensions: [...l.fileExtensions], aliases: [...l.aliases] }));

/** Every fact by language id (file and behavior languages). */
export const LANGUAGE_FACT_BY_ID: ReadonlyMap<string, LanguageFact> = new Map(LANGUAGE_FACTS.languages.map((l) => [l.id, l]));

/** Languages of plain files the workspace may hold (read-only highlighting). */
const OTHER_LANGUAGES: Record<string, string> = {
    '.py': 'python',
    '.json': 'json',
    '.md': 'markdown',
    '.stream': 'maa-stream',
    '.launch': 'python',
    '.xml': 'xml',
    '.txt': 'plaintext',
    '.cmake': 'plaintext',
    '.cfg': 'plaintext',
    '.toml': 'plaintext',
};

export const MODEL_LANGUAGE_IDS: readonly string[] = FAMILY_LANGUAGES.map((l) => l.id);

/** The Monaco language id of a workspace path. */
export function languageOf(path: string): string {
    const dot = path.lastIndexOf('.');
    const ext = dot >= 0 ? path.slice(dot) : '';
    const family = FAMILY_LANGUAGES.find((l) => l.extensions.includes(ext));
    if (family) return family.id;
    if (path.endsWith('CMakeLists.txt')) return 'plaintext';
    return OTHER_LANGUAGES[ext] ?? 'plaintext';
}

export function isModelFile(path: string): boolean {
    return MODEL_LANGUAGE_IDS.includes(languageOf(path));
}

/** Words the lexical highlighting shows as types rather than keywords (MCTypes' primitives and `String`). */
export const TYPES: readonly string[] = ['boolean', 'byte', 'char', 'double', 'float', 'int', 'long', 'short', 'void', 'String'];
/** Keywords shown as constants (RobotArm's `move top;`) and as units (`120deg`), where a language has them. */
const CONSTANTS: readonly string[] = ['bottom', 'top'];
const UNITS: readonly string[] = ['cm', 'deg', 'm', 'mm', 'rad'];

export interface HighlightWords {
    /** Keywords, hard and soft (soft ones are refined by the server's semantic tokens). */
    keywords: string[];
    constants: string[];
    units: string[];
}

/** The highlighting classes of one language's keywords (from its facts). */
export function highlightWords(fact: LanguageFact): HighlightWords {
    const words = [...fact.keywords, ...fact.softKeywords];
    const constants = CONSTANTS.filter((w) => words.includes(w));
    const units = UNITS.filter((w) => words.includes(w));
    const keywords = words.filter((w) => !constants.includes(w) && !units.includes(w) && !TYPES.includes(w)).sort();
    return { keywords, constants, units };
}
