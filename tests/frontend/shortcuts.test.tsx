/**
 * The shortcut registry and the help dialog that lists it: every shortcut the IDE has, with a
 * translated label; the keys per platform; the dialog from the top bar, F1 and `?`.
 */
import { fireEvent, screen, waitFor, within } from '@testing-library/react';
import { describe, expect, it } from 'vitest';
import {
  SCOPES,
  SHORTCUTS,
  ariaKeys,
  currentPlatform,
  keyText,
  keysOf,
  opensShortcutHelp,
} from '../../frontend/src/app/shortcuts';
import { createI18n } from '../../frontend/src/i18n/setup';
import { LANGUAGES } from '../../frontend/src/i18n/languages';
import { healthyServer, renderApp } from './helpers';

function keydown(key: string, target: EventTarget = document.body, init: KeyboardEventInit = {}): KeyboardEvent {
  const event = new KeyboardEvent('keydown', { key, bubbles: true, ...init });
  Object.defineProperty(event, 'target', { value: target });
  return event;
}

describe('the shortcut registry', () => {
  it('lists every shortcut of the IDE once, each in a known scope', () => {
    const ids = SHORTCUTS.map((shortcut) => shortcut.id);
    expect(new Set(ids).size).toBe(ids.length);
    for (const id of ['download', 'compile', 'help', 'definition', 'format', 'completion', 'breakpoint', 'find', 'replace', 'rename', 'delete', 'menu']) {
      expect(ids, id).toContain(id);
    }
    for (const shortcut of SHORTCUTS) expect(SCOPES).toContain(shortcut.scope);
    expect(SHORTCUTS.filter((s) => s.scope === 'tree').map((s) => s.id)).toEqual(['open', 'rename', 'delete', 'menu']);
  });

  it.each(LANGUAGES)('has a label for every shortcut and scope in %s', async (language) => {
    const i18n = createI18n(language);
    await i18n.changeLanguage(language);
    for (const shortcut of SHORTCUTS) {
      expect(i18n.exists(shortcut.labelKey, { lng: language, fallbackLng: false }), `${language}:${shortcut.labelKey}`).toBe(true);
    }
    for (const scope of SCOPES) expect(i18n.exists(`shortcuts.scope.${scope}`, { lng: language, fallbackLng: false })).toBe(true);
  });

  it('prints the keys of each platform, as STEP 7 and Monaco take them', () => {
    const byId = (id: string) => SHORTCUTS.find((shortcut) => shortcut.id === id)!;
    expect(keysOf(byId('compile'), 'windows')).toEqual([['Ctrl', 'F7']]);
    expect(keysOf(byId('compile'), 'mac')).toEqual([['⌘', 'F7']]);
    expect(keysOf(byId('compile'), 'linux')).toEqual([['Ctrl', 'F7']]);
    // Monaco formats with Ctrl+Shift+I on Linux.
    expect(keysOf(byId('format'), 'linux')).toEqual([['Ctrl', 'Shift', 'I']]);
    expect(keysOf(byId('format'), 'windows')).toEqual([['Shift', 'Alt', 'F']]);
    expect(keyText('download', 'windows')).toBe('Ctrl+B');
    expect(keyText('download', 'mac')).toBe('⌘+B');
  });

  it('gives aria-keyshortcuts in the ARIA names, without the mouse', () => {
    expect(ariaKeys('download', 'windows')).toBe('Control+B');
    expect(ariaKeys('download', 'mac')).toBe('Meta+B');
    expect(ariaKeys('definition', 'windows')).toBe('F12');
    expect(ariaKeys('help', 'linux')).toBe('F1 ?');
    expect(() => ariaKeys('nothing')).toThrow(/unknown shortcut/);
  });

  it('tells the platform from the user agent', () => {
    expect(currentPlatform('Mozilla/5.0 (Macintosh; Intel Mac OS X 14_0)')).toBe('mac');
    expect(currentPlatform('Mozilla/5.0 (X11; Linux x86_64)')).toBe('linux');
    expect(currentPlatform('Mozilla/5.0 (Windows NT 10.0; Win64; x64)')).toBe('windows');
  });

  it('opens the help with F1 outside the code editor and ? where no text is typed', () => {
    const editor = document.createElement('div');
    editor.className = 'monaco-editor';
    const textarea = document.createElement('textarea');
    editor.append(textarea);
    const input = document.createElement('input');
    const button = document.createElement('button');
    expect(opensShortcutHelp(keydown('F1'))).toBe(true);
    expect(opensShortcutHelp(keydown('F1', button))).toBe(true);
    // Monaco's command palette keeps F1, and a typed ? stays a character.
    expect(opensShortcutHelp(keydown('F1', textarea))).toBe(false);
    expect(opensShortcutHelp(keydown('?', textarea))).toBe(false);
    expect(opensShortcutHelp(keydown('?', input))).toBe(false);
    expect(opensShortcutHelp(keydown('?', button))).toBe(true);
    expect(opensShortcutHelp(keydown('؟'))).toBe(true);
    // Ctrl+/ is Monaco's line comment.
    expect(opensShortcutHelp(keydown('/', document.body, { ctrlKey: true }))).toBe(false);
    expect(opensShortcutHelp(keydown('F1', document.body, { shiftKey: true }))).toBe(false);
  });
});

