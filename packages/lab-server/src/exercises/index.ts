// Lab exercises (docs/lab.md "Exercises"): load an exercise folder, release it to a course,
// give students their starter, and bring starter updates to them without losing their edits.
export { ExerciseError } from './errors.js';
export { type LoadedExercise, loadExercise, releasedSpec } from './load.js';
export { type MergeLabels, type MergeOutcome, mergeStarter } from './merge.js';
export { type ReleaseOptions, type Released, releaseExercise } from './release.js';
export { type Updated, updateExercise } from './update.js';
export { specOf } from './spec.js';
export { CONFLICT_SUFFIX, type FileOutcome, type FileUpdate, updateWorkspace } from './update-workspace.js';
export { openExerciseWorkspace } from './workspace.js';
export { exerciseCommand, type ExerciseIo, registerExerciseCommands } from './command.js';
