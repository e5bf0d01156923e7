import { screen, waitFor, within } from '@testing-library/react';
import { describe, expect, it } from 'vitest';
import { LESSON_PANE_STORAGE_KEY } from '../../frontend/src/app/Workbench';
import { healthyServer, json, renderApp, serverDown, waitForServer } from './helpers';

describe('page structure', () => {
  it('has the landmarks of an IDE: banner, navigation, main, complementary and contentinfo', () => {
    healthyServer();
    renderApp();
    expect(screen.getByRole('banner')).toBeTruthy();
    expect(screen.getByRole('navigation')).toBe(screen.getByTestId('block-tree'));
    expect(screen.getByRole('main')).toBeTruthy();
    expect(screen.getByRole('complementary')).toBe(screen.getByTestId('lesson-pane'));
    expect(screen.getByRole('contentinfo')).toBeTruthy();
    expect(within(screen.getByRole('main')).getByTestId('editor-area')).toBeTruthy();
  });

  it('gives every button, select, input and tab an accessible name', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.click(screen.getByTestId('project-new'));
    const controls = [
      ...screen.getAllByRole('button'),
      ...screen.getAllByRole('combobox'),
      ...screen.getAllByRole('textbox'),
      ...screen.getAllByRole('tab'),
    ];
    expect(controls.length).toBeGreaterThan(15);
    for (const control of controls) {
      const labelledBy = control.getAttribute('aria-labelledby');
      const label =
        control.getAttribute('aria-label') ??
        (labelledBy ? document.getElementById(labelledBy)?.textContent : null) ??
        (control.id ? document.querySelector(`label[for="${control.id}"]`)?.textContent : null) ??
        control.textContent;
      expect(label?.trim(), control.outerHTML.slice(0, 120)).toBeTruthy();
    }
  });
});

describe('CPU toolbar', () => {
  it('shows Download, RUN, STOP and STEP named, disabled until a project and a session exist, and explained', () => {
    healthyServer();
    renderApp();
    const group = screen.getByRole('group', { name: 'CPU control' });
    const download = screen.getByTestId('cpu-download') as HTMLButtonElement;
    expect(group.contains(download)).toBe(true);
    expect(download.disabled).toBe(true);
    expect(download.getAttribute('aria-keyshortcuts')).toBe('Control+B');
    expect(download.title).toContain('Select a project in the project tree first');
    for (const [id, name] of [
      ['cpu-run', 'RUN: start the CPU'],
      ['cpu-stop', 'STOP: stop the CPU'],
      ['cpu-step', 'STEP: execute one step'],
    ] as const) {
      const button = screen.getByTestId(id) as HTMLButtonElement;
      expect(group.contains(button)).toBe(true);
      expect(button.disabled).toBe(true);
      expect(screen.getByRole('button', { name })).toBe(button);
      expect(button.textContent).toBe(name.split(':')[0]);
      const reason = document.getElementById(button.getAttribute('aria-describedby')!);
      expect(reason?.textContent).toContain('Select a project in the project tree first');
    }
  });

  it('shows the CPU state honestly: nothing downloaded', () => {
    healthyServer();
    renderApp();
    expect(screen.getByTestId('cpu-state').textContent).toBe('No program downloaded');
    expect(screen.getByTestId('cpu-status').textContent).toBe('CPU: No program downloaded');
    expect(screen.queryByText('RUN', { selector: '.cpu-state__text' })).toBeNull();
  });
});

describe('lesson pane', () => {
  it('is open at first and shows the course outline the server lists', async () => {
    healthyServer([], {
      'GET /api/lessons?lang=en': () =>
        json({
          units: [{ id: 'vi4', order: 4, language: 'vi', title: { vi: 'Khóa học PLC', en: 'PLC course' }, summary: {}, lessons: [] }],
          problems: [],
        }),
    });
    renderApp();
    const pane = screen.getByTestId('lesson-pane');
    expect(pane.tagName).toBe('ASIDE');
    expect(within(pane).getByRole('heading', { name: 'Lessons' })).toBeTruthy();
    expect(await within(pane).findByTestId('course-unit-vi4')).toBeTruthy();
    expect(within(pane).getByText('Khóa học PLC')).toBeTruthy();
    expect(within(pane).getByText('PLC course')).toBeTruthy();
    expect(screen.getByTestId('lesson-toggle').getAttribute('aria-pressed')).toBe('true');
  });

  it('toggles from the top bar and remembers the choice', async () => {
    healthyServer();
    const { user, unmount } = renderApp();
    const toggle = screen.getByTestId('lesson-toggle');
    expect(toggle.getAttribute('aria-controls')).toBe(screen.getByTestId('lesson-pane').id);

    await user.click(toggle);
    expect(screen.queryByTestId('lesson-pane')).toBeNull();
    expect(toggle.getAttribute('aria-pressed')).toBe('false');
    expect(window.localStorage.getItem(LESSON_PANE_STORAGE_KEY)).toBe('false');

    unmount();
    healthyServer();
    const again = renderApp();
    expect(screen.queryByTestId('lesson-pane')).toBeNull();
    await again.user.click(screen.getByTestId('lesson-toggle'));
    expect(screen.getByTestId('lesson-pane')).toBeTruthy();
    expect(window.localStorage.getItem(LESSON_PANE_STORAGE_KEY)).toBe('true');
  });

  it('closes with its own button and gives focus back to the toggle', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.click(screen.getByRole('button', { name: 'Close the lesson pane' }));
    expect(screen.queryByTestId('lesson-pane')).toBeNull();
    expect(document.activeElement).toBe(screen.getByTestId('lesson-toggle'));
    expect(window.localStorage.getItem(LESSON_PANE_STORAGE_KEY)).toBe('false');
  });
});

