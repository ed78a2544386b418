/**
 * The generate panel: application/platform picker (GET /api/apps), generation
 * (POST /api/generate), the generated file tree and a read-only preview, and navigation
 * between model and generated code through the trace file.
 */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import { MODEL_ROOT_MARKER, resolveModelRoot } from '@maa/language-server/model-root';
import type { LineSpan, Trace } from '@maa/protocol';
import { api, type GenerateDiagnostic, type TraceElement, type TraceFile } from '../api.js';
import type { AppInfo, TextPosition, TextRange } from '../contracts.js';
import { languageOf } from '../languages.js';
import { basename, h } from './dom.js';

export interface GenerateHost {
    /** Opens a model file at a range. */
    openModel(path: string, range: TextRange): void;
    /** Ensures a model exists for a workspace file (for generator diagnostics). */
    modelOf(path: string): Promise<monaco.editor.ITextModel>;
    notify(severity: 'info' | 'warning' | 'error', message: string): void;
    /** Shows the generate tab of the bottom panel. */
    reveal(): void;
    /** All workspace paths (to find the model root of an application). */
    workspacePaths(): string[];
}

const MARKER_OWNER = 'maa-generate';

interface Generated {
    app: AppInfo;
    platform: string;
    files: string[];
    trace?: TraceFile;
}

export class GeneratePanel {
    private readonly picker: HTMLSelectElement;
    private readonly button: HTMLButtonElement;
    private readonly status: HTMLElement;
    private readonly tree: HTMLElement;
    private readonly location: HTMLElement;
    private readonly preview: monaco.editor.IStandaloneCodeEditor;
    private apps: AppInfo[] = [];
    private current: Generated | undefined;
    private shownFile: string | undefined;
    private markedModels: monaco.editor.ITextModel[] = [];

    constructor(
        container: HTMLElement,
        private readonly host: GenerateHost,
    ) {
        this.picker = h('select', { class: 'platform-picker', 'data-testid': 'platform-picker', title: 'Application and platform' });
        this.button = h('button', { class: 'primary', 'data-testid': 'generate-button' }, 'Generate');
        this.status = h('span', { class: 'generate-status' });
        this.tree = h('div', { class: 'generated-tree', 'data-testid': 'generated-files' });
        this.location = h('span', { class: 'generated-location' });
        const previewHost = h('div', { class: 'generated-preview', 'data-testid': 'generated-preview' });
        container.replaceChildren(
            h('div', { class: 'panel-toolbar' }, this.picker, this.button, this.status),
            h(
                'div',
                { class: 'generate-body' },
                this.tree,
                h('div', { class: 'generated-right' }, h('div', { class: 'generated-header' }, this.location), previewHost),
            ),
        );
        this.preview = monaco.editor.create(previewHost, {
            readOnly: true,
            automaticLayout: true,
            minimap: { enabled: false },
            fontSize: 12,
            scrollBeyondLastLine: false,
            domReadOnly: true,
            fixedOverflowWidgets: true,
        });
        this.preview.addAction({
            id: 'maa.goToModel',
            label: 'Go to Model Element',
            keybindings: [monaco.KeyCode.F12],
            contextMenuGroupId: 'navigation',
            run: () => this.goToModel(),
        });
        this.preview.onDidChangeCursorPosition((e) => this.showLocation(e.position.lineNumber));
        this.button.addEventListener('click', () => void this.generate());
        void this.loadApps();
    }

    async loadApps(): Promise<void> {
        try {
            this.apps = await api.apps();
        } catch (error) {
            this.status.textContent = String(error instanceof Error ? error.message : error);
            return;
        }
        const previous = this.picker.value;
        this.picker.replaceChildren(
            ...this.apps.flatMap((app) =>
                app.platforms.map((p) => h('option', { value: `${app.path}\u0000${p.name}` }, `${app.name} · ${p.name} (${p.kind})`)),
            ),
        );
        if (previous && [...this.picker.options].some((o) => o.value === previous)) this.picker.value = previous;
    }

    /** Selects a platform by name (first application that has it). */
    selectPlatform(platform: string): void {
        const option = [...this.picker.options].find((o) => o.value.endsWith(`\u0000${platform}`));
        if (option) this.picker.value = option.value;
    }

    private selection(): { app: AppInfo; platform: string } | undefined {
        const [appPath, platform] = this.picker.value.split('\u0000');
        const app = this.apps.find((a) => a.path === appPath);
        return app && platform ? { app, platform } : undefined;
    }

