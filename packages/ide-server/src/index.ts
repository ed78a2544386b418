// @maa/ide-server: the IDE backend `maa-ide` (docs/ide.md). The programmatic entry is for
// tests and the end-to-end suite; the bin is src/cli.ts.
export { startIdeServer, defaults, type IdeServer, type IdeServerOptions } from './server.js';
export type { AppInfo, AppPlatformInfo } from './apps.js';
export type { GenerateAnswer, IdeDiagnostic } from './generation.js';
export type { SimStatus, SimMode } from './sim-session.js';
export type { WorkspaceEntry } from './workspace.js';
// The services the lab server runs per student workspace (docs/lab.md "Workspaces").
export { type ApiOptions, createApiRouter, startSimulation } from './api.js';
export { listApps } from './apps.js';
export { type GenerateJob, type GenerateJobResult, type GenerateRunner, GenerationService, runGenerateJob } from './generation.js';
export { readRequest, requireQuery } from './http-util.js';
export { descendantGroups, groupAlive, processAlive } from './process-group.js';
export { ROSBRIDGE_PATH, rejectUpgrade, SimProxy, VISER_PATH } from './proxy.js';
export { PathRedactor } from './redact.js';
export type { Router } from './router.js';
export { packageDir, ros2Environment } from './server.js';
export { type SimCommandWrapper, type SimLaunch, SimSessions, type SimSessionOptions } from './sim-session.js';
export { type StreamTestAnswer, StreamTestService, streamTestRequest } from './stream-tests.js';
export { Workspace } from './workspace.js';