describe('editor area', () => {
  it('opens with the Start tab and stays left-to-right', () => {
    healthyServer();
    renderApp('ar');
    const area = screen.getByTestId('editor-area');
    expect(area.getAttribute('dir')).toBe('ltr');
    expect(within(area).getByTestId('editor-tab-start').textContent).toBe('البداية');
    expect(within(area).getByTestId('start-page').getAttribute('dir')).toBe('rtl');
    // Code inside the prose page stays LTR.
    const sample = within(area).getByRole('figure', { name: 'مثال STL: دائرة إمساك ذاتي لمحرك' });
    expect(sample.querySelector('pre')!.getAttribute('dir')).toBe('ltr');
    expect(sample.querySelector('pre')!.textContent).toContain('AN    "Stop"');
  });

  it('tells what works now and what is coming', () => {
    healthyServer();
    renderApp();
    const page = screen.getByTestId('start-page');
    expect(within(page).getByRole('heading', { name: 'Works now' })).toBeTruthy();
    expect(within(page).getByText('Projects stored on the server')).toBeTruthy();
    expect(within(page).getByRole('heading', { name: 'Coming next' })).toBeTruthy();
    for (const feature of ['STL and SCL editors', 'CPU simulator', 'LAD and FBD editors', 'S7-Graph editor']) {
      expect(within(page).getByText(feature)).toBeTruthy();
    }
  });

  it('closes the Start tab to an empty state and reopens it', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.click(screen.getByRole('button', { name: 'Close Start' }));
    expect(screen.queryByTestId('start-page')).toBeNull();
    const empty = screen.getByTestId('editor-empty');
    expect(empty.textContent).toContain('No editor open');
    await user.click(within(empty).getByRole('button', { name: 'Open the Start page' }));
    expect(screen.getByTestId('start-page')).toBeTruthy();
    expect(screen.getByTestId('editor-tab-start').getAttribute('aria-current')).toBe('true');
  });

  it('reopens the Start tab from the help dialog', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.click(screen.getByTestId('editor-tab-close-start'));
    await user.click(screen.getByRole('button', { name: 'Help' }));
    const dialog = screen.getByRole('dialog', { name: 'About Nasaq' });
    await user.click(within(dialog).getByRole('button', { name: 'Open the Start page' }));
    expect(screen.queryByRole('dialog')).toBeNull();
    expect(screen.getByTestId('start-page')).toBeTruthy();
  });
});

describe('help dialog and status bar', () => {
  it('shows the server version and what is here and coming', async () => {
    healthyServer();
    const { user } = renderApp();
    await waitForServer();
    await user.click(screen.getByTestId('help-button'));
    const dialog = screen.getByTestId('about-dialog');
    expect(dialog.getAttribute('role')).toBe('dialog');
    expect(dialog.getAttribute('aria-modal')).toBe('true');
    expect(within(dialog).getByTestId('about-version').textContent).toBe('0.1.0');
    expect(within(dialog).getByRole('heading', { name: "What's here" })).toBeTruthy();
    expect(within(dialog).getByRole('heading', { name: "What's coming" })).toBeTruthy();
    await user.keyboard('{Escape}');
    expect(screen.queryByTestId('about-dialog')).toBeNull();
    expect(document.activeElement).toBe(screen.getByTestId('help-button'));
  });

  it('shows the server connection in the status bar', async () => {
    healthyServer();
    renderApp();
    const status = screen.getByTestId('server-status');
    await waitFor(() => expect(status.getAttribute('data-state')).toBe('online'));
    expect(status.textContent).toBe('Server connected (v0.1.0)');
    expect(screen.getByTestId('ui-language-status').textContent).toBe('Language: English');
  });

  it('says so when the server cannot be reached', async () => {
    serverDown();
    const { user } = renderApp();
    const status = screen.getByTestId('server-status');
    await waitFor(() => expect(status.getAttribute('data-state')).toBe('offline'));
    expect(status.textContent).toBe('Server not reachable');
    await user.click(screen.getByTestId('help-button'));
    expect(screen.getByTestId('about-version').textContent).toBe('unknown (server not reachable)');
  });
});
