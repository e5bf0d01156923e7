import { useCallback, useEffect, useMemo, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import { getDbMembers, type DbMember, type DbMembers } from '../api/symbols';
import { useMonitor, useSession, useWatchEntries } from '../cpu/SessionContext';
import type { DbTab } from '../editor/EditorTabsContext';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { defaultFormat, formatValue, parseModifyValue } from '../panels/watchFormat';
import { useProjectContents } from '../projects/projectContents';
import './dbeditor.css';

export type DbView = 'declaration' | 'data';

/** The watch entry of a member: `DB10.Motor.Speed`, `DB10.Values[1]`. */
export function watchEntryOf(db: number, member: DbMember): string {
  return `DB${db}.${member.path}`;
}

function ProblemLine({ error }: { error: ApiError }) {
  const text = useApiErrorText();
  return (
    <>
      <code className="error-code">{error.code}</code> <span>{text(error)}</span>
    </>
  );
}

interface RowProps {
  member: DbMember;
  view: DbView;
  entry: string | null;
  online: boolean;
  onOpen: (member: DbMember) => void;
  onModify: (entry: string, value: string) => void;
}

function MemberRow({ member, view, entry, online, onOpen, onModify }: RowProps) {
  const { t } = useTranslation();
  const value = useMonitor((state) => (entry ? state.watch[entry] : undefined));
  const report = useMonitor((state) => (entry ? state.watchReports[entry] : undefined));
  const [draft, setDraft] = useState('');
  const type = report?.type ?? member.type;
  const shown = value && value.error === null ? formatValue(value.value, type, defaultFormat(type)) : '';
  const problem = value?.error ?? report?.error ?? null;
  const submit = (event: FormEvent) => {
    event.preventDefault();
    if (entry && draft.trim() !== '') {
      onModify(entry, draft);
      setDraft('');
    }
  };
  return (
    <tr className="db-row" data-testid="db-row" data-path={member.path}>
      <td className="db-row__name" style={{ paddingInlineStart: `${0.5 + member.depth * 1.25}rem` }}>
        {member.line !== null && member.file ? (
          <button
            type="button"
            className="db-row__link"
            title={t('dbEditor.openDeclaration', { name: member.path })}
            data-testid="db-member-link"
            onClick={() => onOpen(member)}
          >
            {member.name}
          </button>
        ) : (
          <span>{member.name}</span>
        )}
      </td>
      <td className="db-row__type">{member.type}</td>
      <td className="db-row__offset">{member.offset ?? ''}</td>
      <td className="db-row__initial" data-testid="db-initial">
        {member.initial ?? ''}
      </td>
      {view === 'declaration' ? (
        <td className="db-row__comment">{member.comment}</td>
      ) : (
        <>
          <td className="db-row__actual" data-testid="db-actual">
            {member.actual ?? ''}
          </td>
          {online ? (
            <>
              <td className="db-row__online" data-testid="db-online">
                {problem ? (
                  <span className="db-row__error" title={problem}>
                    {report?.code ?? '!'}
                  </span>
                ) : (
                  shown
                )}
              </td>
              <td className="db-row__modify">
                {entry ? (
                  <form onSubmit={submit}>
                    <input
                      className="input input--compact"
                      dir="ltr"
                      value={draft}
                      aria-label={t('dbEditor.modifyLabel', { name: member.path })}
                      data-testid="db-modify-value"
                      onChange={(event) => setDraft(event.target.value)}
                    />
                    <button type="submit" className="button button--small" data-testid="db-modify">
                      {t('dbEditor.modify')}
                    </button>
                  </form>
                ) : null}
              </td>
            </>
          ) : null}
        </>
      )}
    </tr>
  );
}

/**
 * The DB editor: a data block's variables, nested by depth, with offsets and initial values (the
 * declaration view) and the compiled DB's actual values plus, while the project's simulation
 * runs, each elementary member's live value that can be modified (the data view). Declarations are
 * changed in the DB's source: "Edit source" opens it.
 */
export function DbEditorView({ tab, active }: { tab: DbTab; active: boolean }) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const openFile = useOpenProjectFile();
  const { session, command } = useSession();
  const connection = useMonitor((state) => state.connection);
  const contents = useProjectContents(tab.projectId);
  const [data, setData] = useState<DbMembers | null>(null);
  const [error, setError] = useState<ApiError | null>(null);
  const [view, setView] = useState<DbView>('data');

  const load = useCallback(
    async (signal?: AbortSignal) => {
      setError(null);
      try {
        setData(await getDbMembers(tab.projectId, tab.block, signal));
      } catch (caught) {
        if (caught instanceof DOMException && caught.name === 'AbortError') return;
        setError(asApiError(caught));
      }
    },
    [tab.projectId, tab.block],
  );

  // Read again whenever the project's build changes (a source was saved).
  const blocks = contents?.blocks;
  useEffect(() => {
    const controller = new AbortController();
    void load(controller.signal);
    return () => controller.abort();
  }, [load, blocks]);

  const online = !!session && session.projectId === tab.projectId && connection === 'open';
  const watched = view === 'data' && online && active && data !== null;
  const entries = useMemo(
    () => (watched && data ? data.members.filter((m) => m.elementary).map((m) => watchEntryOf(data.number, m)) : []),
    [watched, data],
  );
  useWatchEntries(`db-editor-${tab.id}`, entries);

  const openDeclaration = (member: DbMember) => {
    if (member.file) void openFile(tab.projectId, member.file, member.line ? { line: member.line } : null).catch(setErrorOf);
  };
  const setErrorOf = (caught: unknown) => setError(asApiError(caught));
  const editSource = () => {
    if (data) void openFile(tab.projectId, data.file, data.line ? { line: data.line } : null).catch(setErrorOf);
  };
  const modify = (entry: string, value: string) => {
    void command({ type: 'modify', target: entry, value: parseModifyValue(value) });
  };

  const title = data ? `DB${data.number}${data.name ? ` "${data.name}"` : ''}` : tab.name;
  return (
    <div className="db-editor" hidden={!active} data-testid={`db-editor-${tab.id}`}>
      <div className="db-editor__toolbar" dir={dir} lang={language}>
        <h2 className="db-editor__title">
          <bdi dir="ltr">{title}</bdi>
          {data?.instance_of != null ? (
            <span className="db-editor__instance">{t('dbEditor.instanceOf', { fb: `FB${data.instance_of}` })}</span>
          ) : null}
        </h2>
        <div className="db-editor__views" role="group" aria-label={t('dbEditor.viewLabel')}>
          {(['declaration', 'data'] as const).map((item) => (
            <button
              key={item}
              type="button"
              className={`button button--small${view === item ? ' button--primary' : ''}`}
              aria-pressed={view === item}
              data-testid={`db-view-${item}`}
              onClick={() => setView(item)}
            >
              {t(item === 'data' ? 'dbEditor.dataView' : 'dbEditor.declarationView')}
            </button>
          ))}
        </div>
        <button type="button" className="button button--small" data-testid="db-reload" onClick={() => void load()}>
          {t('dbEditor.reload')}
        </button>
        <button type="button" className="button button--small" data-testid="db-edit-source" disabled={!data} onClick={editSource}>
          {t('dbEditor.editSource')}
        </button>
      </div>
      <p className="db-editor__hint" dir={dir} lang={language}>
        {t('dbEditor.editHint')}{' '}
        {view === 'data' ? (
          <span data-testid="db-online-state">{online ? t('dbEditor.online') : t('dbEditor.offline')}</span>
        ) : null}
      </p>
      {error ? (
        <p className="db-editor__error" role="alert" dir={dir} lang={language} data-testid="db-error">
          <ProblemLine error={error} />
        </p>
      ) : null}
      {data === null && !error ? (
        <p role="status" dir={dir} lang={language}>
          {t('dbEditor.loading')}
        </p>
      ) : null}
      {data ? (
        data.members.length === 0 ? (
          <p dir={dir} lang={language}>{t('dbEditor.empty')}</p>
        ) : (
          <div className="db-editor__scroll">
            <table className="data-table db-table" dir="ltr" data-testid="db-table">
              <caption className="visually-hidden">{title}</caption>
              <thead>
                <tr>
                  <th scope="col">{t('dbEditor.columns.name')}</th>
                  <th scope="col">{t('dbEditor.columns.type')}</th>
                  <th scope="col">{t('dbEditor.columns.offset')}</th>
                  <th scope="col">{t('dbEditor.columns.initial')}</th>
                  {view === 'declaration' ? (
                    <th scope="col">{t('dbEditor.columns.comment')}</th>
                  ) : (
                    <>
                      <th scope="col">{t('dbEditor.columns.actual')}</th>
                      {online ? (
                        <>
                          <th scope="col">{t('dbEditor.columns.online')}</th>
                          <th scope="col">{t('dbEditor.columns.modify')}</th>
                        </>
                      ) : null}
                    </>
                  )}
                </tr>
              </thead>
              <tbody>
                {data.members.map((member) => (
                  <MemberRow
                    key={member.path}
                    member={member}
                    view={view}
                    entry={member.elementary ? watchEntryOf(data.number, member) : null}
                    online={online}
                    onOpen={openDeclaration}
                    onModify={modify}
                  />
                ))}
              </tbody>
            </table>
          </div>
        )
      ) : null}
    </div>
  );
}
