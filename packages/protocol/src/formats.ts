/**
 * The names, format tags and versions of the files the generators write. Kept in a file that imports
 * nothing, exported as `@maa/protocol/formats`, so that a writer needing only the tag (the
 * generator core's trace stage, the generators) does not load TypeBox and every schema at start.
 */

/** The trace file's name in each platform's output folder. */
export const TRACE_FILE_NAME = '.maa-trace.json';
/** `.maa-trace.json`'s `version` (trace/schema.ts). */
export const TRACE_FORMAT_VERSION = 2;

export const DEPLOYMENT_FILE_NAME = 'deployment.json';
/** `deployment.json`'s `format` (deployment/schema.ts). */
export const DEPLOYMENT_FORMAT = 'maa-deployment/1';

export const LOCKSTEP_FILE_NAME = 'lockstep.json';
/** `lockstep.json`'s `format` (lockstep/schema.ts). */
export const LOCKSTEP_FORMAT = 'maa-lockstep/1';

/** A lab exercise's description file in its folder (examples/lab/<name>/exercise.json). */
export const EXERCISE_FILE_NAME = 'exercise.json';
/** `exercise.json`'s `format` (exercise/schema.ts). */
export const EXERCISE_FORMAT = 'maa-exercise/1';
