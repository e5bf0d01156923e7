import { useCallback, useEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, getFile, saveFile } from '../api/client';
import type { Diagnostic } from '../api/types';
import { Autosaver, registerAutosaver } from '../editor/autosave';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { useEditorTabs, type SaveState, type SourceTab } from '../editor/EditorTabsContext';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { projectContents } from '../projects/projectContents';
import { ErrorIcon, WarningIcon } from '../ui/icons';
import { checkProperties } from './api';
import { lineOf, propertyText, setProperty, type CpuProperties, type PropertyKey } from './format';
import './cpuprops.css';

/** The clock memory bits' frequencies (S7-300/400 manuals), bit 0 first. */
const CLOCK_HZ = ['10', '5', '2.5', '2', '1.25', '1', '0.625', '0.5'];

type Drafts = Partial<Record<PropertyKey, string>>;

function isError(problem: Diagnostic): boolean {
  return problem.severity === 'error';
}

/** The text of the line a problem is on: problems of lines the page did not write stay known. */
function problemLines(text: string, problems: readonly Diagnostic[]): Set<string> {
  const lines = text.split('\n');
  return new Set(problems.filter(isError).map((problem) => lines[(problem.span?.line ?? 1) - 1] ?? ''));
}

/**
 * The CPU properties page of a project (STEP 7's "Properties - CPU"): labelled fields for the
 * properties of `cpu.properties`, each problem beside its field, autosaved with the file's
 * version check. The server reads the text (one parser for the page, downloads and `nasaq run`);
 * a value with a problem is shown as typed and not saved until it is corrected.
 */
