/**
 * `make bench`'s browser part: the editor bench (`*.bench.ts`) with the browser, server and
 * fresh database of the end-to-end tests' config. The normal e2e run never picks these files
 * up (its tests are `*.spec.ts`), and `make test` does not run them.
 */
import { defineConfig } from '@playwright/test';
import base from '../playwright.config';

export default defineConfig({
  ...base,
  testDir: __dirname,
  testMatch: '*.bench.ts',
  // Generating, opening and scrolling two large sources takes a while on a small machine.
  timeout: 600_000,
  reporter: [['list']],
  // A trace records DOM snapshots as the page changes: it would be measured with the editor.
  use: { ...base.use, trace: 'off' },
});
