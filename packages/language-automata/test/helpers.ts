import type { LangiumDocument, URI } from 'langium';
import type { HostLanguageServices } from '@maa/language-adl';
import { ModelTestBench, type Finding } from '@maa/language-adl/testing';
import { createAutomataServices } from '../src/index.js';

export { dump, hits, type Finding } from '@maa/language-adl/testing';

const bench = new ModelTestBench(() => createAutomataServices(), 'automata');

/** One set of services for a test file (building the parser is the expensive part). */
export function services(): HostLanguageServices {
    return bench.host;
}

/** Builds a model root given as files (path relative to the root -> text) and returns its documents. */
export function build(files: Readonly<Record<string, string>>): Promise<{ root: URI; docs: LangiumDocument[] }> {
    return bench.build(files);
}

/** Validates a model root and returns every diagnostic with the text it covers. */
export function validate(files: Readonly<Record<string, string>>): Promise<Finding[]> {
    return bench.validate(files);
}

/** A component `Comp` in `Comp.arc` with the given body. */
export function comp(body: string, header = ''): Record<string, string> {
    return { 'Comp.arc': `component Comp${header} {\n${body}\n}\n` };
}
