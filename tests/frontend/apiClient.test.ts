import { describe, expect, it, vi } from 'vitest';
import { ApiError, createProject, getHealth, listProjects } from '../../frontend/src/api/client';
import { HEALTH, apiError, json, makeProject } from './helpers';

function stubFetch(answer: () => Response | Promise<Response>) {
  const fetchMock = vi.fn<typeof fetch>(async () => answer());
  vi.stubGlobal('fetch', fetchMock);
  return fetchMock;
}

async function failure(promise: Promise<unknown>): Promise<ApiError> {
  try {
    await promise;
  } catch (error) {
    expect(error).toBeInstanceOf(ApiError);
    return error as ApiError;
  }
  throw new Error('the call did not fail');
}

describe('API client', () => {
  it('reads health and projects from relative /api URLs', async () => {
    const fetchMock = stubFetch(() => json(HEALTH));
    expect(await getHealth()).toEqual(HEALTH);
    expect(fetchMock.mock.calls[0]![0]).toBe('/api/health');

    const projects = [makeProject(1, 'Conveyor')];
    stubFetch(() => json(projects));
    expect(await listProjects()).toEqual(projects);
  });

  it('posts a new project as JSON', async () => {
    const fetchMock = stubFetch(() => json(makeProject(4, 'Mixer', 'Batch mixer'), 201));
    const project = await createProject({ name: 'Mixer', description: 'Batch mixer' });
    expect(project.id).toBe(4);
    const [url, init] = fetchMock.mock.calls[0]!;
    expect(url).toBe('/api/projects');
    expect(init?.method).toBe('POST');
    expect(JSON.parse(String(init?.body))).toEqual({ name: 'Mixer', description: 'Batch mixer' });
    const headers = new Headers(init?.headers);
    expect(headers.get('Content-Type')).toBe('application/json');
    expect(headers.get('Accept')).toBe('application/json');
  });

  it('turns the server error object into a typed ApiError', async () => {
    stubFetch(() =>
      apiError(409, 'API409', 'project_name_taken', "A project named 'Mixer' already exists.", { name: 'Mixer' }, [
        'body',
        'name',
      ]),
    );
    const error = await failure(createProject({ name: 'Mixer', description: '' }));
    expect(error.code).toBe('API409');
    expect(error.key).toBe('project_name_taken');
    expect(error.message).toBe("A project named 'Mixer' already exists.");
    expect(error.params).toEqual({ name: 'Mixer' });
    expect(error.location).toEqual(['body', 'name']);
    expect(error.status).toBe(409);
    expect(error.unreachable).toBe(false);
  });

  it('reports a network failure as "server unreachable"', async () => {
    vi.stubGlobal(
      'fetch',
      vi.fn(async () => {
        throw new TypeError('Failed to fetch');
      }),
    );
    const error = await failure(listProjects());
    expect(error.unreachable).toBe(true);
    expect(error.status).toBe(0);
    expect(error.key).toBe('server_unreachable');
  });

  it('treats a bare 502 from a proxy as "server unreachable"', async () => {
    stubFetch(() => new Response('Bad Gateway', { status: 502 }));
    const error = await failure(getHealth());
    expect(error.unreachable).toBe(true);
    expect(error.status).toBe(502);
  });

  it('describes an error answer without the API error shape', async () => {
    stubFetch(() => new Response('<html>oops</html>', { status: 500 }));
    const error = await failure(listProjects());
    expect(error.key).toBe('unexpected_response');
    expect(error.params).toEqual({ status: 500 });
    expect(error.unreachable).toBe(false);
  });

  it('rejects a success answer that is not JSON', async () => {
    stubFetch(() => new Response('not json', { status: 200 }));
    const error = await failure(listProjects());
    expect(error.key).toBe('unexpected_response');
  });
});
