/**
 * Which project file a Monaco model shows. Monaco's providers are registered once for every
 * model of a language; they ask here which project's outline applies. The editor binds its model
 * when it creates it, with a getter (a tab's file may be renamed while it is open).
 */

export interface ModelSource {
  projectId: number;
  /** The file's name in the project (`OB1.awl`). */
  path: string;
}

type Getter = () => ModelSource | null;

const sources = new WeakMap<object, Getter>();

/** Binds `model` to the file `source()` names; dispose the result with the model. */
export function bindModel(model: object, source: Getter): { dispose: () => void } {
  sources.set(model, source);
  return { dispose: () => void sources.delete(model) };
}

/** The project file of a model, or null for a text that belongs to no project. */
export function sourceOf(model: object): ModelSource | null {
  return sources.get(model)?.() ?? null;
}
