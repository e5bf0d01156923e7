/**
 * Monaco's environment, set before Monaco's own modules run (setup.ts imports this first).
 *
 * - `getWorker`: the one worker the editor needs (diffs, word ranges for completion, link
 *   detection), a bundled module served by Nasaq itself. Monaco asks for no other label: the
 *   JSON/TypeScript/CSS/HTML language services are not part of this build.
 * - `globalAPI`: Monaco's documented switch that also puts its API on `window.monaco`, so the
 *   browser tests (and a teacher at the console) can read models and markers of the open editors.
 */
import EditorWorker from 'monaco-editor/editor/editor.worker?worker';

self.MonacoEnvironment = {
  globalAPI: true,
  getWorker: () => new EditorWorker(),
};
