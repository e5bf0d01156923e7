/**
 * Does the page stay responsive with large sources? A project with an STL function of 500
 * networks (called from OB1) and a 5,000-line SCL source is made through the API, downloaded
 * and RUN; each source is opened in the editor and scrolled from top to bottom and back, a page
 * per frame, first without and then with monitoring on. A `longtask` PerformanceObserver
 * records every main-thread task over 50 ms; the bench fails when one task while scrolling
 * (with or without monitoring) takes 100 ms or more.
 */
import type { APIRequestContext, Page } from '@playwright/test';
import { test, expect } from '../fixtures';
import { observeLongTasks, openDownloadAndRun, takeLongTasks } from './benchPage';
import { OB1, sclSource, stlBlock } from './sources';

type Monaco = typeof import('monaco-editor/editor/editor.api');
type Bench = Window & { monaco: Monaco };

/** The target of the issue: no task of the page may block it this long. */
const LIMIT_MS = 100;
const PROJECT = 'Editor bench';
const FILES: ReadonlyArray<{ name: string; text: string; label: string }> = [
  { name: 'OB1.awl', text: OB1, label: '' },
  { name: 'Machine.awl', text: stlBlock(500), label: 'STL FC, 500 networks' },
  { name: 'Functions.scl', text: sclSource(5000), label: 'SCL, 5,000 lines' },
];

interface Row {
  source: string;
  lines: number;
  openMs: number;
  openLongestMs: number;
  plain: Pass;
  monitored: Pass | null;
}

async function makeProject(request: APIRequestContext): Promise<number> {
  const created = await request.post('/api/projects', { data: { name: PROJECT, description: 'make bench' } });
  expect(created.status(), await created.text()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const file of FILES) {
    const saved = await request.put(`/api/projects/${id}/files/${encodeURIComponent(file.name)}`, { data: { text: file.text } });
    expect(saved.ok(), await saved.text()).toBe(true);
  }
  // The sources are meant to compile cleanly: a bench of a broken program measures nothing.
  const build = (await (await request.get(`/api/projects/${id}/blocks`)).json()) as {
    diagnostics: Array<{ severity: string; code: string; message: string }>;
  };
  expect(build.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  return id;
}

/** How long one scroll pass may take before the bench gives up on it (and says so). */
const SCROLL_BUDGET_MS = 90_000;

/**
 * Scrolls the editor in front from top to bottom and back, a page at a time with two animation
 * frames between steps (so every step is drawn), as fast paging or a flicked wheel would.
 * Monaco's `setScrollTop` rather than wheel events: Chromium hands a synthetic wheel to Monaco
 * as a few lines only, which would take minutes for 5,000 lines. False if the budget ran out.
 */
function scrollThrough(page: Page): Promise<{ complete: boolean; steps: number }> {
  return page.evaluate(async (budgetMs) => {
    const monaco = (window as unknown as Bench).monaco;
    const editor = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null)!;
    const frame = () => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    const deadline = performance.now() + budgetMs;
    const height = editor.getLayoutInfo().height;
    let steps = 0;
    for (const direction of [1, -1]) {
      for (;;) {
        if (performance.now() > deadline) return { complete: false, steps };
        const max = editor.getScrollHeight() - height;
        const top = editor.getScrollTop();
        if ((direction > 0 && top >= max - 1) || (direction < 0 && top <= 0)) break;
        editor.setScrollTop(Math.max(0, Math.min(max, top + direction * height)));
        steps += 1;
        await frame();
      }
    }
    return { complete: true, steps };
  }, SCROLL_BUDGET_MS);
}

interface Pass {
  longestMs: number;
  tasks: number;
  seconds: number;
  steps: number;
  complete: boolean;
}

/** One pass down and up, then a second at the top; the long tasks it caused. */
async function measuredScroll(page: Page): Promise<Pass> {
  await takeLongTasks(page);
  const started = Date.now();
  const { complete, steps } = await scrollThrough(page);
  await page.waitForTimeout(1000);
  const tasks = await takeLongTasks(page);
  return {
    longestMs: Math.round(Math.max(0, ...tasks)),
    tasks: tasks.length,
    seconds: (Date.now() - started) / 1000,
    steps,
    complete,
  };
}

