// The storage of accounts on both backends: invitations used once (also when two uses race),
// expired and unknown ones refused; importUsers all or nothing; users by e-mail; linking a
// single sign-on identity once.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type LabStore, openLabStore, StorageConflictError } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';

describe.each(BACKENDS)('accounts in the LabStore on %s', (backendName) => {
    let backend: Backend;
    let store: LabStore;
    const inAWeek = () => new Date(Date.now() + 7 * 24 * 3600_000);

    beforeAll(async () => {
        backend = await startBackend(backendName);
        store = await openLabStore(await backend.freshStorage());
    });
    afterAll(async () => {
        await store?.close();
        await backend?.dispose();
    });

    it('redeems an invitation once: the password hash is set, a second use is refused as used', async () => {
        const [user] = await store.importUsers([
            { user: { login: 'ada', name: 'Ada', role: 'student' }, invitation: { id: 'hash-ada', expiresAt: inAWeek() } },
        ]);
        expect(user?.passwordHash).toBeNull();
        const first = await store.redeemInvitation('hash-ada', '$argon2id$first');
        expect(first).toMatchObject({ ok: true, user: { login: 'ada', passwordHash: '$argon2id$first' } });
        expect(await store.redeemInvitation('hash-ada', '$argon2id$second')).toEqual({ ok: false, reason: 'used' });
        expect((await store.findUserByLogin('ada'))?.passwordHash).toBe('$argon2id$first');
        expect((await store.findInvitation('hash-ada'))?.usedAt).toBeInstanceOf(Date);
    });

    it('lets exactly one of two concurrent uses of an invitation win', async () => {
        const user = await store.createUser({ login: 'racer', name: 'Racer', role: 'student' });
        await store.createInvitation({ id: 'hash-race', userId: user.id, expiresAt: inAWeek() });
        const results = await Promise.all([store.redeemInvitation('hash-race', 'one'), store.redeemInvitation('hash-race', 'two')]);
        expect(results.filter((r) => r.ok)).toHaveLength(1);
        expect(results.filter((r) => !r.ok)).toEqual([{ ok: false, reason: 'used' }]);
    });

    it('refuses an expired and an unknown invitation without setting a password', async () => {
        const user = await store.createUser({ login: 'late', name: 'Late', role: 'student' });
        await store.createInvitation({ id: 'hash-late', userId: user.id, expiresAt: new Date(Date.now() - 1000) });
        expect(await store.redeemInvitation('hash-late', 'x')).toEqual({ ok: false, reason: 'expired' });
        expect(await store.redeemInvitation('no-such-hash', 'x')).toEqual({ ok: false, reason: 'unknown' });
        expect((await store.findUserByLogin('late'))?.passwordHash).toBeNull();
    });

    it('imports users all or nothing, enrolling them in the course', async () => {
        const course = await store.createCourse({ name: 'robotics', title: 'Robotics' });
        const users = await store.importUsers(
            [
                {
                    user: { login: 'bob', name: 'Bob', role: 'student', email: 'bob@uni.example' },
                    invitation: { id: 'hash-bob', expiresAt: inAWeek() },
                },
                { user: { login: 'cy', name: 'Cy', role: 'student' } },
            ],
            course.id,
        );
        expect(users.map((u) => u.login)).toEqual(['bob', 'cy']);
        expect((await store.listEnrolled(course.id)).map((u) => u.login)).toEqual(['bob', 'cy']);
        // The second row's e-mail is taken: the first row must not stay either.
        const failing = store.importUsers(
            [
                { user: { login: 'dan', name: 'Dan', role: 'student' }, invitation: { id: 'hash-dan', expiresAt: inAWeek() } },
                { user: { login: 'bobby', name: 'Bobby', role: 'student', email: 'bob@uni.example' } },
            ],
            course.id,
        );
        await expect(failing).rejects.toBeInstanceOf(StorageConflictError);
        expect(await store.findUserByLogin('dan')).toBeUndefined();
        expect(await store.findInvitation('hash-dan')).toBeUndefined();
        expect((await store.listEnrolled(course.id)).map((u) => u.login)).toEqual(['bob', 'cy']);
    });

    it('finds users by e-mail regardless of case, and links a single sign-on identity once', async () => {
        const bob = await store.findUserByEmail('BOB@Uni.Example');
        expect(bob?.login).toBe('bob');
        expect(await store.findUserByEmail('nobody@uni.example')).toBeUndefined();
        const linked = await store.linkOidc(bob?.id ?? 0, 'https://id.uni.example', 'sub-bob');
        expect(linked).toMatchObject({ oidcIssuer: 'https://id.uni.example', oidcSubject: 'sub-bob' });
        expect((await store.findUserByOidc('https://id.uni.example', 'sub-bob'))?.login).toBe('bob');
        await expect(store.linkOidc(bob?.id ?? 0, 'https://id.uni.example', 'sub-other')).rejects.toBeInstanceOf(StorageConflictError);
        const cy = await store.findUserByLogin('cy');
        await expect(store.linkOidc(cy?.id ?? 0, 'https://id.uni.example', 'sub-bob')).rejects.toBeInstanceOf(StorageConflictError);
    });
});
