// @maa/lab-server: the classroom lab server (docs/lab.md): its storage, its HTTP server with
// accounts and sessions, and the `maa-lab` command.
export * from './storage/index.js';
export * from './exercises/index.js';
export * from './grading/index.js';
export { type LabServer, type LabServerOptions, startLabServer, DEFAULT_PORT } from './http/server.js';
export {
    type Access,
    type AuthedHandler,
    type AuthedRequest,
    type LabRequest,
    type LabRoute,
    LabRoutes,
    type PublicHandler,
} from './http/routes.js';
export { readJson, stringField, userView } from './http/body.js';
export { CSRF_HEADER, type Authenticated } from './auth/sessions.js';
export type { OidcSettings } from './auth/oidc.js';
export type { RateLimitOptions } from './auth/rate-limit.js';
export { createLabProgram, type LabCommandFactory, LabCliError, type LabIo, registerLabCommand, runLab } from './cli/main.js';
export { type LabWorkspaceOptions, LabWorkspaces, WS_PREFIX, workspacePrefix } from './workspaces/index.js';
export { DEFAULT_QUOTAS, type QuotaOptions } from './quotas/index.js';
