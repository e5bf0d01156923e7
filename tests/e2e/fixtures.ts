/**
 * A page fixture that records what a user would never want to see: console errors, uncaught
 * exceptions, failed requests, and any request that leaves the local server.
 */
import { test as base, expect, type Page } from '@playwright/test';

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
