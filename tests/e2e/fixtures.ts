/**
 * A page fixture that records what a user would never want to see: console errors, uncaught
 * exceptions, failed requests, and any request that leaves the local server.
 */
import { test as base, expect, type Locator, type Page } from '@playwright/test';

export interface PageWatch {
  consoleErrors: string[];
  foreignRequests: string[];
  failedRequests: string[];
}

export const test = base.extend<{ watch: PageWatch }>({
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
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  return editor;
}
