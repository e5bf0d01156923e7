/**
 * A stand-in for Monaco in jsdom (the real one runs in the browser tests): models that take
 * "typing", editors that record what the app asks of them. Use with
 * `vi.mock('../../frontend/src/editor/monaco/load', () => import('./fakeMonaco'))`.
 */
type Listener = () => void;

export class FakeModel {
  listeners = new Set<Listener>();
  disposed = false;
  constructor(
    public value: string,
    public language: string,
  ) {}
  getValue = () => this.value;
  getLanguageId = () => this.language;
  getLineContent = (line: number) => this.value.split('\n')[line - 1] ?? '';
  getLineCount = () => this.value.split('\n').length;
  getLineMaxColumn = (line: number) => this.getLineContent(line).length + 1;
  getFullModelRange = () => ({ startLineNumber: 1, startColumn: 1, endLineNumber: 1, endColumn: 1 });
  pushEditOperations = (_before: unknown, edits: Array<{ text: string }>) => {
    this.value = edits[0]!.text;
    this.listeners.forEach((listener) => listener());
    return null;
  };
  onDidChangeContent = (listener: Listener) => {
    this.listeners.add(listener);
    return { dispose: () => this.listeners.delete(listener) };
  };
  /** What keystrokes do: the text changes and the listeners hear of it. */
  type = (text: string) => {
    this.value += text;
    this.listeners.forEach((listener) => listener());
  };
  /** Replaces the whole text, as a select-all and paste would. */
  replace = (text: string) => {
    this.value = text;
    this.listeners.forEach((listener) => listener());
  };
  dispose = () => {
    this.disposed = true;
  };
}

interface FakeAction {
  id: string;
  label: string;
  keybindings?: number[];
  run: (editor: FakeEditor) => void;
}

/** A decoration as the app gives it to Monaco. */
export interface FakeDecoration {
  range: { startLineNumber: number; startColumn: number; endLineNumber: number; endColumn: number };
  options: Record<string, unknown>;
}

/** `editor.createDecorationsCollection()`: what it holds now. */
export class FakeDecorations {
  items: FakeDecoration[] = [];
  sets = 0;
  constructor(initial: FakeDecoration[] = []) {
    this.items = [...initial];
  }
  set = (items: FakeDecoration[]) => {
    this.items = [...items];
    this.sets += 1;
  };
  clear = () => {
    this.items = [];
  };
}

/** Monaco's mouse target types the app reads. */
export const MouseTargetType = { CONTENT_TEXT: 6, GUTTER_GLYPH_MARGIN: 2 };

export class FakeEditor {
  disposed = false;
  blurListeners = new Set<Listener>();
  mouseListeners = new Set<(event: unknown) => void>();
  contextMenuListeners = new Set<(event: unknown) => void>();
  scrollListeners = new Set<Listener>();
  cursorListeners = new Set<Listener>();
  layoutListeners = new Set<Listener>();
  decorationCollections: FakeDecorations[] = [];
  /** The view: 20 px lines, `viewLines` of them in view from `scrollTop`. */
  scrollTop = 0;
  viewLines = 20;
  actions = new Map<string, FakeAction>();
  position = { lineNumber: 1, column: 1 };
  revealed: number[] = [];
  constructor(
    public host: HTMLElement,
    public options: Record<string, unknown>,
  ) {}
  getModel = () => this.options.model as FakeModel;
  updateOptions = (options: Record<string, unknown>) => Object.assign(this.options, options);
  onDidBlurEditorText = (listener: Listener) => {
    this.blurListeners.add(listener);
    return { dispose: () => this.blurListeners.delete(listener) };
  };
  onMouseDown = (listener: (event: unknown) => void) => {
    this.mouseListeners.add(listener);
    return { dispose: () => this.mouseListeners.delete(listener) };
  };
  onContextMenu = (listener: (event: unknown) => void) => {
    this.contextMenuListeners.add(listener);
    return { dispose: () => this.contextMenuListeners.delete(listener) };
  };
  onDidScrollChange = (listener: Listener) => {
    this.scrollListeners.add(listener);
    return { dispose: () => this.scrollListeners.delete(listener) };
  };
  onDidChangeCursorPosition = (listener: Listener) => {
    this.cursorListeners.add(listener);
    return { dispose: () => this.cursorListeners.delete(listener) };
  };
  onDidLayoutChange = (listener: Listener) => {
    this.layoutListeners.add(listener);
    return { dispose: () => this.layoutListeners.delete(listener) };
  };
  onDidChangeModelContent = (listener: Listener) => this.getModel().onDidChangeContent(listener);
  createDecorationsCollection = (initial: FakeDecoration[] = []) => {
    const collection = new FakeDecorations(initial);
    this.decorationCollections.push(collection);
    return collection;
  };
  /** Every decoration the app shows now. */
  decorations = () => this.decorationCollections.flatMap((collection) => collection.items);
  getScrollTop = () => this.scrollTop;
  getTopForLineNumber = (line: number) => (line - 1) * 20;
  getVisibleRanges = () => {
    const first = Math.floor(this.scrollTop / 20) + 1;
    const last = Math.min(this.getModel().getLineCount(), first + this.viewLines - 1);
    return [{ startLineNumber: first, startColumn: 1, endLineNumber: last, endColumn: 1 }];
  };
  revealLineInCenterIfOutsideViewport = (line: number) => this.revealed.push(line);
  /** The user scrolls the text to `top` pixels. */
  scrollTo = (top: number) => {
    this.scrollTop = top;
    this.scrollListeners.forEach((listener) => listener());
  };
  /** The caret moves (a click or the arrow keys). */
  moveCaret = (lineNumber: number, column = 1) => {
    this.position = { lineNumber, column };
    this.cursorListeners.forEach((listener) => listener());
  };
  /** A click in the glyph margin (`right`: the right button, which opens the context menu). */
  clickGlyph = (lineNumber: number, right = false) => {
    const target = { type: MouseTargetType.GUTTER_GLYPH_MARGIN, position: { lineNumber, column: 1 } };
    const event = { leftButton: !right, rightButton: right, ctrlKey: false, metaKey: false, preventDefault: () => undefined };
    this.mouseListeners.forEach((listener) => listener({ target, event }));
    if (right) this.contextMenuListeners.forEach((listener) => listener({ target, event }));
  };
  /** Runs an action by id, with the caret where it is. */
  runAction = (id: string) => this.actions.get(id)?.run(this);
  addAction = (action: FakeAction) => {
    this.actions.set(action.id, action);
    return { dispose: () => this.actions.delete(action.id) };
  };
  getPosition = () => this.position;
  setPosition = (position: { lineNumber: number; column: number }) => {
    this.position = position;
  };
  revealLineInCenter = (line: number) => this.revealed.push(line);
  layout = () => undefined;
  focus = () => undefined;
  /** The text area loses the focus. */
  blur = () => this.blurListeners.forEach((listener) => listener());
  /** F12 with the caret at `line`/`column`. */
  goToDefinition = (lineNumber: number, column: number) => {
    this.position = { lineNumber, column };
    this.actions.get('nasaq.goToDefinition')?.run(this);
  };
  dispose = () => {
    this.disposed = true;
  };
}

