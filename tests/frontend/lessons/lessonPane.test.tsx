/**
 * The lesson pane against a fake lessons API: the course outline (own-language titles with
 * English beside them, progress, prerequisites), opening a lesson (its project opened in the
 * workbench with its first file, its text right to left with code left to right), "Check"
 * (saves first; passed/failed steps with expected and actual values and a click that opens the
 * failing network; compiler diagnostics instead of a failed check), hints one at a time, the
 * "predict, then run" quiz, and the solution fetched only after giving up.
 */
import { screen, waitFor, within } from '@testing-library/react';
import { render } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { I18nextProvider } from 'react-i18next';
import { describe, expect, it } from 'vitest';
import type { Mock } from 'vitest';
import { EditorTabsProvider, useEditorTabs } from '../../../frontend/src/editor/EditorTabsContext';
import { createI18n } from '../../../frontend/src/i18n/setup';
import type { Language } from '../../../frontend/src/i18n/languages';
import type { CheckResult, Course, Lesson, Progress } from '../../../frontend/src/lessons/api';
import { LessonPane, OPEN_LESSON_STORAGE_KEY } from '../../../frontend/src/lessons/LessonPane';
import { ActiveProjectProvider, useActiveProject } from '../../../frontend/src/projects/ActiveProject';
import { json, mockServer, requestsOf } from '../helpers';

const NOT_STARTED: Progress = { status: 'not_started', attempts: 0, time_s: 0, hints_revealed: 0, gave_up: false, passed_at: null };

const COURSE: Course = {
  units: [
    {
      id: 'fa2',
      order: 3,
      language: 'fa',
      title: { fa: 'مبدل‌ها و بیت‌های وضعیت', en: 'Converters and status bits' },
      summary: { fa: 'خلاصه', en: 'Summary' },
      lessons: [
        {
          id: 'fa2-06',
          order: 6,
          title: { fa: 'بیت‌های وضعیت OS و BR', en: 'Stored overflow OS and binary result BR' },
          summary: { fa: '', en: '' },
          languages: ['fa', 'en'],
          works_in: 'LAD',
          form: 'program',
          plant: null,
          prerequisites: ['fa2-05'],
          progress: { status: 'tried', attempts: 2, time_s: 95, hints_revealed: 0, gave_up: false, passed_at: null },
        },
        {
          id: 'fa2-05',
          order: 5,
          title: { fa: 'بیت سرریز OV', en: 'The overflow bit OV' },
          summary: { fa: '', en: '' },
          languages: ['fa', 'en'],
          works_in: 'LAD',
          form: 'program',
          plant: null,
          prerequisites: [],
          progress: null,
        },
      ],
    },
  ],
  problems: [{ file: 'examples/lessons/fa2/fa2-99/lesson.yaml', line: 4, code: 'LSN101', message: 'Broken lesson.' }],
};

const FA_TEXT = '# بیت‌های وضعیت\n\n## کار\n\nخروجی `Q 2.1` را روشن کنید.\n\n```lad-view\nA OS\nA BR\n= Q 2.1\n```\n';

const LESSON: Lesson = {
  id: 'fa2-06',
  unit: 'fa2',
  order: 6,
  title: COURSE.units[0]!.lessons[0]!.title,
  summary: { fa: '', en: '' },
  languages: ['fa', 'en'],
  works_in: 'LAD',
  open: 'OB1.lad',
  form: 'program',
  time_limit_min: 15,
  text: { fa: FA_TEXT, en: '# OS and BR\n\n## Task\n\nLight `Q 2.1`.\n' },
  figures: [],
  hints_total: 2,
  hints: [],
  quiz: [
    { id: 'q1', kind: 'predict', prompt: { fa: 'پیش‌بینی کنید', en: 'Predict' }, ask: ['Q 2.1'], set: { 'I 8.0': 1 }, scans: 1 },
  ],
  plant: null,
  checks: [{ kind: 'scenario', name: 'behaviour.yaml' }],
  prerequisites: ['fa2-05'],
  progress: NOT_STARTED,
};

const LAD_TEXT = `ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
RUNG
  Contact(I 0.0)
  Coil(Q 4.0)
END_RUNG
END_ORGANIZATION_BLOCK
`;

const FAILED: CheckResult = {
  status: 'failed',
  checks: [
    {
      kind: 'scenario',
      name: 'behaviour.yaml',
      passed: false,
      error: null,
      diagnostics: [],
      stop: null,
      steps: [
        { step: 1, note: 'no overflow', passed: true, failures: [] },
        {
          step: 2,
          note: 'overflow in network 1',
          passed: false,
          failures: [{ address: 'Q 2.1', expected: 1, actual: 0, at_ms: 10, where: { file: 'OB1.lad', line: 24, network: 4, element: 'e2' } }],
        },
      ],
    },
  ],
  quiz: [{ id: 'q1', correct: false, expected_shown: 'Q 2.1 = 0', explain: { fa: 'چون BR صفر است.', en: 'Because BR is 0.' } }],
  progress: { status: 'tried', attempts: 1, time_s: 30, hints_revealed: 0, gave_up: false, passed_at: null },
};

