import type { URI, ValidationChecks, ValidationRegistry } from 'langium';
import type { CDModel, ClassDiagramAstType } from '../generated/ast.js';
import { CdCodes } from '../codes.js';

/** Where a class-diagram file sits: whether it is part of the built-in library and which package its folder stands for. */
export interface CdFileLocation {
    isBuiltin(uri: URI): boolean;
    /** The package a file's folder stands for, relative to its model root ('' at the root). */
    expectedPackage(uri: URI): string;
}

/**
 * Registers the checks of class diagrams: the file name and package agree with the location
 * (not for built-in files), and type names and enum constants are unique. The checks are typed
 * against this package's AST; they apply to the class diagrams of any family that composes the
 * grammar, since a composed AST keeps the `$type`s and properties.
 */
export function registerCdChecks(registry: ValidationRegistry, location: CdFileLocation): void {
    const checks: ValidationChecks<ClassDiagramAstType> = {
        CDModel: (m: CDModel, accept) => {
            const doc = m.$document;
            if (!doc || !m.diagram || location.isBuiltin(doc.uri)) return;
            const file = doc.uri.path.substring(doc.uri.path.lastIndexOf('/') + 1).replace(/\.cd$/, '');
            if (m.diagram.name !== file) {
                accept(
                    'error',
                    `Class diagram '${m.diagram.name}' must be declared in a file named '${m.diagram.name}.cd', not '${file}.cd'.`,
                    {
                        node: m.diagram,
                        property: 'name',
                        code: CdCodes.FileNameMismatch,
                    },
                );
            }
            const expected = location.expectedPackage(doc.uri);
            if ((m.package ?? '') !== expected) {
                const msg = `The package of '${file}.cd' must be '${expected || '(none)'}' to match its folder, not '${m.package ?? '(none)'}'.`;
                if (m.package) accept('error', msg, { node: m, property: 'package', code: CdCodes.PackageMismatch });
                else accept('error', msg, { node: m.diagram, property: 'name', code: CdCodes.PackageMismatch });
            }
            const seen = new Map<string, number>();
            for (const e of m.diagram.elements) {
                if (e.$type === 'CDAssociation' || !e.name) continue;
                seen.set(e.name, (seen.get(e.name) ?? 0) + 1);
                if (seen.get(e.name) === 2) {
                    accept('error', `Class diagram '${m.diagram.name}' declares '${e.name}' more than once.`, {
                        node: e,
                        property: 'name',
                        code: CdCodes.DuplicateName,
                    });
                }
                if (e.$type === 'CDEnum') {
                    const names = new Set<string>();
                    for (const c of e.constants) {
                        if (names.has(c.name)) {
                            accept('error', `Enum '${e.name}' declares constant '${c.name}' more than once.`, {
                                node: c,
                                property: 'name',
                                code: CdCodes.DuplicateName,
                            });
                        }
                        names.add(c.name);
                    }
                }
            }
        },
    };
    registry.register(checks);
}
