/**
 * A lesson with its plant, in each of the four interface languages, as the README shows it: the
 * lesson opened from the course outline, the reference solution put in its project (as after
 * "Give up", written through the files API so the learner's progress is untouched), downloaded
 * and run, the plant's operator panel used, and the machine moving beside the lesson text.
 * Screenshots: docs/screenshots/<lang>-lesson-plant.png.
 */
import type { Locator, Page } from '@playwright/test';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { test, expect, chooseLanguage } from './fixtures';

const root = path.resolve(__dirname, '../..');
const lessons = path.join(root, 'examples', 'lessons');

interface Case {
  language: 'en' | 'ar' | 'fa' | 'vi';
  lesson: string;
  kind: string;
  /** What the learner does on the operator panel, and what the drawing then shows. */
  operate: (plant: Locator, page: Page) => Promise<void>;
}

/** Holds a momentary push button for a moment, as a finger does. */
async function press(page: Page, button: Locator): Promise<void> {
  await button.hover();
  await page.mouse.down();
  await page.waitForTimeout(300);
  await page.mouse.up();
}

const CASES: Case[] = [
  {
    language: 'en',
    lesson: 'vi4-30',
    kind: 'tank',
    operate: async (plant, page) => {
      await press(page, plant.getByTestId('plant-control-pump_pb'));
      await expect(plant.getByTestId('plant-pump')).toHaveAttribute('data-running', '1', { timeout: 10_000 });
    },
  },
  {
    language: 'ar',
    lesson: 'ar0-06',
    kind: 'motor',
    operate: async (plant, page) => {
      await press(page, plant.getByTestId('plant-control-start'));
      await expect(plant.getByTestId('plant-contactor')).toHaveAttribute('data-on', '1', { timeout: 10_000 });
    },
  },
  {
    language: 'fa',
    lesson: 'fa2-01',
    kind: 'bcd_panel',
    operate: async (plant) => {
      // The thumbwheels: sign digit 0, then 1, 2, 3 -> +123 in BCD on IW0.
      const wheels = plant.getByTestId(/^plant-wheel-input-/);
      const count = await wheels.count();
      const digits = ['0', '1', '2', '3'].slice(-count);
      for (let k = 0; k < count; k += 1) await wheels.nth(k).fill(digits[k]!);
      await expect(plant.getByTestId('plant-drawing-bcd_panel')).toBeVisible();
    },
  },
  {
    language: 'vi',
    lesson: 'vi4-26',
    kind: 'traffic_light',
    operate: async (plant) => {
      await plant.getByTestId('plant-control-run').click();
      await expect(plant.locator('[data-testid^="plant-lamp-"][data-on="1"]').first()).toBeVisible({ timeout: 10_000 });
    },
  },
];

function unitOf(lesson: string): string {
  return lesson.split('-')[0]!;
}

for (const item of CASES) {
  test(`${item.language}: lesson ${item.lesson} with its ${item.kind} plant running`, async ({ page, request, watch }) => {
    test.setTimeout(150_000);
    await page.setViewportSize({ width: 1440, height: 900 });
    await page.goto('/');
    await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
    if (item.language !== 'en') await chooseLanguage(page, item.language);

    // Open the lesson from the course outline, then give its project the reference solution.
    const pane = page.getByTestId('lesson-pane');
    const unit = pane.getByTestId(`course-unit-${unitOf(item.lesson)}`);
    if ((await unit.getAttribute('open')) === null) await unit.locator('summary').first().click();
    await pane.getByTestId(`lesson-open-${item.lesson}`).click({ timeout: 30_000 });
    await expect(pane.getByTestId('lesson-view')).toHaveAttribute('data-lesson', item.lesson);
    const opened = await request.post(`/api/lessons/${item.lesson}/open`, { data: { reset: false } });
    expect(opened.ok()).toBe(true);
    const { project_id: projectId } = (await opened.json()) as { project_id: number };
    const solution = path.join(lessons, unitOf(item.lesson), item.lesson, 'solution');
    for (const name of readdirSync(solution)) {
      const text = readFileSync(path.join(solution, name), 'utf8');
      expect((await request.put(`/api/projects/${projectId}/files/${name}`, { data: { text } })).ok()).toBe(true);
    }
    await page.reload();
    await expect(pane.getByTestId('lesson-view')).toHaveAttribute('data-lesson', item.lesson, { timeout: 30_000 });
    await expect(pane.getByTestId('lesson-text')).toHaveAttribute('lang', item.language);

    // Download and run: the lesson's plant comes alive beside the text.
    const plant = pane.getByTestId('lesson-plant');
    await expect(plant).toHaveAttribute('data-kind', item.kind);
    await expect(plant.getByTestId(`plant-drawing-${item.kind}`)).toBeVisible({ timeout: 20_000 });
    await page.keyboard.press('Control+B');
    await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 30_000 });
    await page.getByTestId('cpu-run').click();
    await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
    await expect(plant.getByTestId('plant-panel')).toHaveAttribute('data-live', '1', { timeout: 15_000 });
    await plant.scrollIntoViewIfNeeded();
    await item.operate(plant, page);
    // Arabic and Persian pages mirror; the drawing keeps its left-to-right layout.
    await expect(plant.locator('figure.plant-drawing')).toHaveAttribute('dir', 'ltr');
    await page.waitForTimeout(1500); // let the machine move a little for the picture
    await plant.scrollIntoViewIfNeeded();
    await page.evaluate(() => document.fonts.ready);
    await page.screenshot({ path: path.join(root, 'docs', 'screenshots', `${item.language}-lesson-plant.png`), animations: 'disabled' });
    expect(watch.consoleErrors).toEqual([]);
    expect(watch.foreignRequests).toEqual([]);
  });
}
