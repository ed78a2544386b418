/**
 * A classroom lab exercise (docs/lab.md "Exercises"): `exercise.json` in the exercise's folder
 * (`examples/lab/<name>/`), read by the lab server when an instructor releases it, and the
 * released exercise the lab server stores and serves to the browser IDE. One definition for both
 * sides; `errorMessage` is the message a reader shows for a field that breaks the schema.
 */
import { Type, type Static } from '@sinclair/typebox';
import { EXERCISE_FORMAT } from '../formats.js';

export { EXERCISE_FILE_NAME, EXERCISE_FORMAT } from '../formats.js';

/**
 * A path inside the starter folder: relative, `/`-separated, no empty, `.` or `..` segments, no
 * backslash (the lab's workspace paths, which storage checks again).
 */
const RELATIVE_PATH = '^(?!/)(?!.*\\\\)(?!.*//)(?!(.*/)?\\.\\.?(/|$))[^\\u0000-\\u001f]{1,512}$';

/** The base folder: relative, `/`-separated, `..` segments allowed (it lies beside the exercise), no `.` or empty ones. */
const BASE_PATH = '^(?!/)(?!.*\\\\)(?!.*//)(?!(.*/)?\\.(/|$))[^\\u0000-\\u001f]{1,512}$';

const StarterPath = (what: string, suffix = '') =>
    Type.String({
        pattern: suffix ? `(?=${RELATIVE_PATH})^.*${suffix.replace(/\./g, '\\.')}$` : RELATIVE_PATH,
        errorMessage: `${what} must be a relative path with / (no .. or leading /)${suffix ? ` ending in ${suffix}` : ''}`,
    });

const PathList = (what: string, suffix = '') =>
    Type.Array(StarterPath(what, suffix), { uniqueItems: true, errorMessage: `${what} must be a list of distinct relative paths` });

/** A platform of the application (`timesync`, `rospython`): what `maa-gen generate --platform` takes. */
const Platform = Type.String({ pattern: '^[A-Za-z][A-Za-z0-9_-]*$', errorMessage: 'a platform is a name like timesync' });

/** The fields `exercise.json` and a released exercise share. */
const CommonFields = {
    format: Type.Literal(EXERCISE_FORMAT, { errorMessage: `format must be '${EXERCISE_FORMAT}'` }),
    /** Shown as the exercise's heading. */
    title: Type.String({ minLength: 1, maxLength: 200, errorMessage: 'title must be a non-empty string (at most 200 characters)' }),
    /** The application configuration (`.arcapp`) in the starter that `maa-gen test` and the simulator run. */
    app: StarterPath('app', '.arcapp'),
    /**
     * Starter files the student may not edit: a path, or a folder ending in `/` (everything below
     * it). They always take the newest starter on an update.
     */
    readOnly: Type.Array(StarterPath('readOnly entry'), {
        uniqueItems: true,
        errorMessage: 'readOnly must be a list of distinct relative paths (a folder ends in /)',
    }),
    /** The stream tests (`.stream` files of the starter) the student sees and runs. */
    tests: PathList('tests entry', '.stream'),
    /** The platforms the student may generate for and simulate on (declared in the app). */
    platforms: Type.Array(Platform, {
        minItems: 1,
        uniqueItems: true,
        errorMessage: 'platforms must be a non-empty list of distinct names',
    }),
};

/** `exercise.json`: what an instructor writes. */
export const ExerciseManifest = Type.Object(
    {
        ...CommonFields,
        /** The Markdown file (in the exercise folder) with the description students read. */
        description: StarterPath('description', '.md'),
        /** The folder (in the exercise folder) whose files every student starts with; default `starter`. */
        starter: Type.Optional(StarterPath('starter')),
        /**
         * A folder (relative to the exercise folder, e.g. `../../toast-service`) whose files form the
         * starter first; the starter folder's files add to or replace them. It lies beside the
         * exercises (below the exercise folder's grandparent, in the repository `examples/`).
         */
        base: Type.Optional(
            Type.String({
                pattern: BASE_PATH,
                errorMessage: 'base must be a relative folder path with / (.. allowed, no leading /)',
            }),
        ),
        /** Files of the base left out of the starter: a path, or a folder ending in `/` (everything below it). */
        omit: Type.Optional(
            Type.Array(StarterPath('omit entry'), {
                uniqueItems: true,
                errorMessage: 'omit must be a list of distinct relative paths (a folder ends in /)',
            }),
        ),
    },
    {
        $id: 'urn:maa:protocol:exercise',
        title: 'ExerciseManifest',
        description: 'exercise.json: a lab exercise (docs/lab.md "Exercises")',
        additionalProperties: false,
        errorMessage: 'expected an object with format, title, description, app, readOnly, tests and platforms',
    },
);
export type ExerciseManifest = Static<typeof ExerciseManifest>;

/** The exercise as released to a course: what the lab server stores and the browser shows. */
export const ReleasedExercise = Type.Object(
    {
        ...CommonFields,
        /** The exercise's name in its course (its folder's name). */
        name: Type.String({ pattern: '^[a-z0-9][a-z0-9-]*$', errorMessage: 'name must be lower case letters, digits and -' }),
        /** The description as Markdown text. */
        description: Type.String({ errorMessage: 'description must be Markdown text' }),
        /** The starter's files (paths), in the newest starter version. */
        files: PathList('files entry'),
        /** The newest starter version (1 at the first release, +1 at each update that changed it). */
        starterVersion: Type.Integer({ minimum: 1, errorMessage: 'starterVersion must be an integer from 1' }),
    },
    {
        $id: 'urn:maa:protocol:released-exercise',
        title: 'ReleasedExercise',
        description: 'a lab exercise as released to a course',
        additionalProperties: false,
        errorMessage: 'expected a released exercise',
    },
);
export type ReleasedExercise = Static<typeof ReleasedExercise>;
