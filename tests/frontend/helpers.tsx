import { render, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { vi, type Mock } from 'vitest';
import type { Health, Project } from '../../frontend/src/api/types';
import { App } from '../../frontend/src/app/App';
import { createI18n } from '../../frontend/src/i18n/setup';
import type { Language } from '../../frontend/src/i18n/languages';

export const HEALTH: Health = { status: 'ok', version: '0.1.0', database: 'ok' };

export function json(body: unknown, status = 200): Response {
  return new Response(JSON.stringify(body), { status, headers: { 'Content-Type': 'application/json' } });
}

export function apiError(
  status: number,
  code: string,
  key: string,
  message: string,
  params: Record<string, unknown> = {},
  location: Array<string | number> | null = null,
): Response {
  return json({ error: { code, key, message, params, location } }, status);
}

export function makeProject(id: number, name: string, description = ''): Project {
  const stamp = `2025-01-0${Math.min(id, 9)}T10:00:00Z`;
  return { id, name, description, created_at: stamp, updated_at: stamp };
}

type Handler = (init: RequestInit | undefined) => Response | Promise<Response>;

/**
 * Replaces `fetch` with a small fake server: `"METHOD /path"` → handler.
 * Unknown routes answer 404 in the API's error shape.
 */
export function mockServer(routes: Record<string, Handler>): Mock<typeof fetch> {
  const fetchMock = vi.fn<typeof fetch>(async (input, init) => {
    const url = typeof input === 'string' ? input : input instanceof URL ? input.pathname : input.url;
    const method = (init?.method ?? 'GET').toUpperCase();
    const handler = routes[`${method} ${url}`];
    if (!handler) return apiError(404, 'API101', 'route_not_found', `No API route at ${url}.`, { path: url });
    return handler(init);
  });
  vi.stubGlobal('fetch', fetchMock);
  return fetchMock;
}

/** A server with the given projects and a healthy database. */
export function healthyServer(projects: Project[] = [], extra: Record<string, Handler> = {}) {
  return mockServer({
    'GET /api/health': () => json(HEALTH),
    'GET /api/projects': () => json(projects),
    ...extra,
  });
}

/** `fetch` that fails as when the server is down. */
export function serverDown(): Mock<typeof fetch> {
  const fetchMock = vi.fn<typeof fetch>(async () => {
    throw new TypeError('Failed to fetch');
  });
  vi.stubGlobal('fetch', fetchMock);
  return fetchMock;
}

/** Renders the whole application with its own i18n instance. */
export function renderApp(language?: Language) {
  const user = userEvent.setup();
  const i18n = createI18n(language);
  const view = render(<App i18n={i18n} />);
  return { user, i18n, ...view };
}

/** The requests the fake server received, as "METHOD /path". */
export function requestsOf(fetchMock: Mock<typeof fetch>): string[] {
  return fetchMock.mock.calls.map(([input, init]) => {
    const url = typeof input === 'string' ? input : input instanceof URL ? input.pathname : input.url;
    return `${(init?.method ?? 'GET').toUpperCase()} ${url}`;
  });
}

export async function waitForServer(): Promise<void> {
  await waitFor(() => {
    const status = document.querySelector('[data-testid="server-status"]');
    if (!status || status.getAttribute('data-state') === 'checking') throw new Error('still checking');
  });
}
