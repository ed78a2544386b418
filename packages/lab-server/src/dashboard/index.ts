// The instructor's dashboard (docs/lab.md "The instructor's dashboard").
export { type FileDiagnostic, type FolderChecker, familyChecker, type WorkspaceCheck, WorkspaceChecker } from './checker.js';
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
export { DASHBOARD_CSP } from './pages.js';
export { addDashboardRoutes, type DashboardOptions } from './routes.js';
