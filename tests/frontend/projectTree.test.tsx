import { screen, waitFor, within } from '@testing-library/react';
import { beforeEach, describe, expect, it } from 'vitest';
import { projectContents } from '../../frontend/src/projects/projectContents';
import {
  apiError,
  healthyServer,
  json,
  makeProject,
  mockServer,
  HEALTH,
  renderApp,
  requestsOf,
  serverDown,
} from './helpers';
import { block, projectServer } from './projectServer';

beforeEach(() => projectContents.clear());

function tree() {
  return screen.getByTestId('block-tree');
}

describe('project tree', () => {
  it('is a navigation landmark that shows a loading state, then the projects by name', async () => {
    let release: (value: Response) => void = () => {};
    mockServer({
      'GET /api/health': () => json(HEALTH),
      'GET /api/projects': () =>
        new Promise<Response>((resolve) => {
          release = resolve;
        }),
    });
    renderApp();
    expect(tree().tagName).toBe('NAV');
    expect(screen.getByRole('navigation', { name: 'Projects' })).toBe(tree());
    expect(within(tree()).getByRole('status').textContent).toContain('Loading projects');

    release(json([makeProject(2, 'Tank filling'), makeProject(1, 'Conveyor', 'Line 3 conveyor')]));
    const items = await within(tree()).findAllByRole('treeitem');
    expect(items.map((item) => item.textContent)).toEqual(['Conveyor', 'Tank filling']);
    expect(within(tree()).getByRole('tree', { name: 'Projects' })).toBeTruthy();
    expect(within(tree()).getByRole('treeitem', { name: 'Conveyor' }).getAttribute('aria-expanded')).toBe('false');
  });

  it('shows an empty state when the server has no projects', async () => {
    healthyServer([]);
    renderApp();
    expect(await within(tree()).findByText('No projects yet')).toBeTruthy();
    expect(within(tree()).getByRole('button', { name: 'Create the first project' })).toBeTruthy();
  });

  it('expands a project to show its blocks by kind and its source files', async () => {
    projectServer([
      {
        project: makeProject(1, 'Conveyor'),
        files: new Map([
          ['OB1.awl', { text: 'ORGANIZATION_BLOCK OB 1', version: 1 }],
          ['Scale.scl', { text: 'FUNCTION "Scale" : REAL', version: 1 }],
          ['symbols.sdf', { text: '"Main","OB 1","OB 1",""', version: 1 }],
        ]),
        blocks: [block('OB', 1, 'Main', 'OB1.awl'), block('FC', 10, 'Scale', 'Scale.scl')],
        diagnostics: () => [],
      },
      { project: makeProject(2, 'Mixer'), files: new Map(), blocks: [], diagnostics: () => [] },
    ]);
    const { user } = renderApp();
    const node = await within(tree()).findByRole('treeitem', { name: 'Conveyor' });
    await user.click(within(node).getByText('Conveyor'));
    expect(node.getAttribute('aria-expanded')).toBe('true');
    await within(tree()).findByRole('treeitem', { name: 'OB1 Main' });
    const items = within(tree()).getAllByRole('treeitem');
    expect(items.map((item) => [item.textContent, item.getAttribute('aria-level')])).toEqual([
      ['Conveyor', '1'],
      ['Organization blocks (OB)1', '2'],
      ['OB1 MainSTL', '3'],
      ['Functions (FC)1', '2'],
      ['FC10 ScaleSCL', '3'],
      ['Sources3', '2'],
      ['OB1.awl', '3'],
      ['Scale.scl', '3'],
      ['symbols.sdf', '3'],
      ['Mixer', '1'],
    ]);
    // The counts are for the eye: the folder's name is its own text.
    expect(within(tree()).getByRole('treeitem', { name: 'Sources' }).getAttribute('aria-expanded')).toBe('true');
    expect(within(tree()).getByRole('treeitem', { name: 'OB1.awl' }).getAttribute('aria-posinset')).toBe('1');
    expect(within(tree()).getByRole('treeitem', { name: 'OB1.awl' }).getAttribute('aria-setsize')).toBe('3');

    await user.click(within(node).getByText('Conveyor'));
    expect(node.getAttribute('aria-expanded')).toBe('false');
    expect(within(tree()).getAllByRole('treeitem')).toHaveLength(2);
  });

  it('moves through the tree with the arrow keys', async () => {
    projectServer([
      {
        project: makeProject(1, 'Alpha'),
        files: new Map([['OB1.awl', { text: '', version: 1 }]]),
        blocks: [],
        diagnostics: () => [],
      },
      { project: makeProject(2, 'Beta'), files: new Map(), blocks: [], diagnostics: () => [] },
    ]);
    const { user } = renderApp();
    const alpha = await within(tree()).findByRole('treeitem', { name: 'Alpha' });
    const beta = within(tree()).getByRole('treeitem', { name: 'Beta' });
    // One tab stop for the whole tree.
    expect(alpha.tabIndex).toBe(0);
    expect(beta.tabIndex).toBe(-1);

    alpha.focus();
    await user.keyboard('{ArrowDown}');
    expect(document.activeElement).toBe(beta);
    await user.keyboard('{ArrowUp}');
    expect(document.activeElement).toBe(alpha);
    await user.keyboard('{ArrowRight}');
    expect(alpha.getAttribute('aria-expanded')).toBe('true');
    const sources = await within(tree()).findByRole('treeitem', { name: 'Sources' });
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(sources);
    await user.keyboard('{ArrowLeft}');
    expect(sources.getAttribute('aria-expanded')).toBe('false');
    await user.keyboard('{ArrowLeft}');
    expect(document.activeElement).toBe(alpha);
    await user.keyboard('{ArrowLeft}');
    expect(alpha.getAttribute('aria-expanded')).toBe('false');
    await user.keyboard('{End}');
    expect(document.activeElement).toBe(beta);
    expect(beta.tabIndex).toBe(0);
  });

  it('creates a project: posts the name and description as JSON and shows the new project', async () => {
    const created = makeProject(7, 'Bottle line', 'Filling and capping');
    const fetchMock = healthyServer([makeProject(1, 'Conveyor')], {
      'POST /api/projects': () => json(created, 201),
    });
    const { user } = renderApp();
    await within(tree()).findByRole('treeitem', { name: 'Conveyor' });

    await user.click(screen.getByTestId('project-new'));
    const dialog = screen.getByRole('dialog', { name: 'New project' });
    expect(document.activeElement).toBe(screen.getByTestId('project-name-input'));
    await user.type(within(dialog).getByLabelText('Project name'), '  Bottle line ');
    await user.type(within(dialog).getByLabelText(/Description/), 'Filling and capping');
    await user.click(screen.getByTestId('project-create-submit'));

    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    const post = fetchMock.mock.calls.find(([, init]) => init?.method === 'POST');
    expect(post).toBeDefined();
    const [url, init] = post!;
    expect(url).toBe('/api/projects');
    expect(JSON.parse(String(init?.body))).toEqual({ name: 'Bottle line', description: 'Filling and capping' });
    expect(new Headers(init?.headers).get('Content-Type')).toBe('application/json');

    const node = within(tree()).getByRole('treeitem', { name: 'Bottle line' });
    expect(node.getAttribute('aria-selected')).toBe('true');
    expect(node.getAttribute('aria-expanded')).toBe('true');
    const names = within(tree())
      .getAllByRole('treeitem')
      .filter((item) => item.getAttribute('aria-level') === '1')
      .map((item) => item.textContent);
    expect(names).toEqual(['Bottle line', 'Conveyor']);
  });

  it('shows a 409 error with its code and message beside the name field', async () => {
    healthyServer([makeProject(1, 'Conveyor')], {
      'POST /api/projects': () =>
        apiError(409, 'API409', 'project_name_taken', "A project named 'Conveyor' already exists.", { name: 'Conveyor' }, [
          'body',
          'name',
        ]),
    });
    const { user } = renderApp();
    await within(tree()).findByRole('treeitem', { name: 'Conveyor' });
    await user.click(screen.getByTestId('project-new'));
    await user.type(screen.getByTestId('project-name-input'), 'Conveyor');
    await user.click(screen.getByTestId('project-create-submit'));

    const error = await screen.findByTestId('project-name-error');
    expect(error.textContent).toContain('API409');
    expect(error.textContent).toContain('A project named “Conveyor” already exists.');
    const input = screen.getByTestId('project-name-input');
    expect(input.getAttribute('aria-invalid')).toBe('true');
    expect(input.getAttribute('aria-describedby')).toContain(error.id);
    // The dialog stays open and the list is unchanged.
    expect(screen.getByRole('dialog')).toBeTruthy();
    expect(within(tree()).getAllByRole('treeitem')).toHaveLength(1);
  });

  it('translates a known error key and shows the server message for an unknown one', async () => {
    let answer = apiError(409, 'API409', 'project_name_taken', "A project named 'Tank' already exists.", {
      name: 'Tank',
    });
    healthyServer([], { 'POST /api/projects': () => answer });
    const { user } = renderApp('fa');
    await user.click(await screen.findByTestId('project-new'));
    await user.type(screen.getByTestId('project-name-input'), 'Tank');
    await user.click(screen.getByTestId('project-create-submit'));
    const error = await screen.findByTestId('project-name-error');
    expect(error.textContent).toContain('API409');
    expect(error.textContent).toContain('پروژه\u200cای با نام «Tank» از قبل وجود دارد.');

    answer = apiError(422, 'API422', 'some_future_rule', 'name: the server says no', {}, ['body', 'name']);
    await user.click(screen.getByTestId('project-create-submit'));
    await waitFor(() => expect(screen.getByTestId('project-name-error').textContent).toContain('API422'));
    expect(screen.getByTestId('project-name-error').textContent).toContain('name: the server says no');
  });

  it('refuses an empty name without asking the server', async () => {
    const fetchMock = healthyServer([]);
    const { user } = renderApp();
    await user.click(await screen.findByTestId('project-new'));
    await user.type(screen.getByTestId('project-name-input'), '   ');
    await user.click(screen.getByTestId('project-create-submit'));
    expect(screen.getByTestId('project-name-error').textContent).toContain('Enter a name for the project.');
    expect(requestsOf(fetchMock)).not.toContain('POST /api/projects');
  });

  it('closes the dialog with Escape and Cancel', async () => {
    healthyServer([]);
    const { user } = renderApp();
    await user.click(await screen.findByTestId('project-new'));
    await user.keyboard('{Escape}');
    expect(screen.queryByRole('dialog')).toBeNull();
    expect(document.activeElement).toBe(screen.getByTestId('project-new'));
    await user.click(screen.getByTestId('project-new'));
    await user.click(screen.getByRole('button', { name: 'Cancel' }));
    expect(screen.queryByRole('dialog')).toBeNull();
  });

  it('shows a clear error state when the server cannot be reached, and retries', async () => {
    const down = serverDown();
    const { user } = renderApp();
    const alert = await within(tree()).findByRole('alert');
    expect(alert.textContent).toContain('Server not reachable');
    expect(alert.textContent).toContain('The Nasaq server does not answer.');
    expect(requestsOf(down)).toContain('GET /api/projects');

    healthyServer([makeProject(3, 'Traffic light')]);
    await user.click(within(alert).getByRole('button', { name: 'Try again' }));
    expect(await within(tree()).findByRole('treeitem', { name: 'Traffic light' })).toBeTruthy();
    expect(within(tree()).queryByRole('alert')).toBeNull();
  });

  it('shows the code and message of a server error while listing', async () => {
    mockServer({
      'GET /api/health': () => json(HEALTH),
      'GET /api/projects': () =>
        apiError(500, 'API500', 'internal_error', 'The server failed to handle this request.'),
    });
    renderApp();
    const alert = await within(tree()).findByRole('alert');
    expect(alert.textContent).toContain('Projects could not be loaded');
    expect(alert.textContent).toContain('API500');
    expect(alert.textContent).toContain('the details are in the server log');
  });

  it('reports a failed create that did not reach the server below the form', async () => {
    healthyServer([], {
      'POST /api/projects': () => {
        throw new TypeError('Failed to fetch');
      },
    });
    const { user } = renderApp();
    await user.click(await screen.findByTestId('project-new'));
    await user.type(screen.getByTestId('project-name-input'), 'Mixer');
    await user.click(screen.getByTestId('project-create-submit'));
    const error = await screen.findByTestId('project-form-error');
    expect(error.textContent).toContain('The Nasaq server cannot be reached.');
    expect((screen.getByTestId('project-create-submit') as HTMLButtonElement).disabled).toBe(false);
  });
});