    async generate(): Promise<boolean> {
        const selection = this.selection();
        if (!selection) {
            this.host.notify('warning', 'No application configuration (.arcapp) to generate.');
            return false;
        }
        const { app, platform } = selection;
        this.button.disabled = true;
        this.status.textContent = `Generating ${app.name} for ${platform}…`;
        this.status.className = 'generate-status running';
        const started = performance.now();
        try {
            const result = await api.generate(app.path, platform);
            await this.showDiagnostics(app, result.diagnostics);
            const files = result.files.map((f) => f.path).sort();
            this.current = { app, platform, files };
            try {
                this.current.trace = await api.trace(app.path, platform);
            } catch {
                /* no trace (failed generation) */
            }
            this.renderTree();
            const errors = result.diagnostics.filter((d) => d.severity === 'error').length;
            this.status.className = `generate-status ${result.ok ? 'ok' : 'failed'}`;
            this.status.textContent = result.ok
                ? `${files.length} files for ${platform} in ${Math.round(performance.now() - started)} ms`
                : `Generation failed: ${errors} error(s), see Problems`;
            if (!result.ok) this.host.notify('error', `Generation for ${platform} failed`);
            return result.ok;
        } catch (error) {
            this.status.className = 'generate-status failed';
            this.status.textContent = error instanceof Error ? error.message : String(error);
            this.host.notify('error', this.status.textContent);
            return false;
        } finally {
            this.button.disabled = false;
        }
    }

    /**
     * The model root of an application (workspace-relative, `''` for the workspace folder), by the
     * one rule the backend generates with (`resolveModelRoot`, docs/user-guide.md "Model roots").
     * An `.arcapp` declares no package, so only the `maa.json` rule and the app's folder apply.
     */
    private modelRootOf(app: AppInfo): string {
        const paths = new Set(this.host.workspacePaths());
        return resolveModelRoot(app.path, {
            hasMarker: (folder) => paths.has(folder ? `${folder}/${MODEL_ROOT_MARKER}` : MODEL_ROOT_MARKER),
            stopAt: '',
        });
    }

    private workspacePathOf(element: TraceElement): string {
        const root = this.current ? this.modelRootOf(this.current.app) : '';
        return root ? `${root}/${element.file}` : element.file;
    }

    private async showDiagnostics(app: AppInfo, diagnostics: GenerateDiagnostic[]): Promise<void> {
        for (const model of this.markedModels) if (!model.isDisposed()) monaco.editor.setModelMarkers(model, MARKER_OWNER, []);
        this.markedModels = [];
        const byFile = new Map<string, GenerateDiagnostic[]>();
        for (const d of diagnostics) {
            const file = d.file || app.path;
            byFile.set(file, [...(byFile.get(file) ?? []), d]);
        }
        for (const [file, list] of byFile) {
            let model: monaco.editor.ITextModel;
            try {
                model = await this.host.modelOf(file);
            } catch {
                continue;
            }
            monaco.editor.setModelMarkers(
                model,
                MARKER_OWNER,
                list.map((d) => {
                    const range = d.range;
                    return {
                        severity:
                            d.severity === 'error'
                                ? monaco.MarkerSeverity.Error
                                : d.severity === 'warning'
                                  ? monaco.MarkerSeverity.Warning
                                  : monaco.MarkerSeverity.Info,
                        message: d.message,
                        code: d.code,
                        source: 'generate',
                        startLineNumber: range.start.line + 1,
                        startColumn: range.start.character + 1,
                        endLineNumber: range.end.line + 1,
                        endColumn: Math.max(range.end.character + 1, range.start.character + 2),
                    };
                }),
            );
            this.markedModels.push(model);
        }
    }

    private renderTree(): void {
        const generated = this.current;
        if (!generated) return;
        const root = h('ul', { class: 'tree' });
        const folders = new Map<string, HTMLElement>([['', root]]);
        const folderList = (folder: string): HTMLElement => {
            const existing = folders.get(folder);
            if (existing) return existing;
            const parent = folder.includes('/') ? folder.slice(0, folder.lastIndexOf('/')) : '';
            const list = h('ul', { class: 'tree' });
            const depth = folder.split('/').length - 1;
            const row = h(
                'div',
                { class: 'tree-row folder', style: `padding-left:${8 + depth * 12}px` },
                h('span', { class: 'twistie' }, '▾'),
                h('span', { class: 'tree-label' }, basename(folder)),
            );
            row.addEventListener('click', () => {
                list.hidden = !list.hidden;
                row.firstElementChild!.textContent = list.hidden ? '▸' : '▾';
            });
            folderList(parent).append(h('li', {}, row, list));
            folders.set(folder, list);
            return list;
        };
        for (const file of generated.files) {
            const folder = file.includes('/') ? file.slice(0, file.lastIndexOf('/')) : '';
            const depth = folder ? folder.split('/').length : 0;
            const row = h(
                'div',
                { class: 'tree-row file', 'data-path': file, title: file, style: `padding-left:${8 + depth * 12}px` },
                h('span', { class: 'twistie' }),
                h('span', { class: 'tree-label' }, basename(file)),
            );
            row.addEventListener('click', () => void this.showFile(file));
            folderList(folder).append(h('li', {}, row));
        }
        this.tree.replaceChildren(root);
    }

