/**
 * The stable diagnostic codes of class diagrams (ARCHITECTURE.md section 5). Codes are released
 * API: never rename one. The host language's `Codes` (in @maa/language-adl) lists them too, as
 * `CdDuplicateName`, `CdFileNameMismatch` and `CdPackageMismatch`, taken from here.
 */
export const CdCodes = {
    DuplicateName: 'cd/duplicate-name',
    FileNameMismatch: 'cd/file-name-mismatch',
    PackageMismatch: 'cd/package-mismatch',
} as const;

export type CdCode = (typeof CdCodes)[keyof typeof CdCodes];
