/** axe-core (bundled, run inside the page) finds no WCAG A/AA violation in any UI language. */
import AxeBuilder from '@axe-core/playwright';
import { test, expect, chooseLanguage, newStartSource } from './fixtures';

for (const code of ['en', 'fa', 'ar', 'vi'] as const) {
  test(`no accessibility violations in ${code}`, async ({ page }) => {
    await page.goto('/');
    await chooseLanguage(page, code);
    await expect(page.getByTestId('lesson-pane')).toBeVisible();
    await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
    const results = await new AxeBuilder({ page }).withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']).analyze();
    const summary = results.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    expect(summary).toEqual([]);
  });
}

for (const code of ['en', 'fa', 'ar', 'vi'] as const) {
  test(`no accessibility violations with an STL source open in ${code}`, async ({ page }) => {
    await page.goto('/');
    await chooseLanguage(page, code);
    const editor = await newStartSource(page, 'stl');
    // With the caret in the text and the word suggestions open.
    await editor.locator('.view-lines').click();
    await page.keyboard.type('A');
    const results = await new AxeBuilder({ page }).withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']).analyze();
    const summary = results.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    expect(summary).toEqual([]);
  });
}
