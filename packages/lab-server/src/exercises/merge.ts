// The three-way merge of a starter update into a student's file (node-diff3): base = the starter
// the student got, theirs = the student's file, next = the new starter.
import { mergeDiff3 } from 'node-diff3';

export type MergeOutcome =
    /** the merged text (the student's edits and the starter's changes touch different lines) */
    | { clean: true; content: string }
    /** the student's file with conflict markers where both changed the same lines */
    | { clean: false; marked: string };

export interface MergeLabels {
    /** e.g. `your toast/Controller.arc` */
    theirs: string;
    /** e.g. `starter version 1 (what you started from)` */
    base: string;
    /** e.g. `starter version 2 (the update)` */
    next: string;
}

/**
 * Merges line by line. Where both sides made the same change there is no conflict. A conflict is
 * marked as git does with `merge.conflictStyle diff3`: `<<<<<<<` the student's lines, `|||||||`
 * the base's, `=======` the new starter's, `>>>>>>>`.
 */
export function mergeStarter(base: string, theirs: string, next: string, labels: MergeLabels): MergeOutcome {
    const lines = (text: string) => text.split('\n');
    const merged = mergeDiff3(lines(theirs), lines(base), lines(next), {
        label: { a: labels.theirs, o: labels.base, b: labels.next },
    });
    const text = merged.result.join('\n');
    return merged.conflict ? { clean: false, marked: text } : { clean: true, content: text };
}