/** A completion or hover provider registered for a language (`monaco.languages.register*`). */
export interface FakeProvider {
  kind: 'completion' | 'hover';
  language: string;
  provider: Record<string, unknown>;
  disposed: boolean;
}

function register(kind: FakeProvider['kind'], language: string, provider: Record<string, unknown>) {
  const entry: FakeProvider = { kind, language, provider, disposed: false };
  fake.providers.push(entry);
  return { dispose: () => void (entry.disposed = true) };
}

export const fake = {
  editors: [] as FakeEditor[],
  models: [] as FakeModel[],
  markers: [] as Array<{ model: FakeModel; owner: string; markers: Array<Record<string, unknown>> }>,
  providers: [] as FakeProvider[],
  reset() {
    this.editors.length = 0;
    this.models.length = 0;
    this.markers.length = 0;
    this.providers.length = 0;
  },
  /** The newest provider of a kind for a language that is still registered. */
  providerOf(kind: FakeProvider['kind'], language: string) {
    return this.providers.filter((p) => p.kind === kind && p.language === language && !p.disposed).at(-1)?.provider;
  },
  /** The newest markers set on a model. */
  markersOf(model: FakeModel) {
    return this.markers.filter((entry) => entry.model === model).at(-1)?.markers ?? [];
  },
};

const monaco = {
  languages: {
    CompletionItemKind: { Operator: 11, Keyword: 17, Snippet: 27, Function: 1, Constant: 14, Field: 3, Module: 8, TypeParameter: 24 },
    CompletionItemInsertTextRule: { InsertAsSnippet: 4 },
    registerCompletionItemProvider: (language: string, provider: Record<string, unknown>) => register('completion', language, provider),
    registerHoverProvider: (language: string, provider: Record<string, unknown>) => register('hover', language, provider),
  },
  MarkerSeverity: { Hint: 1, Info: 2, Warning: 4, Error: 8 },
  KeyMod: { CtrlCmd: 2048, Shift: 1024, Alt: 512 },
  KeyCode: { F12: 70, F9: 67, F2: 60 },
  editor: {
    MouseTargetType,
    TrackedRangeStickiness: { AlwaysGrowsWhenTypingAtEdges: 0, NeverGrowsWhenTypingAtEdges: 1 },
    createModel: (value: string, language: string) => {
      const model = new FakeModel(value, language);
      fake.models.push(model);
      return model;
    },
    create: (host: HTMLElement, options: Record<string, unknown>) => {
      const editor = new FakeEditor(host, options);
      fake.editors.push(editor);
      return editor;
    },
    setModelLanguage: (model: FakeModel, language: string) => {
      model.language = language;
    },
    setModelMarkers: (model: FakeModel, owner: string, markers: Array<Record<string, unknown>>) => {
      fake.markers.push({ model, owner, markers });
    },
    remeasureFonts: () => undefined,
  },
};

export function loadMonaco() {
  return Promise.resolve(monaco);
}
