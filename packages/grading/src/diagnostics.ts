/** The diagnostics criterion: all points when the model has no error diagnostic, none otherwise; each error named with its file and line. */
import path from 'node:path';
import type { CheckDiagnostic } from '@maa/language-adl';
import type { CriterionGrade, DiagnosticsCriterion, Feedback } from '@maa/protocol/grading';
import { criterionGrade, plural } from './feedback.js';

/** At most this many errors are listed one by one. */
const SHOWN = 20;

export function gradeDiagnostics(criterion: DiagnosticsCriterion, root: string, diagnostics: readonly CheckDiagnostic[]): CriterionGrade {
    const errors = diagnostics.filter((d) => d.severity === 'error');
    if (errors.length === 0) return criterionGrade(criterion, 1, [{ severity: 'info', text: 'The model has no errors.' }]);
    const feedback: Feedback[] = [
        { severity: 'error', text: `The model has ${plural(errors.length, 'error')}; fix them for these points.` },
    ];
    for (const d of errors.slice(0, SHOWN)) {
        const file = path.relative(root, d.file).split(path.sep).join('/');
        feedback.push({
            severity: 'error',
            text: `${file}:${d.line}: ${d.message} (${d.code})`,
            element: { qualifiedName: '', file, line: d.line },
        });
    }
    if (errors.length > SHOWN) feedback.push({ severity: 'error', text: `… and ${errors.length - SHOWN} more errors.` });
    return criterionGrade(criterion, 0, feedback);
}
