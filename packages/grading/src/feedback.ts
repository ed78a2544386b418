/** Building a criterion's grade from its checks: the share of points and the feedback sentences. */
import type { CriterionGrade, Criterion, Feedback } from '@maa/protocol/grading';

/** A criterion's grade: `share` (0..1) of its weight, rounded to hundredths of a point. */
export function criterionGrade(criterion: Criterion, share: number, feedback: Feedback[]): CriterionGrade {
    const bounded = Math.min(1, Math.max(0, Number.isFinite(share) ? share : 0));
    return {
        id: criterion.id,
        title: criterion.title,
        kind: criterion.kind,
        score: Math.round(bounded * criterion.weight * 100) / 100,
        max: criterion.weight,
        feedback,
    };
}

/** `1 state`, `3 states`. */
export function plural(n: number, word: string, many = `${word}s`): string {
    return `${n} ${n === 1 ? word : many}`;
}

/** Simulated seconds as feedback shows them (`23.4 s`). */
export function seconds(t: number): string {
    return `${t.toFixed(1)} s`;
}
