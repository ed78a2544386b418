// @maa/ide-server: the IDE backend `maa-ide` (docs/ide.md). The programmatic entry is for
// tests and the end-to-end suite; the bin is src/cli.ts.
export { startIdeServer, defaults, type IdeServer, type IdeServerOptions } from './server.js';
export type { AppInfo, AppPlatformInfo } from './apps.js';
export type { GenerateAnswer, IdeDiagnostic } from './generation.js';
export type { SimStatus, SimMode } from './sim-session.js';
export type { WorkspaceEntry } from './workspace.js';