describe('the shortcuts dialog', () => {
  it('opens from the top bar, lists the shortcuts by scope, and closes with Escape', async () => {
    healthyServer();
    const { user } = renderApp();
    const opener = screen.getByTestId('shortcuts-button');
    expect(opener.getAttribute('aria-keyshortcuts')).toBe('F1 ?');
    await user.click(opener);
    const dialog = screen.getByRole('dialog', { name: 'Keyboard shortcuts' });
    expect(within(dialog).getByRole('heading', { name: 'Everywhere' })).toBeTruthy();
    expect(within(dialog).getByRole('heading', { name: 'In the code editor' })).toBeTruthy();
    expect(within(dialog).getByRole('heading', { name: 'In the project tree' })).toBeTruthy();
    const compile = within(dialog).getByTestId('shortcut-compile');
    expect(compile.textContent).toContain('Compile the project and show its diagnostics');
    expect(within(compile).getAllByText(/Ctrl|⌘|F7/).length).toBeGreaterThan(0);
    expect(within(dialog).getByTestId('shortcut-breakpoint').textContent).toContain('F9');
    expect(within(dialog).getByTestId('shortcut-definition').textContent).toContain('click');
    expect(within(dialog).getByTestId('shortcuts-editor').querySelectorAll('tbody tr')).toHaveLength(
      SHORTCUTS.filter((s) => s.scope === 'editor').length,
    );
    await user.keyboard('{Escape}');
    expect(screen.queryByRole('dialog')).toBeNull();
    expect(document.activeElement).toBe(opener);
  });

  it('opens with F1 and with ?, in the interface language, keys left-to-right', async () => {
    healthyServer();
    const { user } = renderApp('fa');
    await user.keyboard('{F1}');
    const dialog = await screen.findByRole('dialog', { name: 'میان‌برهای صفحه‌کلید' });
    expect(within(dialog).getByTestId('shortcut-download').textContent).toContain('بارگذاری پروژه در CPU');
    expect(within(dialog).getByTestId('shortcut-download').querySelector('td')!.getAttribute('dir')).toBe('ltr');
    await user.keyboard('{Escape}');
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    fireEvent.keyDown(document.body, { key: '?' });
    expect(await screen.findByTestId('shortcuts-dialog')).toBeTruthy();
  });

  it('is reached from the About dialog too', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.click(screen.getByTestId('help-button'));
    await user.click(within(screen.getByTestId('about-dialog')).getByTestId('about-shortcuts'));
    expect(screen.queryByTestId('about-dialog')).toBeNull();
    expect(screen.getByRole('dialog', { name: 'Keyboard shortcuts' })).toBeTruthy();
  });
});

describe('start page and About texts', () => {
  it('count the editors (LAD/FBD too), the simulator, monitoring, the lessons and S7-Graph as here, the classroom as coming', async () => {
    healthyServer();
    const { user } = renderApp();
    const page = screen.getByTestId('start-page');
    const [now, next] = within(page).getAllByRole('list').slice(0, 2) as [HTMLElement, HTMLElement];
    for (const feature of ['Projects stored on the server', 'STL and SCL editors', 'LAD and FBD editors', 'S7-Graph editor', 'CPU simulator', 'Online monitoring', 'Lessons']) {
      expect(within(now).getByText(feature)).toBeTruthy();
    }
    expect(within(next).getByText('Accounts for a classroom')).toBeTruthy();
    expect(within(next).queryByText('S7-Graph editor')).toBeNull();
    expect(within(next).queryByText('Lessons')).toBeNull();
    expect(within(next).queryByText('CPU simulator')).toBeNull();
    expect(within(next).queryByText('LAD and FBD editors')).toBeNull();
    await user.click(screen.getByTestId('help-button'));
    const about = screen.getByTestId('about-dialog');
    const [here, coming] = within(about).getAllByRole('list') as [HTMLElement, HTMLElement];
    expect(here.textContent).toContain('STL and SCL editors');
    expect(here.textContent).toContain('Online monitoring');
    expect(here.textContent).toContain('LAD and FBD editors');
    expect(here.textContent).toContain('Lessons: the course in Arabic, Persian and Vietnamese');
    expect(here.textContent).toContain('S7-Graph editor: the sequencer chart');
    expect(coming.textContent).toBe('Accounts for a classroom: teacher and students, and the class\'s progress.');
  });
});
