/**
 * Loads Monaco on demand. The editor (about 1 MB of script) is its own chunk: the app shell
 * stays small for a classroom on a slow network, and only someone who opens a source waits
 * for it. Its own texts come in the page's language (`locales/`). A failed load (the server
 * went away) is not cached, so the next try loads again.
 */
export type MonacoApi = typeof import('monaco-editor/editor/editor.api');

let loading: Promise<MonacoApi> | null = null;

export function loadMonaco(): Promise<MonacoApi> {
  // Monaco's texts in the interface language must be in place before its modules run.
  loading ??= import('./locales')
    .then((locales) => {
      locales.followDocumentLanguage();
      return import('./setup');
    })
    .then(
      (setup) => setup.monaco,
      (error: unknown) => {
        loading = null;
        throw error;
      },
    );
  return loading;
}
