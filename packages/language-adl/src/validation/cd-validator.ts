import type { ValidationChecks } from 'langium';
import type { AdlAstType, CDModel } from '../generated/ast.js';
import type { AdlServices } from '../adl-module.js';
import { Codes } from './codes.js';

/** Checks of class diagrams: file name and package agree with the location; names are unique. */
export function registerCdChecks(services: AdlServices): void {
    const roots = services.shared.maa.ModelRoots;
    const checks: ValidationChecks<AdlAstType> = {
        CDModel: (m: CDModel, accept) => {
            const doc = m.$document;
            if (!doc || !m.diagram || roots.isBuiltin(doc.uri)) return;
            const file = doc.uri.path.substring(doc.uri.path.lastIndexOf('/') + 1).replace(/\.cd$/, '');
            if (m.diagram.name !== file) {
                accept('error', `Class diagram '${m.diagram.name}' must be declared in a file named '${m.diagram.name}.cd', not '${file}.cd'.`, { node: m.diagram, property: 'name', code: Codes.CdFileNameMismatch });
            }
            const expected = roots.expectedPackage(doc.uri);
            if ((m.package ?? '') !== expected) {
                const msg = `The package of '${file}.cd' must be '${expected || '(none)'}' to match its folder, not '${m.package ?? '(none)'}'.`;
                if (m.package) accept('error', msg, { node: m, property: 'package', code: Codes.CdPackageMismatch });
                else accept('error', msg, { node: m.diagram, property: 'name', code: Codes.CdPackageMismatch });
            }
            const seen = new Map<string, number>();
            for (const e of m.diagram.elements) {
                if (e.$type === 'CDAssociation' || !e.name) continue;
                seen.set(e.name, (seen.get(e.name) ?? 0) + 1);
                if (seen.get(e.name) === 2) accept('error', `Class diagram '${m.diagram.name}' declares '${e.name}' more than once.`, { node: e, property: 'name', code: Codes.CdDuplicateName });
                if (e.$type === 'CDEnum') {
                    const names = new Set<string>();
                    for (const c of e.constants) {
                        if (names.has(c.name)) accept('error', `Enum '${e.name}' declares constant '${c.name}' more than once.`, { node: c, property: 'name', code: Codes.CdDuplicateName });
                        names.add(c.name);
                    }
                }
            }
        }
    };
    services.validation.ValidationRegistry.register(checks);
}
