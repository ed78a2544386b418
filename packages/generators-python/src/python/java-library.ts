import { BUILTIN_DOCUMENTS } from '@maa/language-adl';

/**
 * What the Python generators need to know about the JDK library the checker resolves
 * (`@maa/language-adl`'s built-in class diagrams): the qualified names of its types and the
 * names of its instance methods. Calls of these go to the runtime's `jcall`/`jstatic`/`jfield`
 * (rte/maa_behavior/jlib.py); calls of other methods are methods of class-diagram types.
 */
export interface JavaLibrary {
    /** `java.util.Date`, ... */
    readonly types: ReadonlySet<string>;
    /** Simple name -> qualified name (`Date` -> `java.util.Date`). */
    readonly bySimpleName: ReadonlyMap<string, string>;
    /** Names of non-static methods (`containsKey`, `intValue`, ...). */
    readonly instanceMethods: ReadonlySet<string>;
}

function load(): JavaLibrary {
    const types = new Set<string>();
    const bySimpleName = new Map<string, string>();
    const instanceMethods = new Set<string>();
    for (const { text } of BUILTIN_DOCUMENTS) {
        const pkg = /^\s*package\s+([\w.]+)\s*;/m.exec(text)?.[1] ?? '';
        for (const m of text.matchAll(/\b(?:class|interface|enum)\s+(\w+)/g)) {
            const q = `${pkg}.${m[1]}`;
            types.add(q);
            bySimpleName.set(m[1]!, q);
        }
        // Member declarations are separated by ';' and '{'; a method has a parameter list.
        for (const decl of text.split(/[;{}]/)) {
            const method = /(\w+)\s*\([^()]*\)\s*$/.exec(decl.trim());
            if (method && !/\bstatic\b/.test(decl)) instanceMethods.add(method[1]!);
        }
    }
    return { types, bySimpleName, instanceMethods };
}

export const JAVA_LIBRARY: JavaLibrary = load();
