// Autograding in the lab (docs/lab.md "Grading"): the service that runs gradings, its routes and command.
export { defaultEngine, type EngineOptions, type EngineSubmission, type GradeEngine, progressOf } from './engine.js';
export { keepRecordings, recordingFile, recordingName } from './files.js';
export { addGradingRoutes } from './routes.js';
export { GradingBusy, GradingService, type GradingServiceOptions, GradingUnavailable } from './service.js';
export { gradingBase, type ResultView, type RunView, recordingUrl, resultView, runView } from './views.js';
