// Invitation links and the all-or-nothing user import (roster CSV, `maa-lab users add`).
import type { Kysely, Transaction } from 'kysely';
import { toUser } from './rows.js';
import type { Database } from './schema.js';
import type { ImportedUser, Invitation, NewUser, Redemption, User } from './types.js';

type Db = Kysely<Database> | Transaction<Database>;

export function toInvitation(r: { id: string; user_id: number; created_at: Date; expires_at: Date; used_at: Date | null }): Invitation {
    return { id: r.id, userId: r.user_id, createdAt: r.created_at, expiresAt: r.expires_at, usedAt: r.used_at };
}

export async function insertUser(db: Db, u: NewUser): Promise<User> {
    const row = await db
        .insertInto('users')
        .values({
            login: u.login,
            name: u.name,
            role: u.role,
            email: u.email ?? null,
            password_hash: u.passwordHash ?? null,
            oidc_issuer: u.oidcIssuer ?? null,
            oidc_subject: u.oidcSubject ?? null,
        })
        .returningAll()
        .executeTakeFirstOrThrow();
    return toUser(row);
}

export async function insertInvitation(db: Db, i: Omit<Invitation, 'createdAt' | 'usedAt'>): Promise<Invitation> {
    const row = await db
        .insertInto('invitations')
        .values({ id: i.id, user_id: i.userId, expires_at: i.expiresAt })
        .returningAll()
        .executeTakeFirstOrThrow();
    return toInvitation(row);
}

export function redeem(db: Kysely<Database>, id: string, passwordHash: string, now: Date): Promise<Redemption> {
    return db.transaction().execute(async (tx): Promise<Redemption> => {
        const row = await tx.selectFrom('invitations').selectAll().where('id', '=', id).forUpdate().executeTakeFirst();
        if (!row) return { ok: false, reason: 'unknown' };
        if (row.used_at !== null) return { ok: false, reason: 'used' };
        if (row.expires_at <= now) return { ok: false, reason: 'expired' };
        await tx.updateTable('invitations').set({ used_at: now }).where('id', '=', id).execute();
        const user = await tx
            .updateTable('users')
            .set({ password_hash: passwordHash })
            .where('id', '=', row.user_id)
            .returningAll()
            .executeTakeFirstOrThrow();
        return { ok: true, user: toUser(user) };
    });
}

export function importAll(db: Kysely<Database>, users: ImportedUser[], courseId?: number): Promise<User[]> {
    return db.transaction().execute(async (tx) => {
        const created: User[] = [];
        for (const { user, invitation } of users) {
            const row = await insertUser(tx, user);
            if (invitation) await insertInvitation(tx, { id: invitation.id, userId: row.id, expiresAt: invitation.expiresAt });
            if (courseId !== undefined) await tx.insertInto('enrollments').values({ course_id: courseId, user_id: row.id }).execute();
            created.push(row);
        }
        return created;
    });
}