const COMPILE_ERROR: CheckResult = {
  status: 'compile_error',
  checks: [
    {
      kind: 'scenario',
      name: 'behaviour.yaml',
      passed: false,
      error: null,
      diagnostics: [{ code: 'LAD111', severity: 'error', message: 'Expected ")".', file: 'OB1.lad', line: 7, column: 3 }],
      stop: null,
      steps: [],
    },
  ],
  quiz: [],
  progress: null,
};

/** The editor tabs and the active project, as text a test can read. */
function Probe() {
  const { tabs, setSaveState } = useEditorTabs();
  const { projectId } = useActiveProject();
  const failSaves = () => {
    for (const tab of tabs) if (tab.kind === 'source') setSaveState(tab.id, { status: 'failed', error: null });
  };
  return (
    <output data-testid="probe" onClick={failSaves}>
      {JSON.stringify({
        projectId,
        tabs: tabs.filter((tab) => tab.kind === 'source').map((tab) => (tab.kind === 'source' ? { name: tab.name, reveal: tab.reveal } : null)),
      })}
    </output>
  );
}

function probe(): { projectId: number | null; tabs: Array<{ name: string; reveal: { line: number; network?: number; element?: string } | null }> } {
  return JSON.parse(screen.getByTestId('probe').textContent ?? '{}');
}

