/**
 * A fake Nasaq server with projects of source files, for the tests of the project tree and the
 * file tabs: the routes of `/api/projects/{id}/files`, `/blocks` and `/check`, kept in memory.
 */
import type { Mock } from 'vitest';
import type { Diagnostic, FileInfo, FileOut, Project, ProjectBuild, TreeBlock } from '../../frontend/src/api/types';
import { HEALTH, apiError, json } from './helpers';
import { vi } from 'vitest';

export interface FakeFile {
  text: string;
  version: number;
}

export interface FakeProject {
  project: Project;
  files: Map<string, FakeFile>;
  blocks: TreeBlock[];
  /** What `/blocks` and `/check` answer (the text checked is in `checks`). */
  diagnostics: (name: string | null, text: string | null) => Diagnostic[];
}

export function fileInfo(name: string, file: FakeFile): FileInfo {
  const language = name.endsWith('.scl') ? 'scl' : /\.(awl|stl)$/.test(name) ? 'stl' : 'symbols';
  return {
    name,
    language,
    size: file.text.length,
    version: file.version,
    created_at: '2025-01-01T10:00:00Z',
    updated_at: '2025-01-01T10:00:00Z',
  };
}

export function block(kind: TreeBlock['kind'], number: number, name: string, file: string, line: number | null = 1): TreeBlock {
  return { kind, number, name, title: '', language: file.endsWith('.scl') ? 'scl' : 'stl', file, line, instance_of: null };
}

export interface FakeServer {
  fetch: Mock<typeof fetch>;
  projects: FakeProject[];
  /** Bodies of PUT requests, by file name. */
  saves: Array<{ name: string; text: string; base_version: number | null }>;
  checks: Array<{ name: string; text: string }>;
  /** Makes the next PUTs answer with this (once each), e.g. a 409. */
  putAnswers: Array<() => Response>;
  requests: () => string[];
}

function decode(part: string): string {
  return decodeURIComponent(part);
}

/** A fake server holding `projects`; any other route answers 404 in the API's error shape. */
export function projectServer(projects: FakeProject[]): FakeServer {
  const server: FakeServer = {
    fetch: null as unknown as Mock<typeof fetch>,
    projects,
    saves: [],
    checks: [],
    putAnswers: [],
    requests: () =>
      server.fetch.mock.calls.map(([input, init]) => `${(init?.method ?? 'GET').toUpperCase()} ${String(input)}`),
  };
  const find = (id: string) => projects.find((p) => p.project.id === Number(id));
  const build = (p: FakeProject, name: string | null, text: string | null): ProjectBuild => ({
    blocks: p.blocks,
    diagnostics: p.diagnostics(name, text),
  });
  server.fetch = vi.fn<typeof fetch>(async (input, init) => {
    const url = String(input);
    const method = (init?.method ?? 'GET').toUpperCase();
    const body = typeof init?.body === 'string' ? (JSON.parse(init.body) as Record<string, unknown>) : null;
    if (url === '/api/health') return json(HEALTH);
    if (url === '/api/projects' && method === 'GET') return json(projects.map((p) => p.project));
    let match = /^\/api\/projects\/(\d+)\/files$/.exec(url);
    if (match && method === 'GET') {
      const p = find(match[1]!);
      if (!p) return apiError(404, 'API104', 'project_not_found', 'No project');
      return json([...p.files].map(([name, file]) => fileInfo(name, file)));
    }
    match = /^\/api\/projects\/(\d+)\/blocks$/.exec(url);
    if (match) {
      const p = find(match[1]!);
      return p ? json(build(p, null, null)) : apiError(404, 'API104', 'project_not_found', 'No project');
    }
    match = /^\/api\/projects\/(\d+)\/check$/.exec(url);
    if (match) {
      const p = find(match[1]!)!;
      const unsaved = body as { name: string; text: string };
      server.checks.push(unsaved);
      return json(build(p, unsaved.name, unsaved.text));
    }
    match = /^\/api\/projects\/(\d+)\/files\/([^/]+)(\/duplicate)?$/.exec(url);
    if (match) {
      const p = find(match[1]!)!;
      const name = decode(match[2]!);
      const file = p.files.get(name);
      if (match[3]) {
        const copy = { text: file!.text, version: 1 };
        const to = String(body?.name);
        p.files.set(to, copy);
        return json(fileInfo(to, copy), 201);
      }
      if (method === 'GET') {
        if (!file) return apiError(404, 'API107', 'file_not_found', `Project has no file '${name}'.`, { name });
        const out: FileOut = { ...fileInfo(name, file), text: file.text };
        return json(out);
      }
      if (method === 'PUT') {
        const save = body as { text: string; base_version: number | null };
        server.saves.push({ name, ...save });
        const answer = server.putAnswers.shift();
        if (answer) return answer();
        if (save.base_version != null && file && file.version !== save.base_version) {
          return apiError(
            409,
            'API111',
            'file_changed',
            `'${name}' was changed elsewhere after this copy was loaded.`,
            { name, current_version: file.version },
            ['body', 'base_version'],
          );
        }
        const saved = { text: save.text, version: (file?.version ?? 0) + 1 };
        p.files.set(name, saved);
        return json(fileInfo(name, saved), file ? 200 : 201);
      }
      if (method === 'PATCH') {
        const to = String(body?.name);
        const renamed = { ...file!, version: file!.version + 1 };
        p.files.delete(name);
        p.files.set(to, renamed);
        p.blocks = p.blocks.map((b) => (b.file === name ? { ...b, file: to } : b));
        return json(fileInfo(to, renamed));
      }
      if (method === 'DELETE') {
        p.files.delete(name);
        p.blocks = p.blocks.filter((b) => b.file !== name);
        return new Response(null, { status: 204 });
      }
    }
    match = /^\/api\/projects\/(\d+)$/.exec(url);
    if (match && method === 'DELETE') {
      const index = projects.findIndex((p) => p.project.id === Number(match![1]));
      projects.splice(index, 1);
      return new Response(null, { status: 204 });
    }
    if (url.startsWith('/api/projects/import') && method === 'POST') {
      const created: Project = {
        id: 99,
        name: new URL(url, 'http://x').searchParams.get('name') ?? 'imported',
        description: '',
        created_at: '2025-01-01T10:00:00Z',
        updated_at: '2025-01-01T10:00:00Z',
      };
      projects.push({ project: created, files: new Map(), blocks: [], diagnostics: () => [] });
      return json({ project: created, files: ['OB1.awl'], skipped: [] }, 201);
    }
    return apiError(404, 'API101', 'route_not_found', `No API route at ${url}.`, { path: url });
  });
  vi.stubGlobal('fetch', server.fetch);
  return server;
}
