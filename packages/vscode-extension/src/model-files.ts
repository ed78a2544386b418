/**
 * The family's file languages as the manifest contributes them, and the files the language
 * server hears of. No Node built-ins: both entries (desktop and web) use it.
 */
/** A file language of the family as the manifest contributes it (generated from the language facts). */
export interface ContributedLanguage {
    readonly id: string;
    readonly extensions: readonly string[];
}

/** The files whose changes the server hears of: every model file of the family and the model roots' maa.json. */
export function watchedFiles(languages: readonly ContributedLanguage[]): string {
    const names = ['maa.json', ...languages.flatMap((l) => l.extensions.map((e) => `*${e}`))];
    return `**/{${names.join(',')}}`;
}
