/**
 * Browser tests: Debian's Chromium (/usr/bin/chromium) against a real Nasaq server that this
 * config starts with a fresh SQLite database. Playwright's own browser download is never used.
 */
import { defineConfig } from '@playwright/test';
import path from 'node:path';

const root = path.resolve(__dirname, '../..');
const port = Number(process.env.E2E_PORT ?? 8765);
export const baseURL = `http://127.0.0.1:${port}`;
// Each port gets its own folder, so runs on different ports (E2E_PORT) can go side by side.
const output = path.join(__dirname, '.output', port === 8765 ? '' : String(port));
const dataDir = path.join(output, 'data');
const DOCS = /(screenshots|lesson-plants|lessons|plant-tank|io-panel|watch-tables|xref-rename|graph-monitor)\.spec\.ts$/;

export default defineConfig({
  testDir: '.',
  outputDir: path.join(output, 'results'),
  timeout: 30_000,
  expect: { timeout: 5_000 },
  fullyParallel: false,
  workers: 1,
  forbidOnly: !!process.env.CI,
  retries: 0,
  reporter: [
    ['list'],
    ['junit', { outputFile: process.env.PLAYWRIGHT_JUNIT_OUTPUT_FILE ?? path.join(root, '.reports', 'e2e.xml') }],
  ],
  use: {
    baseURL,
    trace: 'retain-on-failure',
    screenshot: 'only-on-failure',
    launchOptions: {
      executablePath: '/usr/bin/chromium',
      // Without these, Chromium reaches for Google's services at start; the network is closed.
      args: [
        '--no-sandbox',
        '--disable-gpu',
        '--disable-quic',
        '--no-first-run',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
      ],
    },
  },
  // The specs that take the README's screenshots run first, on the fresh database, so the
  // project tree in the pictures holds the example projects and their own, not the hundred
  // projects the other specs leave behind.
  projects: [
    { name: 'screenshots', testMatch: DOCS },
    { name: 'flows', testIgnore: DOCS, dependencies: ['screenshots'] },
  ],
  webServer: {
    command: `rm -rf "${dataDir}" && "${path.join(root, '.venv/bin/nasaq')}" serve --port ${port}`,
    cwd: root,
    env: { NASAQ_DATA_DIR: dataDir, NASAQ_LOG_LEVEL: 'warning' },
    url: `${baseURL}/api/health`,
    reuseExistingServer: false,
    timeout: 60_000,
    stdout: 'pipe',
    stderr: 'pipe',
  },
});
