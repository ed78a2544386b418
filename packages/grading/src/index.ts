/**
 * @maa/grading: autograding of MontiArc models against an exercise's grading specification
 * (docs/lab.md "Grading"). {@link gradeSubmissions} is the entry point.
 */
export { gradeSubmissions } from './grade.js';
export { GradingSpecError, loadGradingSpec } from './spec.js';
export type { GradeOptions, GradeProgress, Submission } from './types.js';
export { defaultPython, gradingPython, hasDefaultPython } from './python.js';
export { DriverError } from './driver.js';
export { type SubmissionModel, loadSubmissionModel } from './model.js';
export { gradeStructure } from './structure.js';
export { gradeDiagnostics } from './diagnostics.js';
export { computeCoverage, coverageShare, type Coverage } from './coverage.js';
export { DEFAULT_LIMITS, scenarioArgv } from './plan.js';
