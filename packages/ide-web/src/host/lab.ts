/**
 * Lab mode (docs/lab.md "The IDE in the lab"): the lab server serves this page per student
 * workspace at `/ide/<course>/<exercise>/<owner>/`, with the session's CSRF token and the
 * workspace's prefix in meta tags (packages/lab-server/src/ide/page.ts). Every relative URL of the
 * page, the extension and the language server then reaches that workspace; what lab mode adds
 * here is the token on the page's writes and what the exercise says (read-only files, whether
 * the sender may write at all: an instructor looks at a student's workspace read-only).
 */
import { isReadOnly } from '@maa/protocol/exercise';

/** The meta tags' names (the lab writes them: packages/lab-server/src/ide/page.ts). */
const CSRF_META = 'maa-csrf-token';
const WORKSPACE_META = 'maa-lab-workspace';
const CSRF_HEADER = 'X-CSRF-Token';
const SAFE_METHODS = new Set(['GET', 'HEAD', 'OPTIONS']);

/** What the lab's `GET <prefix>` says of the workspace (the part the IDE uses). */
export interface ExerciseInfo {
    readonly course: string;
    readonly exercise: string;
    readonly owner: string;
    readonly writable: boolean;
    readonly title: string;
    /** the exercise's description, Markdown */
    readonly description: string;
    readonly app: string;
    readonly readOnly: readonly string[];
    readonly tests: readonly string[];
    readonly platforms: readonly string[];
    readonly latestTests: { passed: number; failed: number; at: string } | null;
}

export interface LabMode {
    readonly csrfToken: string;
    /** the workspace's prefix on the lab server (`/api/ws/<course>/<exercise>/<owner>`) */
    readonly workspace: string;
    readonly exercise: ExerciseInfo;
    /** whether the student may not change the file (read-only exercise files; every file for a viewer) */
    readOnly(path: string): boolean;
}

/** The lab's meta tags of the page, or undefined outside a lab (maa-ide's page has none). */
export function labMeta(doc: Pick<Document, 'querySelector'>): { csrfToken: string; workspace: string } | undefined {
    const content = (name: string) => doc.querySelector(`meta[name="${name}"]`)?.getAttribute('content') ?? undefined;
    const csrfToken = content(CSRF_META);
    const workspace = content(WORKSPACE_META);
    return csrfToken && workspace ? { csrfToken, workspace } : undefined;
}

/**
 * `fetchFn` with the CSRF token on every request to `origin` that is not a read: the lab wants it
 * on each of them, and no other site ever gets it.
 */
export function withCsrfToken(fetchFn: typeof fetch, token: string, origin: string, base: string): typeof fetch {
    return (input, init) => {
        const request = input instanceof Request ? input : undefined;
        const method = (init?.method ?? request?.method ?? 'GET').toUpperCase();
        const url = new URL(request?.url ?? String(input), base);
        if (SAFE_METHODS.has(method) || url.origin !== origin) return fetchFn(input, init);
        const headers = new Headers(init?.headers ?? request?.headers);
        headers.set(CSRF_HEADER, token);
        return fetchFn(input, { ...init, headers });
    };
}

/** The exercise's answer, checked for the fields the IDE relies on. */
export function parseExerciseInfo(value: unknown): ExerciseInfo {
    const v = value as Partial<ExerciseInfo> | null;
    const strings = (x: unknown): x is string[] => Array.isArray(x) && x.every((s) => typeof s === 'string');
    if (
        !v ||
        typeof v.exercise !== 'string' ||
        typeof v.owner !== 'string' ||
        typeof v.writable !== 'boolean' ||
        typeof v.title !== 'string' ||
        typeof v.description !== 'string' ||
        !strings(v.readOnly) ||
        !strings(v.tests) ||
        !strings(v.platforms)
    )
        throw new Error(
            "the lab's answer about the exercise lacks exercise, owner, writable, title, description, readOnly, tests or platforms",
        );
    return v as ExerciseInfo;
}

/**
 * Lab mode of this page, or undefined outside a lab. Installs the CSRF token on the page's
 * `fetch` (the extension runs on the page's thread and uses it too) before anything is sent.
 */
export async function startLabMode(win: Window = window): Promise<LabMode | undefined> {
    const meta = labMeta(win.document);
    if (!meta) return undefined;
    win.fetch = withCsrfToken(win.fetch.bind(win), meta.csrfToken, win.location.origin, win.document.baseURI);
    const response = await win.fetch('api/exercise');
    if (!response.ok) throw new Error(`reading the exercise: ${response.status} ${response.statusText}`);
    const exercise = parseExerciseInfo(await response.json());
    return {
        ...meta,
        exercise,
        readOnly: (path) => !exercise.writable || isReadOnly(exercise, path),
    };
}
