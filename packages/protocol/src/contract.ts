/**
 * A wire contract: a TypeBox schema (a JSON Schema object) with a name, checked at run time by
 * TypeBox's `Value` (no code generation, so it also runs under a strict CSP in the browser).
 */
import type { Static, TSchema } from '@sinclair/typebox';
import { Value } from '@sinclair/typebox/value';

/** One reason a value breaks a contract: the JSON pointer of the bad field and what is wrong. */
export interface ContractIssue {
    /** RFC 6901 JSON pointer into the checked value (`""` is the value itself). */
    pointer: string;
    message: string;
}

/** A value that breaks a contract; its message names where it came from and the first issues. */
export class ContractError extends Error {
    constructor(
        readonly contract: string,
        readonly where: string,
        readonly issues: readonly ContractIssue[],
    ) {
        super(`${where}: not a valid ${contract}: ${formatIssues(issues)}`);
        this.name = 'ContractError';
    }
}

/** `/nodes/0/name: Expected string; /format: Expected 'maa-deployment/1'` (at most `max` issues). */
export function formatIssues(issues: readonly ContractIssue[], max = 3): string {
    const shown = issues.slice(0, max).map((i) => `${i.pointer || '/'}: ${i.message}`);
    if (issues.length > max) shown.push(`(${issues.length - max} more)`);
    return shown.join('; ');
}

/** TypeBox reports a union or a pattern failure once per sub-schema: one issue per pointer and message. */
export function dedupeIssues(issues: readonly ContractIssue[]): ContractIssue[] {
    const seen = new Set<string>();
    return issues.filter((i) => {
        const key = `${i.pointer}\u0000${i.message}`;
        if (seen.has(key)) return false;
        seen.add(key);
        return true;
    });
}

/**
 * The message of a schema's `errorMessage` keyword (`{key}` = the last segment of the pointer),
 * else the validator's own. Readers in other languages (maa_sim/deployment.py) do the same.
 */
function messageOf(schema: TSchema, pointer: string, fallback: string): string {
    const custom = (schema as { errorMessage?: unknown }).errorMessage;
    if (typeof custom !== 'string') return fallback;
    const key = pointer
        .slice(pointer.lastIndexOf('/') + 1)
        .replace(/~1/g, '/')
        .replace(/~0/g, '~');
    return custom.replace(/\{key\}/g, key);
}

export interface Contract<T extends TSchema> {
    /** What the contract is, for messages (`trace file`, `POST /api/generate request`). */
    readonly name: string;
    readonly schema: T;
    /** Whether the value keeps the contract. */
    check(value: unknown): value is Static<T>;
    /** Every issue of the value (empty when it keeps the contract). */
    issues(value: unknown): ContractIssue[];
    /** The value, typed, or a {@link ContractError} naming `where` (a file, a URL) and the bad fields. */
    parse(value: unknown, where?: string): Static<T>;
}

export function contract<T extends TSchema>(name: string, schema: T): Contract<T> {
    const issues = (value: unknown): ContractIssue[] => {
        const out: ContractIssue[] = [];
        for (const e of Value.Errors(schema, value)) out.push({ pointer: e.path, message: messageOf(e.schema, e.path, e.message) });
        return out;
    };
    return {
        name,
        schema,
        check: (value: unknown): value is Static<T> => Value.Check(schema, value),
        issues,
        parse(value: unknown, where = name): Static<T> {
            if (Value.Check(schema, value)) return value;
            throw new ContractError(name, where, issues(value));
        },
    };
}
