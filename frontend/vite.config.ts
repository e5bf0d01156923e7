import react from '@vitejs/plugin-react';
import { defineConfig } from 'vitest/config';

// The API server (backend/, FastAPI) listens on 127.0.0.1:8000 during development;
// in production it serves the built files of dist/ itself, so every URL stays relative.
const apiServer = 'http://127.0.0.1:8000';

export default defineConfig({
  plugins: [react()],
  server: {
    proxy: {
      // The monitoring sockets live under /api/sessions/{id}/ws.
      '/api': { target: apiServer, ws: true, changeOrigin: false },
      '/ws': { target: apiServer, ws: true, changeOrigin: false },
    },
  },
  build: {
    outDir: 'dist',
    emptyOutDir: true,
    // Fonts stay separate files so the browser fetches only the scripts a language needs.
    assetsInlineLimit: 0,
  },
  test: {
    // The suites live outside the package, in the repository's tests/ tree.
    dir: '../tests/frontend',
    include: ['**/*.test.{ts,tsx}'],
    environment: 'jsdom',
    setupFiles: ['../tests/frontend/setup.ts'],
    restoreMocks: true,
  },
});
