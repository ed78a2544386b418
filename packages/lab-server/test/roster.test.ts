// Roster CSV parsing (pure): good rosters, and bad rows reported with their line numbers.
import { describe, expect, it } from 'vitest';
import { parseRoster, RosterError } from '../src/auth/roster.js';

function problems(text: string): string[] {
    try {
        parseRoster(text);
    } catch (e) {
        if (e instanceof RosterError) return e.problems;
        throw e;
    }
    throw new Error('the roster was accepted');
}

describe('parseRoster', () => {
    it('reads name, e-mail, login and role, with the e-mail as the login when there is none', () => {
        const entries = parseRoster(
            '\uFEFFname,e-mail,login,role\n"Lovelace, Ada",ada@uni.example,ada,student\n\nGrace Hopper,grace@uni.example,,\nAlan Turing,,alan,Instructor\n',
        );
        expect(entries).toEqual([
            { line: 2, user: { login: 'ada', name: 'Lovelace, Ada', role: 'student', email: 'ada@uni.example' } },
            { line: 4, user: { login: 'grace@uni.example', name: 'Grace Hopper', role: 'student', email: 'grace@uni.example' } },
            { line: 5, user: { login: 'alan', name: 'Alan Turing', role: 'instructor', email: null } },
        ]);
    });

    it('takes the columns in any order and without a login column', () => {
        const entries = parseRoster('role,email,name\nstudent,b@x.org,B\n');
        expect(entries[0]?.user).toEqual({ login: 'b@x.org', name: 'B', role: 'student', email: 'b@x.org' });
    });

    it('reports every bad row with its line number', () => {
        const found = problems(
            [
                'name,email,login,role',
                'Ada,ada@x.org,ada,student',
                ',b@x.org,b,student',
                'C,not-an-address,c,student',
                'D,,d d,student',
                'E,e@x.org,e,teacher',
                'F,,,student',
                'Ada Again,other@x.org,ADA,student',
            ].join('\n'),
        );
        expect(found).toEqual([
            'line 3: the name is empty',
            'line 4: "not-an-address" is not an e-mail address',
            'line 5: the login "d d" may hold only letters, digits and . _ @ + - (at most 64)',
            'line 6: the role "teacher" is neither student nor instructor',
            'line 7: the row needs a login or an e-mail',
            'line 8: ada is already on line 2',
        ]);
    });

    it('refuses a bad header, a ragged row, an empty file and a roster without users', () => {
        expect(problems('name,mail,phone\n')).toEqual(['line 1: unknown column "phone" (the columns are name, email, login, role)']);
        expect(problems('email,login\na@x.org,a\n')).toEqual(['line 1: the header has no "name" column']);
        expect(problems('name,role\nA,student\n')).toEqual(['line 1: the header needs a "login" or an "email" column']);
        const ragged = problems('name,login\nA,a\nB,b,extra\n');
        expect(ragged).toHaveLength(1);
        expect(ragged[0]).toMatch(/^line 3: /);
        expect(problems('')).toEqual(['the file is empty (expected a header row: name,email,login,role)']);
        expect(problems('name,login\n')).toEqual(['the roster has a header but no users']);
        const quote = problems('name,login\n"A,a\n');
        expect(quote[0]).toMatch(/^line \d+: /);
    });
});
