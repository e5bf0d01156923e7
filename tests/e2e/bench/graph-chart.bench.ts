/**
 * Does the S7-Graph chart stay responsive with a large sequencer? A 200-step sequencer (branches,
 * joins, a jump; `graphSources.ts`) is made through the API with an OB 1 that calls it, downloaded
 * and RUN, opened in the chart (laid out by elkjs in the diagram layer's worker), then monitored
 * while its active step moves on at every call and the chart is scrolled from top to bottom and
 * back. A `longtask` PerformanceObserver records every main-thread task over 50 ms.
 *
 * Targets (the S7-Graph editor issue): opened and drawn < 1 s from the double click, longest task
 * while monitoring < 100 ms.
 */
import type { APIRequestContext, Page } from '@playwright/test';
import { test, expect } from '../fixtures';
import { observeLongTasks, takeLongTasks } from './benchPage';
import { CHART_OB1, graphChain } from './graphSources';

const STEPS = 200;
const TASK_LIMIT_MS = 100;
const DRAWN_LIMIT_MS = 1000;
const PROJECT = 'Chart bench';

async function makeProject(request: APIRequestContext): Promise<number> {
  const created = await request.post('/api/projects', { data: { name: PROJECT, description: 'make bench' } });
  expect(created.status(), await created.text()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const [name, text] of [
    ['Chain.graph', graphChain(STEPS)],
    ['Main.awl', CHART_OB1],
  ] as const) {
    const saved = await request.put(`/api/projects/${id}/files/${name}`, { data: { text } });
    expect(saved.ok(), await saved.text()).toBe(true);
  }
  const build = (await (await request.get(`/api/projects/${id}/blocks`)).json()) as { diagnostics: Array<{ severity: string; code: string; message: string }> };
  expect(build.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  return id;
}

/** At 1440×900: the project expanded, downloaded and in RUN. */
async function downloadAndRun(page: Page): Promise<void> {
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const node = page.getByTestId('block-tree').getByRole('treeitem', { name: PROJECT, exact: true });
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
  // A download of a 200-step FB takes a while on a busy machine, and RUN is enabled once the CPU
  // holds the program; a press that came too early is tried again until the CPU runs.
  const download = page.getByTestId('cpu-download');
  const run = page.getByTestId('cpu-run');
  await expect(async () => {
    if ((await run.isDisabled()) && (await download.getAttribute('aria-busy')) !== 'true') await download.click();
    await expect(run).toBeEnabled({ timeout: 30_000 });
    await run.click({ timeout: 5_000 });
    await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run', { timeout: 5_000 });
  }).toPass({ timeout: 180_000 });
}

/** Scrolls the chart a page per two frames, down then up; false if it ran out of time. */
function scrollThrough(page: Page): Promise<{ complete: boolean; steps: number }> {
  return page.evaluate(async () => {
    const chart = document.querySelector<HTMLElement>('.source-view:not([hidden]) [data-testid="graph-chart"]')!;
    const frame = () => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    const deadline = performance.now() + 120_000;
    let steps = 0;
    for (const direction of [1, -1]) {
      for (;;) {
        if (performance.now() > deadline) return { complete: false, steps };
        const max = chart.scrollHeight - chart.clientHeight;
        const top = chart.scrollTop;
        if ((direction > 0 && top >= max - 1) || (direction < 0 && top <= 0)) break;
        chart.scrollTop = Math.max(0, Math.min(max, top + (direction * chart.clientHeight) / 2));
        steps += 1;
        await frame();
      }
    }
    return { complete: true, steps };
  });
}

test('a 200-step sequencer opens and draws in under 1 s; monitoring it keeps the main thread free', async ({ page, request }) => {
  const projectId = await makeProject(request);
  await observeLongTasks(page);
  await downloadAndRun(page);

  // Opening: from the double click until the last step is drawn, timed in the page (the
  // dblclick event's time stamp to the frame in which the last step is in the DOM), so the
  // figure is the editor's and not the test driver's polling.
  await takeLongTasks(page);
  await page.evaluate((last) => {
    const bench = window as unknown as { chartOpen?: Promise<number> };
    bench.chartOpen = new Promise((resolve) => {
      document.addEventListener(
        'dblclick',
        (event) => {
          const started = event.timeStamp;
          const seen = () => document.querySelector(`.source-view:not([hidden]) [data-testid="graph-step-${last}"]`);
          const observer = new MutationObserver(() => {
            if (!seen()) return;
            observer.disconnect();
            requestAnimationFrame(() => resolve(performance.now() - started));
          });
          observer.observe(document.body, { childList: true, subtree: true });
        },
        { capture: true, once: true },
      );
    });
  }, STEPS);
  await page.getByTestId(`file-node-${projectId}-Chain.graph`).dblclick();
  const view = page.locator('.source-view:not([hidden])');
  await expect(view.getByTestId(`graph-step-${STEPS}`)).toBeAttached({ timeout: 60_000 });
  const drawnMs = Math.round(await page.evaluate(() => (window as unknown as { chartOpen: Promise<number> }).chartOpen));
  await expect(view.getByTestId('graph-step-1')).toHaveAttribute('data-initial', 'true');
  await page.waitForTimeout(1000);
  const openTasks = await takeLongTasks(page);
  const layout = await page.evaluate(() =>
    performance
      .getEntriesByName('nasaq:elk-layout')
      .map((mark) => (mark as PerformanceMark).detail as { ms: number; nodes: number })
      .sort((a, b) => b.nodes - a.nodes)[0],
  );

  console.log(`\n${STEPS}-step sequencer drawn ${drawnMs} ms after the double click (elkjs ${layout ? layout.ms.toFixed(0) : '?'} ms in the worker)`);

  // Monitoring: the active step moves on at every call of the FB.
  const toggle = view.getByTestId('monitor-toggle');
  await toggle.click();
  await expect(view.getByTestId('graph-monitor-mode')).toHaveAttribute('data-mode', 'AUTO', { timeout: 60_000 });
  await expect(view.locator('[data-testid^="graph-step-"][data-state="active"]').first()).toBeAttached({ timeout: 30_000 });
  const first = await view.locator('[data-testid^="graph-step-"][data-state="active"]').first().getAttribute('data-testid');
  await page.waitForTimeout(500);
  await takeLongTasks(page);
  const started = Date.now();
  const scroll = await scrollThrough(page);
  await page.waitForTimeout(3000);
  const monitorTasks = await takeLongTasks(page);
  const seconds = (Date.now() - started) / 1000;
  const later = await view.locator('[data-testid^="graph-step-"][data-state="active"]').first().getAttribute('data-testid');
  await toggle.click();

  const longest = Math.round(Math.max(0, ...monitorTasks));
  console.log(
    `\nS7-Graph chart bench (Chromium ${page.context().browser()?.version() ?? ''}, 1440×900, CPU in RUN)\n` +
      `${STEPS}-step sequencer: drawn ${drawnMs} ms after the double click (elkjs ${layout ? layout.ms.toFixed(0) : '?'} ms in the worker for ${layout?.nodes ?? '?'} nodes); ` +
      `longest task while opening ${Math.round(Math.max(0, ...openTasks))} ms\n` +
      `monitoring, the active step moving at every call, chart scrolled down and up (${scroll.steps} half pages, ${seconds.toFixed(1)} s): ` +
      `longest task ${longest} ms, ${monitorTasks.length} tasks over 50 ms\n` +
      `targets: drawn < ${DRAWN_LIMIT_MS} ms, task < ${TASK_LIMIT_MS} ms\n`,
  );
  expect(scroll.complete, 'scrolled through within the time budget').toBe(true);
  expect(later, 'the active step moved while monitored').not.toBe(first);
  expect(drawnMs, 'the 200-step chart drawn').toBeLessThan(DRAWN_LIMIT_MS);
  expect(longest, 'longest task while monitoring').toBeLessThan(TASK_LIMIT_MS);
});
