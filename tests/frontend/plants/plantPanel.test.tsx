/**
 * The Plant panel of the workbench without a running session: a project without a plant offers
 * "Attach a plant…", a project with a `.plant` file shows the plant at rest with its wiring (its
 * panel waits for a session), and a file that cannot be read is reported with its line.
 */
import { render, screen, waitFor } from '@testing-library/react';
import { useEffect, type ReactNode } from 'react';
import { I18nextProvider } from 'react-i18next';
import { afterEach, describe, expect, it } from 'vitest';
import { createI18n } from '../../../frontend/src/i18n/setup';
import { forgetPlantCatalogue } from '../../../frontend/src/plants/api';
import { PlantPanel } from '../../../frontend/src/plants/PlantPanel';
import { ActiveProjectProvider, useActiveProject } from '../../../frontend/src/projects/ActiveProject';
import { projectContents } from '../../../frontend/src/projects/projectContents';
import { json, mockServer } from '../helpers';
import { TANK } from './plantFixtures';

function Active({ id, children }: { id: number; children: ReactNode }) {
  const { setProjectId } = useActiveProject();
  useEffect(() => setProjectId(id), [id, setProjectId]);
  return <>{children}</>;
}

function project(files: Record<string, string>) {
  const info = (name: string) => ({ name, language: name.endsWith('.plant') ? 'plant' : 'stl', size: files[name]!.length, version: 1, created_at: '', updated_at: '' });
  const routes: Record<string, () => Response> = {
    'GET /api/plants': () => json([TANK]),
    'GET /api/projects/7/files': () => json(Object.keys(files).map(info)),
    'GET /api/projects/7/blocks': () => json({ blocks: [], diagnostics: [] }),
  };
  for (const name of Object.keys(files)) routes[`GET /api/projects/7/files/${encodeURIComponent(name)}`] = () => json({ ...info(name), text: files[name] });
  mockServer(routes);
  render(
    <I18nextProvider i18n={createI18n('en')}>
      <ActiveProjectProvider>
        <Active id={7}>
          <PlantPanel />
        </Active>
      </ActiveProjectProvider>
    </I18nextProvider>,
  );
}

afterEach(() => {
  projectContents.clear();
  forgetPlantCatalogue();
});

describe('the Plant panel', () => {
  it('offers to attach a plant to a project without one', async () => {
    project({ 'OB1.awl': 'ORGANIZATION_BLOCK OB 1\nBEGIN\nEND_ORGANIZATION_BLOCK\n' });
    const attach = await screen.findByRole('button', { name: 'Attach a plant…' });
    await waitFor(() => expect((attach as HTMLButtonElement).disabled).toBe(false));
    expect(screen.getByTestId('plant-panel').textContent).toContain('This project has no plant');
  });

  it('shows the attached plant at rest, its panel waiting for a session', async () => {
    project({ 'tank.plant': 'kind: tank\nwiring: {pump_pb: I1.0, ls_low: I1.2, pump: Q8.0}\n' });
    await screen.findByTestId('plant-drawing-tank');
    await waitFor(() => expect(screen.getByTestId('plant-address-ls_low').textContent).toBe('I1.2'));
    expect(screen.getByTestId('plant-address-pump').textContent).toBe('Q8.0');
    expect(screen.getByTestId('plant-title').textContent).toBe('Tank with pump and level sensors');
    expect(screen.getByTestId('plant-still').textContent).toContain('download and run');
    expect(screen.getByTestId('plant-panel').getAttribute('data-live')).toBe('0');
    await waitFor(() => expect(screen.getByTestId('plant-control-pump_pb').textContent).toContain('I1.0'));
    expect((screen.getByTestId('plant-control-pump_pb') as HTMLButtonElement).disabled).toBe(true);
    expect(screen.getByRole('button', { name: 'Detach' })).toBeTruthy();
  });

  it('reports a plant file it cannot read, with the line', async () => {
    project({ 'tank.plant': 'kind: tank\nwiring:\n  pump Q4.0\n' });
    const error = await screen.findByTestId('plant-file-error');
    expect(error.textContent).toContain('tank.plant');
    expect(error.textContent).toContain('line 3 is not in the plant file format');
  });
});
