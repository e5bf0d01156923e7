import { cleanup } from '@testing-library/react';
import { afterEach, vi } from 'vitest';

// Each test starts from a blank page: no rendered tree, no remembered choices, no stubs.
afterEach(() => {
  cleanup();
  window.localStorage.clear();
  window.sessionStorage.clear();
  document.documentElement.removeAttribute('dir');
  document.documentElement.removeAttribute('lang');
  document.title = '';
  vi.unstubAllGlobals();
});