export function CpuPropertiesTab({ tab, active }: { tab: SourceTab; active: boolean }) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const { setSaveState, replaceText } = useEditorTabs();
  const message = useDiagnosticMessage();
  const errorText = useApiErrorText();
  const [text, setText] = useState(tab.text);
  const [values, setValues] = useState<CpuProperties | null>(null);
  const [problems, setProblems] = useState<Diagnostic[]>([]);
  const [drafts, setDrafts] = useState<Drafts>({});
  const [clockByte, setClockByte] = useState('100');
  const [save, setSave] = useState<SaveState>({ status: 'saved', error: null });
  const [loadError, setLoadError] = useState<string | null>(null);
  const saverRef = useRef<Autosaver | null>(null);
  // Problems the file had when it was read: the page does not make them, so they do not stop it.
  const known = useRef<Set<string>>(new Set());
  const latest = useRef(0);
  // The text the server has: an edit with a problem takes back what was waiting to be saved.
  const savedText = useRef(tab.text);
  const file = tab.file;
  const fileRef = useRef(file);
  fileRef.current = file;

  const read = useCallback(
    async (next: string) => {
      const seq = ++latest.current;
      const found = await checkProperties(next);
      if (seq !== latest.current) return null;
      setValues(found.properties);
      setProblems(found.diagnostics);
      setLoadError(null);
      if (found.properties.clock_memory !== null) setClockByte(String(found.properties.clock_memory));
      return found;
    },
    [],
  );

  useEffect(() => {
    read(tab.text)
      .then((found) => {
        if (found) known.current = problemLines(tab.text, found.diagnostics);
      })
      .catch((error: unknown) => setLoadError(errorText(asApiError(error))));
    if (!file) return;
    const saver = new Autosaver({
      text: tab.text,
      version: tab.version,
      save: (sent, baseVersion, options) =>
        saveFile(file.projectId, file.path, { text: sent, base_version: baseVersion }, { keepalive: options.keepalive }),
      onState: (state) => {
        setSave(state);
        setSaveState(tab.id, state);
      },
      onSaved: (_info, sent) => {
        savedText.current = sent;
        projectContents.reloadSoon(file.projectId);
      },
    });
    saverRef.current = saver;
    const unregister = registerAutosaver(`${tab.id}:page`, () => fileRef.current, saver);
    return () => {
      unregister();
      saverRef.current = null;
      void saver.dispose();
    };
    // One autosave per tab; the tab's text later changes only through this page.
  }, [tab.id]);

  /** A field changed: the line of its key gets the value; saved when it brings no new problem. */
  const change = async (key: PropertyKey, value: string) => {
    const next = setProperty(text, key, value);
    setText(next);
    setDrafts((current) => ({ ...current, [key]: value }));
    try {
      const found = await read(next);
      if (!found) return;
      const fresh = [...problemLines(next, found.diagnostics)].filter((line) => !known.current.has(line));
      const lines = next.split('\n');
      setDrafts((current) => {
        const kept: Drafts = {};
        for (const [name, typed] of Object.entries(current) as [PropertyKey, string][]) {
          const at = lineOf(next, name);
          if (found.diagnostics.some((problem) => isError(problem) && problem.span?.line === at + 1)) kept[name] = typed;
        }
        return kept;
      });
      saverRef.current?.change(fresh.length === 0 && lines.length > 0 ? next : savedText.current);
    } catch (error) {
      setLoadError(errorText(asApiError(error)));
    }
  };

  const reload = async () => {
    if (!file) return;
    const theirs = await getFile(file.projectId, file.path);
    saverRef.current?.reloaded(theirs.text, theirs.version);
    savedText.current = theirs.text;
    replaceText(tab.id, theirs.text, theirs.version);
    setText(theirs.text);
    setDrafts({});
    const found = await read(theirs.text);
    if (found) known.current = problemLines(theirs.text, found.diagnostics);
  };

  const problemOf = (key: PropertyKey): Diagnostic | null => {
    const at = lineOf(text, key);
    if (at < 0) return null;
    return problems.find((problem) => isError(problem) && problem.span?.line === at + 1) ?? null;
  };
  const shown = (key: PropertyKey): string => {
    const typed = drafts[key];
    if (typed !== undefined) return typed;
    return values ? propertyText(key, values[key]) : '';
  };
  const others = useMemo(() => {
    const owned = new Set(
      (['profile', 'cycle_monitoring_time', 'cycle_time', 'clock_memory', 'retentive_markers', 'retentive_timers', 'retentive_counters', 'startup'] as const)
        .map((key) => lineOf(text, key) + 1)
        .filter((line) => line > 0),
    );
    return problems.filter((problem) => !owned.has(problem.span?.line ?? 0));
  }, [problems, text]);

  const clockOn = (drafts.clock_memory ?? shown('clock_memory')).toLowerCase() !== 'none';

  const field = (key: PropertyKey, label: string, hint: ReactNode, input: ReactNode) => {
    const problem = problemOf(key);
    return (
      <div className="cpu-props__field" data-testid={`cpu-props-field-${key}`}>
        <label htmlFor={`${tab.id}-${key}`} className="cpu-props__label">
          {label}
        </label>
        <div className="cpu-props__input">{input}</div>
        {hint ? <p className="cpu-props__hint">{hint}</p> : null}
        {problem ? (
          <p className="cpu-props__problem" role="alert" id={`${tab.id}-${key}-problem`} data-testid={`cpu-props-problem-${key}`}>
            <ErrorIcon className="cpu-props__problem-icon" /> {message(problem)} <span className="cpu-props__code">{problem.code}</span>
          </p>
        ) : null}
      </div>
    );
  };
  const number = (key: PropertyKey, unit?: string) => (
    <>
      <input
        id={`${tab.id}-${key}`}
        type="text"
        inputMode="numeric"
        dir="ltr"
        className="input cpu-props__number"
        value={shown(key)}
        aria-invalid={problemOf(key) ? true : undefined}
        aria-describedby={problemOf(key) ? `${tab.id}-${key}-problem` : undefined}
        onChange={(event) => void change(key, event.target.value)}
      />
      {unit ? <span className="cpu-props__unit">{unit}</span> : null}
    </>
  );

  return (
    <div className="cpu-props" hidden={!active} dir={dir} lang={language} data-testid="cpu-props">
      {save.status === 'conflict' && save.error ? (
        <div className="source-banner source-banner--conflict" role="alert" data-testid="cpu-props-conflict">
          <WarningIcon className="source-banner__icon" />
          <p className="source-banner__text">{errorText(save.error)}</p>
          <div className="source-banner__actions">
            <button type="button" className="button button--small" onClick={() => void reload()}>
              {t('editor.conflict.reload')}
            </button>
            <button type="button" className="button button--small button--primary" onClick={() => void saverRef.current?.overwrite()}>
              {t('editor.conflict.overwrite')}
            </button>
          </div>
        </div>
      ) : null}
      {save.status === 'failed' && save.error ? (
        <div className="source-banner source-banner--failed" role="alert">
          <ErrorIcon className="source-banner__icon" />
          <p className="source-banner__text">
            {t('editor.save.failedText')} {errorText(save.error)}
          </p>
        </div>
      ) : null}
      <header className="cpu-props__header">
        <h2 className="cpu-props__title">{t('cpuProps.title')}</h2>
        <span className="cpu-props__status" role="status" data-testid="cpu-props-status">
          {t(`cpuProps.status.${save.status}`)}
        </span>
        <button
          type="button"
          className="button button--small button--primary"
          data-testid="cpu-props-save"
          disabled={!file}
          onClick={() => void saverRef.current?.flush()}
        >
          {t('cpuProps.save')}
        </button>
      </header>
      <p className="cpu-props__intro">{t('cpuProps.intro', { file: file?.path ?? tab.name })}</p>
      {loadError ? (
        <p className="cpu-props__problem" role="alert">
          {loadError}
        </p>
      ) : null}

      <section className="cpu-props__group" aria-labelledby={`${tab.id}-general`}>
        <h3 id={`${tab.id}-general`}>{t('cpuProps.general')}</h3>
        {field(
          'profile',
          t('cpuProps.profile'),
          t('cpuProps.profileHint'),
          <select id={`${tab.id}-profile`} className="input" dir="ltr" value={shown('profile')} onChange={(event) => void change('profile', event.target.value)}>
            <option value="S7-300">S7-300</option>
            <option value="S7-400">S7-400</option>
            <option value="S7-1500">S7-1200/1500</option>
          </select>,
        )}
        {field('startup', t('cpuProps.startup'), t('cpuProps.startupHint'), (
          <select id={`${tab.id}-startup`} className="input" value={shown('startup')} onChange={(event) => void change('startup', event.target.value)}>
            <option value="warm">{t('cpuProps.warm')}</option>
            <option value="cold">{t('cpuProps.cold')}</option>
          </select>
        ))}
      </section>

      <section className="cpu-props__group" aria-labelledby={`${tab.id}-cycle`}>
        <h3 id={`${tab.id}-cycle`}>{t('cpuProps.cycle')}</h3>
        {field('cycle_time', t('cpuProps.cycleTime'), t('cpuProps.cycleTimeHint'), number('cycle_time', t('cpuProps.ms')))}
        {field(
          'cycle_monitoring_time',
          t('cpuProps.cycleMonitoring'),
          t('cpuProps.cycleMonitoringHint'),
          number('cycle_monitoring_time', t('cpuProps.ms')),
        )}
      </section>

      <section className="cpu-props__group" aria-labelledby={`${tab.id}-clock`}>
        <h3 id={`${tab.id}-clock`}>{t('cpuProps.clockMemory')}</h3>
        <label className="cpu-props__check">
          <input
            type="checkbox"
            checked={clockOn}
            data-testid="cpu-props-clock-enabled"
            onChange={(event) => void change('clock_memory', event.target.checked ? `MB${clockByte}` : 'none')}
          />
          {t('cpuProps.clockEnabled')}
        </label>
        {clockOn
          ? field(
              'clock_memory',
              t('cpuProps.clockByte'),
              null,
              <>
                <span className="cpu-props__unit" dir="ltr">
                  MB
                </span>
                <input
                  id={`${tab.id}-clock_memory`}
                  type="text"
                  inputMode="numeric"
                  dir="ltr"
                  className="input cpu-props__number"
                  value={drafts.clock_memory !== undefined ? drafts.clock_memory.replace(/^MB/i, '') : clockByte}
                  aria-invalid={problemOf('clock_memory') ? true : undefined}
                  onChange={(event) => {
                    setClockByte(event.target.value);
                    void change('clock_memory', `MB${event.target.value}`);
                  }}
                />
              </>,
            )
          : null}
        <table className="cpu-props__bits" dir="ltr" aria-label={t('cpuProps.clockBits')}>
          <thead>
            <tr>
              <th scope="row">{t('cpuProps.bit')}</th>
              {CLOCK_HZ.map((_, bit) => (
                <th key={bit} scope="col">
                  {clockOn ? `M${clockByte}.${bit}` : bit}
                </th>
              ))}
            </tr>
          </thead>
          <tbody>
            <tr>
              <th scope="row">{t('cpuProps.hz')}</th>
              {CLOCK_HZ.map((hz) => (
                <td key={hz}>{hz}</td>
              ))}
            </tr>
          </tbody>
        </table>
      </section>

      <section className="cpu-props__group" aria-labelledby={`${tab.id}-retentive`}>
        <h3 id={`${tab.id}-retentive`}>{t('cpuProps.retentive')}</h3>
        <p className="cpu-props__hint">{t('cpuProps.retentiveHint')}</p>
        {field('retentive_markers', t('cpuProps.retentiveMarkers'), null, number('retentive_markers'))}
        {field('retentive_timers', t('cpuProps.retentiveTimers'), null, number('retentive_timers'))}
        {field('retentive_counters', t('cpuProps.retentiveCounters'), null, number('retentive_counters'))}
      </section>

      {others.length > 0 ? (
        <section className="cpu-props__group" aria-labelledby={`${tab.id}-others`} data-testid="cpu-props-other-problems">
          <h3 id={`${tab.id}-others`}>{t('cpuProps.otherProblems')}</h3>
          <ul className="cpu-props__problems">
            {others.map((problem, index) => (
              <li key={index} className="cpu-props__problem">
                <ErrorIcon className="cpu-props__problem-icon" />{' '}
                {t('cpuProps.line', { line: problem.span?.line ?? 1 })}: {message(problem)} <span className="cpu-props__code">{problem.code}</span>
              </li>
            ))}
          </ul>
        </section>
      ) : null}

      <details className="cpu-props__group cpu-props__file">
        <summary>{t('cpuProps.fileText', { file: file?.path ?? tab.name })}</summary>
        <pre dir="ltr" className="cpu-props__text" data-testid="cpu-props-text">
          {text}
        </pre>
      </details>
    </div>
  );
}
