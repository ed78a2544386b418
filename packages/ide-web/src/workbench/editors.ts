/**
 * The editor area: one Monaco editor, one model per workspace file (all model files are loaded
 * at start so the language server sees the whole workspace), tabs with dirty markers, saving.
 */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import { RegisteredMemoryFile, type RegisteredFileSystemProvider } from '@codingame/monaco-vscode-files-service-override';
import { api, pathOf, uriOf } from '../api.js';
import type { Disposable, TextRange } from '../contracts.js';
import { languageOf } from '../languages.js';
import { basename, h } from './dom.js';

export interface EditorEvents {
    onActiveChanged(path: string | undefined): void;
    onCursor(path: string, position: monaco.Position): void;
    onSaved(path: string): void;
}

interface Tab {
    path: string;
    element: HTMLElement;
    viewState: monaco.editor.ICodeEditorViewState | null;
}

export class EditorArea {
    readonly editor: monaco.editor.IStandaloneCodeEditor;
    private readonly tabs: Tab[] = [];
    private active: Tab | undefined;
    /** The text on disk as last read or saved, per path (dirty = model text differs). */
    private readonly saved = new Map<string, string>();
    private readonly loading = new Map<string, Promise<monaco.editor.ITextModel>>();

    private readonly registered = new Map<string, RegisteredMemoryFile>();

    constructor(
        private readonly tabBar: HTMLElement,
        container: HTMLElement,
        private readonly files: RegisteredFileSystemProvider | undefined,
        private readonly events: EditorEvents,
    ) {
        this.editor = monaco.editor.create(container, {
            automaticLayout: true,
            minimap: { enabled: false },
            fontSize: 13,
            'semanticHighlighting.enabled': true,
            renderWhitespace: 'selection',
            scrollBeyondLastLine: false,
            fixedOverflowWidgets: true,
            lightbulb: { enabled: monaco.editor.ShowLightbulbIconMode.OnCode },
        });
        this.editor.onDidChangeCursorPosition((e) => {
            if (this.active) this.events.onCursor(this.active.path, e.position);
        });
    }

    get activePath(): string | undefined {
        return this.active?.path;
    }

    openPaths(): string[] {
        return this.tabs.map((t) => t.path);
    }

    /** Creates (or returns) the model of a workspace file; `text` when already known. */
    model(path: string, text?: string): Promise<monaco.editor.ITextModel> {
        const uri = monaco.Uri.parse(uriOf(path));
        const existing = monaco.editor.getModel(uri);
        if (existing) {
            if (!this.saved.has(path)) this.saved.set(path, existing.getValue());
            return Promise.resolve(existing);
        }
        const pending = this.loading.get(path);
        if (pending) return pending;
        const promise = (async () => {
            const content = text ?? (await api.readFile(path));
            const again = monaco.editor.getModel(uri);
            const model = again ?? monaco.editor.createModel(content, languageOf(path), uri);
            this.saved.set(path, model.getValue());
            this.register(path, model.getValue());
            model.onDidChangeContent(() => this.updateDirty(path));
            return model;
        })();
        this.loading.set(path, promise);
        promise.finally(() => this.loading.delete(path)).catch(() => undefined);
        return promise;
    }

    /** Keeps VS Code's file service copy of a workspace file current (it serves peeks and references). */
    private register(path: string, text: string): void {
        if (!this.files) return;
        const existing = this.registered.get(path);
        const content = new TextEncoder().encode(text);
        if (existing) {
            void existing.write(content);
            return;
        }
        const file = new RegisteredMemoryFile(monaco.Uri.parse(uriOf(path)), text);
        this.registered.set(path, file);
        this.files.registerFile(file);
    }

    isDirty(path: string): boolean {
        const model = monaco.editor.getModel(monaco.Uri.parse(uriOf(path)));
        return !!model && this.saved.has(path) && model.getValue() !== this.saved.get(path);
    }

    /** Opens a file in a tab (or activates its tab) and optionally selects a range. */
    async open(path: string, selection?: TextRange, focus = true): Promise<monaco.editor.ICodeEditor> {
        const model = await this.model(path);
        let tab = this.tabs.find((t) => t.path === path);
        if (!tab) {
            const close = h('span', { class: 'tab-close', title: 'Close (Ctrl+W)' }, '×');
            const element = h(
                'div',
                { class: 'tab', 'data-path': path, title: path },
                h('span', { class: 'tab-dirty' }, '●'),
                h('span', { class: 'tab-label' }, basename(path)),
                close,
            );
            element.addEventListener('mousedown', (e) => {
                if (e.button === 1) {
                    e.preventDefault();
                    this.close(path);
                }
            });
            element.addEventListener('click', (e) => {
                if (e.target === close) this.close(path);
                else void this.open(path);
            });
            tab = { path, element, viewState: null };
            this.tabs.push(tab);
            this.tabBar.append(element);
            this.updateDirty(path);
        }
        if (this.active !== tab) {
            if (this.active) this.active.viewState = this.editor.saveViewState();
            this.active = tab;
            this.editor.setModel(model);
            if (tab.viewState) this.editor.restoreViewState(tab.viewState);
            for (const t of this.tabs) t.element.classList.toggle('active', t === tab);
            tab.element.scrollIntoView({ block: 'nearest', inline: 'nearest' });
            this.events.onActiveChanged(path);
        }
        if (selection) {
            const range = new monaco.Range(
                selection.start.line + 1,
                selection.start.character + 1,
                selection.end.line + 1,
                selection.end.character + 1,
            );
            this.editor.setSelection(range);
            this.editor.revealRangeInCenterIfOutsideViewport(range);
        }
        if (focus) this.editor.focus();
        return this.editor;
    }

    close(path: string): void {
        const index = this.tabs.findIndex((t) => t.path === path);
        if (index < 0) return;
        const [tab] = this.tabs.splice(index, 1);
        tab.element.remove();
        if (this.active === tab) {
            this.active = undefined;
            const next = this.tabs[Math.min(index, this.tabs.length - 1)];
            if (next) void this.open(next.path);
            else {
                this.editor.setModel(null);
                this.events.onActiveChanged(undefined);
            }
        }
    }

    /** Saves a file (default: the active one) with PUT /api/file. */
    async save(path = this.active?.path): Promise<void> {
        if (!path) return;
        const model = monaco.editor.getModel(monaco.Uri.parse(uriOf(path)));
        if (!model) return;
        const text = model.getValue();
        await api.writeFile(path, text);
        this.saved.set(path, text);
        this.register(path, text);
        this.updateDirty(path);
        this.events.onSaved(path);
    }

    private updateDirty(path: string): void {
        const tab = this.tabs.find((t) => t.path === path);
        tab?.element.classList.toggle('dirty', this.isDirty(path));
    }

    onDidChangeActive(listener: () => void): Disposable {
        return this.editor.onDidChangeModel(listener);
    }
}

export function pathOfModel(model: monaco.editor.ITextModel): string | undefined {
    return pathOf(model.uri.toString());
}
