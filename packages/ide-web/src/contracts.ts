/**
 * The seams between the parts of the browser app: the workbench shell (editor, explorer,
 * problems, generate panel) owns the language client and the layout; the diagram and the
 * simulate panel are mounted into containers it hands out. Only these types cross the seams.
 */
import type { AppInfo } from '@maa/protocol';

// The diagram's seam lives with the diagram (@maa/diagram-view, shared with the VS Code extension).
export type {
    DiagramHost,
    DiagramLiveLayer,
    DiagramTarget,
    DiagramView,
    Disposable,
    TextPosition,
    TextRange,
} from '@maa/diagram-view/contracts';

/** One application configuration of the workspace (`GET /api/apps`, @maa/protocol). */
export type { AppInfo };

/** What the shell gives the simulate panel (@maa/simulate-view's seam). */
export type { SimulateHost } from '@maa/simulate-view/contracts';