test('large STL and SCL sources open, scroll and monitor without blocking the page', async ({ page, request }) => {
  const projectId = await makeProject(request);
  await observeLongTasks(page);
  // Download and RUN: the CPU scans the 500 networks while the editor is used.
  await openDownloadAndRun(page, PROJECT);

  const rows: Row[] = [];
  for (const file of FILES.filter((f) => f.label)) {
    await takeLongTasks(page);
    const started = Date.now();
    await page.getByTestId(`file-node-${projectId}-${file.name}`).dblclick();
    const editor = page.locator('.source-view:not([hidden]) [data-testid="code-editor"]');
    await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 60_000 });
    await expect(editor.locator('.view-lines')).toBeVisible();
    const openMs = Date.now() - started;
    // Let the first tokenization and the live check settle before they count as "opening".
    await page.waitForTimeout(1500);
    const openTasks = await takeLongTasks(page);

    const plain = await measuredScroll(page);

    // The same with monitoring on (the status of the open block in every frame).
    const toggle = page.locator('.source-view:not([hidden]) [data-testid="monitor-toggle"]');
    let monitored: Pass | null = null;
    if ((await toggle.count()) > 0) {
      if ((await toggle.getAttribute('aria-pressed')) !== 'true') await toggle.click();
      await expect(toggle).toHaveAttribute('aria-pressed', 'true');
      await page.waitForTimeout(1000);
      monitored = await measuredScroll(page);
      await toggle.click();
    }
    rows.push({
      source: file.label,
      lines: file.text.split('\n').length - 1,
      openMs,
      openLongestMs: Math.round(Math.max(0, ...openTasks)),
      plain,
      monitored,
    });
  }

  const pad = (text: string | number, width: number) => String(text).padEnd(width);
  const pass = (p: Pass | null) =>
    p === null
      ? pad('not measured', 34)
      : pad(`${p.longestMs} ms`, 10) + pad(p.tasks, 8) + pad(`${p.seconds.toFixed(1)} s${p.complete ? '' : ' (unfinished)'}`, 16);
  const table = [
    `${pad('', 36)}${pad('longest task while scrolling', 34)}${pad('… scrolling and monitoring', 34)}`,
    `${pad('source', 22)}${pad('lines', 6)}${pad('open', 8)}${pad('longest', 10)}${pad('tasks', 8)}${pad('time', 16)}${pad('longest', 10)}${pad('tasks', 8)}${pad('time', 16)}`,
    ...rows.map(
      (row) =>
        pad(row.source, 22) + pad(row.lines, 6) + pad(`${(row.openMs / 1000).toFixed(1)} s`, 8) + pass(row.plain) + pass(row.monitored),
    ),
  ];
  console.log(
    `\nEditor bench (Chromium ${page.context().browser()?.version() ?? ''}, 1440×900, CPU in RUN; tasks = main-thread tasks over 50 ms)\n` +
      `${table.join('\n')}\n` +
      `longest task while opening: ${rows.map((row) => `${row.source} ${row.openLongestMs} ms`).join(', ')}\n` +
      `target: every task while scrolling and monitoring < ${LIMIT_MS} ms\n`,
  );
  if (rows.some((row) => row.monitored === null)) {
    console.log('NOTE: monitoring was NOT measured: this build has no monitor toggle in the editor.\n');
  }
  for (const row of rows) {
    expect(row.plain.complete, `${row.source}: scrolled through within the time budget`).toBe(true);
    expect(row.plain.longestMs, `${row.source}: longest task while scrolling`).toBeLessThan(LIMIT_MS);
    if (row.monitored) {
      expect(row.monitored.complete, `${row.source}: scrolled through with monitoring within the time budget`).toBe(true);
      expect(row.monitored.longestMs, `${row.source}: longest task while scrolling and monitoring`).toBeLessThan(LIMIT_MS);
    }
  }
});