function renderPane(language: Language = 'en') {
  const user = userEvent.setup();
  const i18n = createI18n(language);
  render(
    <I18nextProvider i18n={i18n}>
      <EditorTabsProvider>
        <ActiveProjectProvider>
          <LessonPane onClose={() => undefined} />
          <Probe />
        </ActiveProjectProvider>
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  return { user };
}

function lessonServer(check: CheckResult = FAILED, lang = 'en'): Mock<typeof fetch> {
  let hints = 0;
  return mockServer({
    [`GET /api/lessons?lang=${lang}`]: () => json(COURSE),
    'GET /api/lessons/fa2-06': () => json(LESSON),
    'POST /api/lessons/fa2-06/open': () => json({ project_id: 7, project_name: 'Lesson fa2-06', open: 'OB1.lad', progress: NOT_STARTED }),
    'GET /api/projects/7/files/OB1.lad': () => json({ name: 'OB1.lad', language: 'lad', text: LAD_TEXT, version: 1, size: LAD_TEXT.length, updated_at: '2026-01-01T00:00:00Z' }),
    'GET /api/projects/7/blocks': () => json({ blocks: [], diagnostics: [] }),
    'POST /api/lessons/fa2-06/check': () => json(check),
    'POST /api/lessons/fa2-06/hint': () => {
      hints += 1;
      const all = [
        { fa: 'به بیت BR نگاه کنید.', en: 'Look at the BR bit.' },
        { fa: 'OS و BR را سری کنید.', en: 'Put OS and BR in series.' },
      ];
      return json({ index: hints, total: 2, hints: all.slice(0, hints) });
    },
    'POST /api/lessons/fa2-06/give-up': () => json({ ...NOT_STARTED, status: 'tried', gave_up: true }),
    'GET /api/lessons/fa2-06/solution?project_id=7': () => json({ files: [{ name: 'OB1.lad', text: 'Status(BR)' }] }),
    'POST /api/convert': () =>
      json({
        text: '',
        diagnostics: [],
        converted: 1,
        kept: 0,
        blocks: [
          {
            language: 'LAD',
            kind: 'OB',
            name: 'OB 1',
            return_type: null,
            title: '',
            declarations: '',
            networks: [
              {
                title: '',
                comment: '',
                label: null,
                logic: { elements: [{ id: 'e1', kind: 'status', bit: 'OS', negated: false, branches: [] }, { id: 'e2', kind: 'status', bit: 'BR', negated: false, branches: [] }] },
                outputs: [{ conditions: { elements: [] }, target: { id: 'e3', kind: 'coil', coil: '=', operand: 'Q 2.1', value: null } }],
                stl: null,
                stl_reason: null,
              },
            ],
          },
        ],
        drawings: null,
      }),
  });
}

describe('the course outline', () => {
  it('lists each unit and lesson in its own language with English beside it, with progress and what to do first', async () => {
    lessonServer();
    renderPane('en');
    const outline = await screen.findByTestId('course-outline');
    const unit = within(outline).getByTestId('course-unit-fa2');
    expect(within(unit).getByText('مبدل‌ها و بیت‌های وضعیت').getAttribute('dir')).toBe('rtl');
    expect(within(unit).getByText('Converters and status bits')).toBeTruthy();
    // Lessons in their order, each with its Persian and English title.
    const opens = Array.from(unit.querySelectorAll('[data-testid^="lesson-open-"]'));
    expect(opens.map((button) => button.getAttribute('data-testid'))).toEqual(['lesson-open-fa2-05', 'lesson-open-fa2-06']);
    const lesson = screen.getByTestId('lesson-open-fa2-06');
    expect(lesson.textContent).toContain('بیت‌های وضعیت OS و BR');
    expect(lesson.textContent).toContain('Stored overflow OS and binary result BR');
    const badges = within(unit).getAllByTestId('lesson-progress');
    expect(badges.map((badge) => badge.getAttribute('data-status'))).toEqual(['not_started', 'tried']);
    expect(badges[1]!.textContent).toContain('attempts: 2');
    expect(badges[1]!.textContent).toContain('1:35');
    expect(screen.getByTestId('lesson-prerequisites-fa2-06').textContent).toContain('fa2-05');
    // A malformed lesson folder is listed, not hidden and not breaking the list.
    expect(screen.getByTestId('course-problems').textContent).toContain('LSN101');
  });

  it('asks for the course in the interface language', async () => {
    const server = lessonServer(FAILED, 'fa');
    renderPane('fa');
    await screen.findByTestId('course-outline');
    expect(requestsOf(server)).toContain('GET /api/lessons?lang=fa');
    expect(screen.getByText('درس‌ها')).toBeTruthy();
  });
});

describe('a lesson', () => {
  it('opens its project in the workbench with its first file, and shows its Persian text right to left', async () => {
    const server = lessonServer(FAILED, 'fa');
    const { user } = renderPane('fa');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    const text = await screen.findByTestId('lesson-text');
    expect(text.getAttribute('dir')).toBe('rtl');
    expect(text.getAttribute('lang')).toBe('fa');
    expect(within(text).getByText('Q 2.1').getAttribute('dir')).toBe('ltr');
    expect(within(text).queryByRole('heading', { level: 1 })).toBeNull();
    // The lad-view fence is drawn with the LAD rung, left to right.
    const diagram = await within(text).findByTestId('lesson-diagram');
    expect(diagram.getAttribute('dir')).toBe('ltr');
    await waitFor(() => expect(diagram.querySelector('svg')).not.toBeNull());
    await waitFor(() => expect(probe()).toMatchObject({ projectId: 7, tabs: [{ name: 'OB1.lad' }] }));
    expect(requestsOf(server)).toContain('POST /api/lessons/fa2-06/open');
    expect(window.localStorage.getItem(OPEN_LESSON_STORAGE_KEY)).toBe('fa2-06');
    // The English text is one click away.
    await user.click(screen.getByTestId('lesson-lang-en'));
    expect(screen.getByTestId('lesson-text').getAttribute('dir')).toBe('ltr');
    expect(screen.getByTestId('lesson-text').textContent).toContain('Light Q 2.1.');
  });

  it('asks for the Check in the interface language, so the steps\' notes come in it', async () => {
    const server = lessonServer(FAILED, 'fa');
    const { user } = renderPane('fa');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    await waitFor(() => expect(probe().tabs).toHaveLength(1));
    await user.click(screen.getByTestId('lesson-check'));
    await screen.findByTestId('lesson-results');
    const body = JSON.parse(String(server.mock.calls.find(([url]) => url === '/api/lessons/fa2-06/check')?.[1]?.body));
    expect(body.lang).toBe('fa');
  });

  it('checks: each step passed or failed with expected and actual values, and the failing rung opens', async () => {
    const server = lessonServer(FAILED);
    const { user } = renderPane('en');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    await waitFor(() => expect(probe().tabs).toHaveLength(1));
    await user.click(screen.getByTestId('lesson-check'));
    const results = await screen.findByTestId('lesson-results');
    expect(results.getAttribute('data-status')).toBe('failed');
    const steps = within(results).getAllByTestId('lesson-step');
    expect(steps.map((step) => step.getAttribute('data-passed'))).toEqual(['true', 'false']);
    const failure = within(results).getByTestId('lesson-failure');
    expect(within(failure).getAllByRole('cell').map((cell) => cell.textContent)).toEqual(['Q 2.1', '1', '0', '10 ms', 'OB1.lad · NW 4']);
    const body = JSON.parse(String(server.mock.calls.find(([url, init]) => url === '/api/lessons/fa2-06/check' && init?.method === 'POST')?.[1]?.body));
    expect(body).toEqual({ project_id: 7, answers: {}, lang: 'en' });
    await user.click(within(failure).getByTestId('lesson-where'));
    await waitFor(() => expect(probe().tabs[0]?.reveal).toMatchObject({ line: 24, network: 4, element: 'e2' }));
    // The progress in the header follows the server's answer.
    expect(screen.getByTestId('lesson-view').querySelector('[data-testid="lesson-progress"]')?.getAttribute('data-status')).toBe('tried');
  });

  it('does not check while the server lacks what the editor shows (a save failed), and says so', async () => {
    const server = lessonServer();
    const { user } = renderPane('en');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    await waitFor(() => expect(probe().tabs).toHaveLength(1));
    await user.click(screen.getByTestId('probe')); // the autosave of OB1.lad failed
    await user.click(screen.getByTestId('lesson-check'));
    expect((await screen.findByTestId('lesson-notice')).textContent).toContain('not saved yet');
    expect(requestsOf(server)).not.toContain('POST /api/lessons/fa2-06/check');
    expect(screen.queryByTestId('lesson-results')).toBeNull();
  });

  it('shows the compiler diagnostics of a program that does not compile, not a failed check', async () => {
    lessonServer(COMPILE_ERROR);
    const { user } = renderPane('en');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    await waitFor(() => expect(probe().tabs).toHaveLength(1));
    await user.click(screen.getByTestId('lesson-check'));
    const results = await screen.findByTestId('lesson-results');
    expect(screen.getByTestId('lesson-verdict').textContent).toContain('does not compile');
    expect(within(results).queryByTestId('lesson-check-outcome')).toBeNull();
    expect(within(results).getByTestId('lesson-diagnostics').textContent).toContain('LAD111');
  });

  it('reveals hints one at a time', async () => {
    const server = lessonServer();
    const { user } = renderPane('en');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    const next = await screen.findByTestId('lesson-hint-next');
    await waitFor(() => expect(next.hasAttribute('disabled')).toBe(false));
    expect(screen.queryAllByTestId('lesson-hint')).toHaveLength(0);
    await user.click(next);
    await waitFor(() => expect(screen.getAllByTestId('lesson-hint').map((hint) => hint.textContent)).toEqual(['Look at the BR bit.']));
    await user.click(screen.getByTestId('lesson-hint-next'));
    await waitFor(() => expect(screen.getAllByTestId('lesson-hint')).toHaveLength(2));
    expect(screen.queryByTestId('lesson-hint-next')).toBeNull();
    expect(requestsOf(server).filter((call) => call === 'POST /api/lessons/fa2-06/hint')).toHaveLength(2);
  });

  it('predict, then run: a prediction is sent only once committed, then the truth is shown', async () => {
    const server = lessonServer();
    const { user } = renderPane('en');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    await waitFor(() => expect(probe().tabs).toHaveLength(1));
    const commit = screen.getByTestId('quiz-q1-commit');
    expect(commit.hasAttribute('disabled')).toBe(true);
    await user.type(screen.getByTestId('quiz-q1-Q 2.1'), '1');
    await user.click(commit);
    expect(screen.getByTestId('quiz-q1-Q 2.1').hasAttribute('disabled')).toBe(true);
    await user.click(screen.getByTestId('lesson-check'));
    await screen.findByTestId('lesson-results');
    const body = JSON.parse(String(server.mock.calls.find(([url]) => url === '/api/lessons/fa2-06/check')?.[1]?.body));
    expect(body.answers).toEqual({ q1: { 'Q 2.1': 1 } });
    expect(screen.getByTestId('quiz-verdict').getAttribute('data-correct')).toBe('false');
    expect(screen.getByTestId('quiz-truth').textContent).toBe('Q 2.1 = 0');
  });

  it('fetches the solution only after the learner gives up', async () => {
    const server = lessonServer();
    const { user } = renderPane('en');
    await user.click(await screen.findByTestId('lesson-open-fa2-06'));
    await waitFor(() => expect(probe().tabs).toHaveLength(1));
    expect(screen.queryByTestId('lesson-solution')).toBeNull();
    expect(requestsOf(server).some((call) => call.includes('/solution'))).toBe(false);
    await user.click(screen.getByTestId('lesson-give-up'));
    await user.click(screen.getByTestId('lesson-give-up-yes'));
    const solution = await screen.findByTestId('lesson-solution');
    await waitFor(() => expect(solution.textContent).toContain('Status(BR)'));
    expect(requestsOf(server).filter((call) => call.includes('/solution'))).toEqual(['GET /api/lessons/fa2-06/solution?project_id=7']);
  });

  it('comes back to the lesson it had open', async () => {
    window.localStorage.setItem(OPEN_LESSON_STORAGE_KEY, 'fa2-06');
    lessonServer();
    renderPane('en');
    expect(await screen.findByTestId('lesson-view')).toBeTruthy();
    await waitFor(() => expect(probe().projectId).toBe(7));
  });
});
