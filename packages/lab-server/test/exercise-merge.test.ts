// The three-way merge of a starter update into a student's file (node-diff3).
import { describe, expect, it } from 'vitest';
import { mergeStarter } from '../src/exercises/merge.js';

const labels = { theirs: 'your A.arc', base: 'starter version 1 (what you started from)', next: 'starter version 2 (the update)' };
const base = 'component A {\n  port in int x;\n\n  // TODO\n}\n';

describe('mergeStarter', () => {
    it('merges edits of lines apart cleanly', () => {
        const theirs = 'component A {\n  port in int x;\n\n  int y = 1;\n}\n';
        const next = 'component A {\n  port in int x, out int z;\n\n  // TODO\n}\n';
        expect(mergeStarter(base, theirs, next, labels)).toEqual({
            clean: true,
            content: 'component A {\n  port in int x, out int z;\n\n  int y = 1;\n}\n',
        });
    });

    it('takes the same change on both sides without a conflict', () => {
        const both = 'component A {\n  port in int x;\n\n  // done\n}\n';
        expect(mergeStarter(base, both, both, labels)).toEqual({ clean: true, content: both });
    });

    it('marks edits of the same lines as a conflict, with the three versions labeled', () => {
        const theirs = 'component A {\n  port in int x;\n\n  int mine = 1;\n}\n';
        const next = 'component A {\n  port in int x;\n\n  // TODO: write the automaton here\n}\n';
        const merged = mergeStarter(base, theirs, next, labels);
        expect(merged.clean).toBe(false);
        if (merged.clean) return;
        expect(merged.marked).toBe(
            [
                'component A {',
                '  port in int x;',
                '',
                '<<<<<<< your A.arc',
                '  int mine = 1;',
                '||||||| starter version 1 (what you started from)',
                '  // TODO',
                '=======',
                '  // TODO: write the automaton here',
                '>>>>>>> starter version 2 (the update)',
                '}',
                '',
            ].join('\n'),
        );
    });
});

describe('mergeStarter: adjacent lines', () => {
    it('edits of adjacent lines conflict (as in git): the student decides', () => {
        const theirs = 'component A {\n  port in int x;\n\n  // TODO\n  int y = 1;\n}\n';
        const next = 'component A {\n  port in int x;\n\n  // TODO: more\n}\n';
        expect(mergeStarter(base, theirs, next, labels).clean).toBe(false);
    });
});
