// The instructor's dashboard (docs/lab.md "The instructor's dashboard").
export { CheckThread, checkWorkerScript } from './check-thread.js';
export {
    type CheckerOptions,
    type CheckRequest,
    type CheckResponse,
    type CheckState,
    type FileDiagnostic,
    type FilesChecker,
    RECHECK_MS,
    type WorkspaceCheck,
    WorkspaceChecker,
    type WorkspaceFile,
} from './checker.js';
export { CSV_COLUMNS, csvField, dashboardCsv } from './csv.js';
export {
    buildDashboard,
    type Dashboard,
    type DashboardCell,
    type DashboardExercise,
    type DashboardStudent,
    type LiveSimulations,
    NO_LIVE_SIMULATIONS,
} from './data.js';
export { addDashboardRoutes, type DashboardHandle, type DashboardOptions } from './routes.js';
