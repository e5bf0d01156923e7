import { screen, waitFor, within } from '@testing-library/react';
import { describe, expect, it, vi } from 'vitest';
import { LANGUAGE_STORAGE_KEY } from '../../frontend/src/i18n/languages';
import { healthyServer, renderApp } from './helpers';

const root = document.documentElement;

describe('language switching', () => {
  it('starts in English, left-to-right, with an English title', async () => {
    healthyServer();
    renderApp();
    expect(root.lang).toBe('en');
    expect(root.dir).toBe('ltr');
    expect(document.title).toBe('Nasaq — PLC IDE');
    expect(screen.getByRole('button', { name: 'RUN: start the CPU' })).toBeTruthy();
    expect(await screen.findByRole('heading', { name: 'Projects' })).toBeTruthy();
  });

  it('lists the four languages, each labelled in its own language', () => {
    healthyServer();
    renderApp();
    const select = screen.getByTestId('lang-switch') as HTMLSelectElement;
    const options = within(select).getAllByRole('option') as HTMLOptionElement[];
    expect(options.map((option) => [option.value, option.textContent])).toEqual([
      ['en', 'English'],
      ['ar', 'العربية'],
      ['fa', 'فارسی'],
      ['vi', 'Tiếng Việt'],
    ]);
    expect(options.map((option) => option.lang)).toEqual(['en', 'ar', 'fa', 'vi']);
    // The select has an accessible name of its own (its label).
    expect(screen.getByRole('combobox', { name: 'Interface language' })).toBe(select);
  });

  it('switches to Persian: the page turns RTL and the labels change, code stays LTR', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.selectOptions(screen.getByTestId('lang-switch'), 'fa');

    expect(root.dir).toBe('rtl');
    expect(root.lang).toBe('fa');
    expect(document.title).toBe('نسق — محیط برنامه\u200cنویسی PLC');
    expect(screen.getByTestId('cpu-run').getAttribute('aria-label')).toBe('RUN: اجرای CPU');
    expect(screen.getByRole('button', { name: 'RUN: اجرای CPU' })).toBe(screen.getByTestId('cpu-run'));
    expect(screen.getByRole('heading', { name: 'پروژه\u200cها' })).toBeTruthy();
    expect(screen.queryByRole('heading', { name: 'Projects' })).toBeNull();
    expect((screen.getByTestId('lang-switch') as HTMLSelectElement).value).toBe('fa');

    // The editor area keeps code left-to-right; the Start page (prose) follows the UI.
    expect(screen.getByTestId('editor-area').getAttribute('dir')).toBe('ltr');
    expect(screen.getByTestId('start-page').getAttribute('dir')).toBe('rtl');
    expect(screen.getByRole('heading', { level: 1 }).textContent).toBe('به نسق خوش آمدید');

    expect(window.localStorage.getItem(LANGUAGE_STORAGE_KEY)).toBe('fa');
  });

  it('switches back to English and to left-to-right', async () => {
    healthyServer();
    const { user } = renderApp();
    const select = screen.getByTestId('lang-switch');
    await user.selectOptions(select, 'ar');
    expect(root.dir).toBe('rtl');
    expect(root.lang).toBe('ar');
    expect(screen.getByRole('button', { name: 'STOP: إيقاف وحدة المعالجة' })).toBeTruthy();

    await user.selectOptions(select, 'en');
    expect(root.dir).toBe('ltr');
    expect(root.lang).toBe('en');
    expect(screen.getByRole('button', { name: 'STOP: stop the CPU' })).toBeTruthy();
    expect(screen.getByTestId('start-page').getAttribute('dir')).toBe('ltr');
    expect(window.localStorage.getItem(LANGUAGE_STORAGE_KEY)).toBe('en');
  });

  it('Vietnamese is left-to-right and translated', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.selectOptions(screen.getByTestId('lang-switch'), 'vi');
    expect(root.dir).toBe('ltr');
    expect(root.lang).toBe('vi');
    expect(screen.getByRole('heading', { name: 'Dự án' })).toBeTruthy();
    expect(screen.getByTestId('ui-language-status').textContent).toContain('Tiếng Việt');
  });

  it('starts in the remembered language', () => {
    window.localStorage.setItem(LANGUAGE_STORAGE_KEY, 'ar');
    healthyServer();
    renderApp();
    expect(root.dir).toBe('rtl');
    expect(root.lang).toBe('ar');
    expect((screen.getByTestId('lang-switch') as HTMLSelectElement).value).toBe('ar');
  });

  it('else starts in the browser language when it is supported', () => {
    vi.spyOn(window.navigator, 'languages', 'get').mockReturnValue(['vi-VN', 'en-US']);
    healthyServer();
    renderApp();
    expect(root.lang).toBe('vi');
    expect(document.title).toBe('Nasaq — Môi trường lập trình PLC');
  });

  it('else starts in English', () => {
    window.localStorage.setItem(LANGUAGE_STORAGE_KEY, 'de');
    vi.spyOn(window.navigator, 'languages', 'get').mockReturnValue(['de-DE', 'fr']);
    healthyServer();
    renderApp();
    expect(root.lang).toBe('en');
    expect(root.dir).toBe('ltr');
  });

  it('translates the server status in the status bar', async () => {
    healthyServer();
    const { user } = renderApp();
    await waitFor(() => expect(screen.getByTestId('server-status').textContent).toBe('Server connected (v0.1.0)'));
    await user.selectOptions(screen.getByTestId('lang-switch'), 'fa');
    expect(screen.getByTestId('server-status').textContent).toBe('اتصال به سرور برقرار است (v0.1.0)');
  });
});
