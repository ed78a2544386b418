// One-time invitation links: the link holds a random token after `#` (a fragment never reaches
// a server, a log or a Referer); the database keeps its hash and expiry. The invitation page
// posts the token with the new password once; a used or expired link is refused.
import type { LabStore, User } from '../storage/index.js';
import { newSecret, secretHash } from './tokens.js';

export const DEFAULT_INVITATION_DAYS = 14;
const DAY_MS = 24 * 60 * 60 * 1000;

/** A fresh invitation token with what the store keeps of it. */
export function newInvitation(days = DEFAULT_INVITATION_DAYS): { token: string; id: string; expiresAt: Date } {
    const token = newSecret();
    return { token, id: secretHash(token), expiresAt: new Date(Date.now() + days * DAY_MS) };
}

/** The link a user opens to set their password. */
export function invitationLink(publicUrl: string, token: string): string {
    return `${publicUrl.replace(/\/+$/, '')}/invite#${token}`;
}

/** Creates an invitation for an existing user; returns its link. */
export async function inviteUser(store: LabStore, user: User, publicUrl: string, days = DEFAULT_INVITATION_DAYS): Promise<string> {
    const invitation = newInvitation(days);
    await store.createInvitation({ id: invitation.id, userId: user.id, expiresAt: invitation.expiresAt });
    return invitationLink(publicUrl, invitation.token);
}
