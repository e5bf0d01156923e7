/**
 * A page fixture that records what a user would never want to see: console errors, uncaught
 * exceptions, failed requests, and any request that leaves the local server.
 */
import { test as base, expect, type APIRequestContext, type Locator, type Page } from '@playwright/test';

export interface PageWatch {
  consoleErrors: string[];
  foreignRequests: string[];
  failedRequests: string[];
}

export const test = base.extend<{ watch: PageWatch; freshSessions: void }>({
  // Simulation sessions belong to projects and outlive the page (a reload reattaches), so each
  // test ends by closing those it left running: the next one starts with no CPU running.
  freshSessions: [
    async ({ request }, use) => {
      await use();
      const running = (await (await request.get('/api/sessions')).json()) as Array<{ id: string }>;
      for (const session of running) await request.delete(`/api/sessions/${session.id}`);
    },
    { auto: true },
  ],
  watch: async ({ page, baseURL }, use) => {
    const origin = new URL(baseURL!).origin;
    const watch: PageWatch = { consoleErrors: [], foreignRequests: [], failedRequests: [] };
    page.on('console', (msg) => {
      if (msg.type() === 'error') watch.consoleErrors.push(msg.text());
    });
    page.on('pageerror', (err) => watch.consoleErrors.push(`uncaught: ${err.message}`));
    page.on('request', (req) => {
      const url = req.url();
      if (url.startsWith('data:') || url.startsWith('blob:')) return;
      if (new URL(url).origin !== origin) watch.foreignRequests.push(url);
    });
    page.on('requestfailed', (req) => watch.failedRequests.push(`${req.url()}: ${req.failure()?.errorText}`));
    await use(watch);
  },
});

export { expect };

/** Chooses a UI language through the language switch, as a user would. */
export async function chooseLanguage(page: Page, code: 'en' | 'ar' | 'fa' | 'vi'): Promise<void> {
  await page.getByTestId('lang-switch').selectOption(code);
  await expect(page.locator('html')).toHaveAttribute('lang', code);
}

/** The code editor of the tab in front. */
export const visibleEditor = (page: Page): Locator =>
  page.locator('.source-view:not([hidden]) [data-testid="code-editor"]');

/** The project tree. */
export const tree = (page: Page): Locator => page.getByTestId('block-tree');

/** Expands a project in the tree (a click on its row) and returns its id. */
export async function expandProject(page: Page, name: string): Promise<number> {
  const node = tree(page).getByRole('treeitem', { name, exact: true });
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
  return Number((await node.getAttribute('data-testid'))?.replace('project-node-', ''));
}

/** Opens a project file from the tree (double-click) and waits for its editor. */
export async function openFile(page: Page, projectId: number, name: string): Promise<Locator> {
  await tree(page).getByTestId(`file-node-${projectId}-${name}`).dblclick();
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
  return editor;
}

let startProjects = 0;

/**
 * The Start page's "New STL/SCL source". With no project selected the user is asked for one and
 * makes a new project (a fresh project gets the example program); with one selected, the source
 * goes there at once. Waits for the editor.
 */
export async function newStartSource(page: Page, language: 'stl' | 'scl'): Promise<Locator> {
  // Making a project (and a file) first takes its own time, on top of the test's own steps.
  test.info().setTimeout(test.info().timeout + 30_000);
  const tabs = page.locator('[data-testid^="editor-tab-source-"]');
  const before = await tabs.count();
  await page.getByTestId(`new-source-${language}`).click();
  const pick = page.getByTestId('project-pick-dialog');
  await expect.poll(async () => (await pick.isVisible()) || (await tabs.count()) > before).toBe(true);
  if (await pick.isVisible()) {
    await pick.getByTestId('project-pick-new').click();
    startProjects += 1;
    await page.getByTestId('project-name-input').fill(`Start ${language} ${Date.now()}-${startProjects}`);
    await page.getByTestId('project-create-submit').click();
  }
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
  return editor;
}

type Monaco = typeof import('monaco-editor/editor/editor.api');
type WithMonaco = Window & { monaco: Monaco };


/** The 1-based line of the editor in front whose text contains `text`. */
export function lineOf(page: Page, text: string): Promise<number> {
  return page.evaluate((wanted) => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const index = editor?.getModel()?.getLinesContent().findIndex((line) => line.includes(wanted)) ?? -1;
    return index + 1;
  }, text);
}

/** Puts the caret on `line` of the editor in front and gives it the focus. */
export async function caretTo(page: Page, line: number): Promise<void> {
  await page.evaluate((target) => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    editor?.setPosition({ lineNumber: target, column: 1 });
    editor?.revealLineInCenter(target);
    editor?.focus();
  }, line);
}

let madeProjects = 0;

/** A new project (its name made unique) holding `files` (path → text), created over the API. */
export async function projectWithFiles(request: APIRequestContext, name: string, files: Record<string, string>): Promise<number> {
  madeProjects += 1;
  const created = await request.post('/api/projects', { data: { name: `${name} ${Date.now()}-${madeProjects}` } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const [path, text] of Object.entries(files)) {
    expect((await request.put(`/api/projects/${id}/files/${path}`, { data: { text } })).ok()).toBe(true);
  }
  return id;
}

/** The text of a project file, read over the API. */
export async function fileText(request: APIRequestContext, projectId: number, path: string): Promise<string> {
  const response = await request.get(`/api/projects/${projectId}/files/${path}`);
  expect(response.ok()).toBe(true);
  return ((await response.json()) as { text: string }).text;
}

/** The workbench loaded and online, with the lesson panel closed. */
export async function openWorkbench(page: Page): Promise<void> {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') {
    await page.getByTestId('lesson-toggle').click();
  }
}

/** Opens the CPU properties page of a project from its row's context menu (Shift+F10). */
export async function openCpuProperties(page: Page, projectId: number): Promise<Locator> {
  const node = page.getByTestId(`project-node-${projectId}`);
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
  await node.focus();
  await page.keyboard.press('Shift+F10');
  await page.getByTestId('tree-menu').getByRole('menuitem', { name: 'CPU properties' }).click();
  const props = page.locator('[data-testid="cpu-props"]:not([hidden])');
  await expect(props).toBeVisible({ timeout: 15_000 });
  return props;
}
