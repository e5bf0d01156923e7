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
  getLineContent = (line: number) => this.value.split('\n')[line - 1] ?? '';
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
  run: (editor: FakeEditor) => void;
}

export class FakeEditor {
  disposed = false;
  blurListeners = new Set<Listener>();
  mouseListeners = new Set<(event: unknown) => void>();
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

export const fake = {
  editors: [] as FakeEditor[],
  models: [] as FakeModel[],
  markers: [] as Array<{ model: FakeModel; owner: string; markers: Array<Record<string, unknown>> }>,
  reset() {
    this.editors.length = 0;
    this.models.length = 0;
    this.markers.length = 0;
  },
  /** The newest markers set on a model. */
  markersOf(model: FakeModel) {
    return this.markers.filter((entry) => entry.model === model).at(-1)?.markers ?? [];
  },
};

const monaco = {
  MarkerSeverity: { Hint: 1, Info: 2, Warning: 4, Error: 8 },
  KeyCode: { F12: 70 },
  editor: {
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
