// Every migration of the lab's database, in order; Kysely's Migrator applies the ones a database
// has not seen (recorded in its kysely_migration table) inside a transaction and a lock.
import type { Migration, MigrationProvider } from 'kysely';
import * as initial from './0001-initial.js';
import * as invitations from './0002-invitations.js';
import * as exerciseStarters from './0003-exercise-starters.js';
import * as grading from './0004-grading.js';

const MIGRATIONS: Record<string, Migration> = {
    '0001-initial': initial,
    '0002-invitations': invitations,
    '0003-exercise-starters': exerciseStarters,
    '0004-grading': grading,
};

/** The migrations compiled into this package (no directory scan, so they work from dist/ and bundles alike). */
export const labMigrations: MigrationProvider = {
    getMigrations: async () => MIGRATIONS,
};
