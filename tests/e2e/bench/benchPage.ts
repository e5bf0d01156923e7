/**
 * What the browser benches share: every main-thread task over 50 ms recorded by a `longtask`
 * PerformanceObserver from the page's start, and a project opened in the tree, downloaded and RUN.
 */
import type { Page } from '@playwright/test';
import { expect } from '../fixtures';

type Bench = Window & { nasaqLongTasks: number[] };

/** Records every long task of the page from its first script on (call before `goto`). */
export async function observeLongTasks(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const bench = window as unknown as Bench;
    bench.nasaqLongTasks = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) bench.nasaqLongTasks.push(entry.duration);
    }).observe({ type: 'longtask', buffered: true });
  });
}

/** The long tasks recorded so far (ms); the list starts anew. */
export function takeLongTasks(page: Page): Promise<number[]> {
  return page.evaluate(() => {
    const bench = window as unknown as Bench;
    const tasks = bench.nasaqLongTasks;
    bench.nasaqLongTasks = [];
    return tasks;
  });
}

/** At 1440×900: the project expanded in the tree, its program downloaded (Ctrl+B) and in RUN. */
export async function openDownloadAndRun(page: Page, project: string): Promise<void> {
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const node = page.getByTestId('block-tree').getByRole('treeitem', { name: project, exact: true });
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 60_000 });
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
}