    /** Shows a generated file in the preview, optionally selecting lines (0-based, inclusive, as in the trace file). */
    async showFile(file: string, lines?: LineSpan): Promise<void> {
        const generated = this.current;
        if (!generated) return;
        const text = await api.generatedFile(generated.app.path, generated.platform, file);
        const uri = monaco.Uri.from({ scheme: 'maa-generated', path: `/${generated.platform}/${file}` });
        let model = monaco.editor.getModel(uri);
        if (model) model.setValue(text);
        else model = monaco.editor.createModel(text, languageOf(file), uri);
        this.preview.setModel(model);
        this.shownFile = file;
        for (const row of this.tree.querySelectorAll<HTMLElement>('.tree-row.file'))
            row.classList.toggle('selected', row.dataset.path === file);
        if (lines) {
            const range = new monaco.Range(lines.first + 1, 1, lines.last + 1, model.getLineMaxColumn(lines.last + 1));
            this.preview.setSelection(range);
            this.preview.revealRangeInCenter(range);
        }
        this.showLocation((lines?.first ?? 0) + 1);
    }

    /** The innermost traced element of a generated line (Monaco's 1-based line number). */
    private innermostTrace(file: string, lineNumber: number): TraceElement | undefined {
        const line = lineNumber - 1;
        const traces = this.current?.trace?.files.find((f) => f.path === file)?.traces ?? [];
        let best: Trace | undefined;
        for (const t of traces) {
            const { first, last } = t.lines;
            if (first <= line && line <= last && (!best || last - first <= best.lines.last - best.lines.first)) best = t;
        }
        return best?.element;
    }

    private showLocation(line: number): void {
        const file = this.shownFile;
        const element = file ? this.innermostTrace(file, line) : undefined;
        if (!file || !element) {
            this.location.replaceChildren(file ? h('span', { class: 'muted' }, `${file} — no model element at line ${line}`) : '');
            return;
        }
        const at = element.range ? `:${element.range.start.line + 1}` : '';
        const link = h(
            'a',
            { href: '#', class: 'trace-link', 'data-testid': 'trace-link', title: 'Go to the model element (F12)' },
            `${element.type} ${element.name ?? ''} — ${element.file}${at}`,
        );
        link.addEventListener('click', (e) => {
            e.preventDefault();
            this.goToModel();
        });
        this.location.replaceChildren(h('span', { class: 'muted' }, `${file}  ↦  `), link);
    }

    goToModel(): void {
        const file = this.shownFile;
        const line = this.preview.getPosition()?.lineNumber ?? 1;
        const element = file ? this.innermostTrace(file, line) : undefined;
        if (!element?.range) {
            this.host.notify('info', 'No model element is traced to this line.');
            return;
        }
        this.host.openModel(this.workspacePathOf(element), element.range);
    }

    /** "Show generated code": the innermost traced generated lines of a model position (0-based, LSP). */
    async showGeneratedFor(path: string, position: TextPosition): Promise<void> {
        if (!this.current) {
            const ok = await this.generate();
            if (!ok && !this.current) return;
        }
        const generated = this.current!;
        const root = this.modelRootOf(generated.app);
        const rel = root && path.startsWith(`${root}/`) ? path.slice(root.length + 1) : path;
        const { line, character } = position;
        let best: { file: string; lines: LineSpan; size: number } | undefined;
        for (const f of generated.trace?.files ?? []) {
            for (const t of f.traces) {
                const range = t.element.range;
                if (!range || t.element.file !== rel) continue;
                const { start, end } = range;
                const inside =
                    (line > start.line || (line === start.line && character >= start.character)) &&
                    (line < end.line || (line === end.line && character <= end.character));
                if (!inside) continue;
                const size = (end.line - start.line) * 10000 + (end.character - start.character);
                if (!best || size < best.size) best = { file: f.path, lines: t.lines, size };
            }
        }
        this.host.reveal();
        if (!best) {
            this.host.notify('info', `No generated code for this position of ${basename(path)} (platform ${generated.platform}).`);
            return;
        }
        await this.showFile(best.file, best.lines);
    }
}
