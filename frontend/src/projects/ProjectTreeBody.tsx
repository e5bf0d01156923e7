import { useCallback, useEffect, useId, useMemo, useState, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { warmUpCharts } from '../graph/warmUp';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { PlusIcon, RefreshIcon, WarningIcon } from '../ui/icons';
import { RowMenu, type MenuAction } from './RowMenu';
import { TreeItem } from './TreeItem';
import type { TreeRow } from './treeRows';
import type { ProjectsState } from './useProjects';
import { useTreeKeyboard } from './useTreeKeyboard';

export interface TreeRowActions {
  /** Click: select the row (and open or close a project or folder). */
  select: (row: TreeRow) => void;
  /** Open or close a project or folder. */
  setOpen: (row: TreeRow, open: boolean) => void;
  /** Enter: open a block or file, open or close the rest. */
  activate: (row: TreeRow) => void;
  /** Double-click: open a block or file. */
  open: (row: TreeRow) => void;
  rename: (row: TreeRow) => void;
  remove: (row: TreeRow) => void;
  menuFor: (row: TreeRow) => MenuAction[];
}

interface ProjectTreeBodyProps {
  state: ProjectsState;
  rows: readonly TreeRow[];
  labelledBy: string;
  selected: string | null;
  actions: TreeRowActions;
  onRetry: () => void;
  onCreate: () => void;
}

function expandable(row: TreeRow): boolean | null {
  if (row.type === 'project') return row.expanded;
  if (row.type === 'folder') return row.expanded;
  return null;
}

/** What the tree pane shows: loading, the server error, the empty state or the tree itself. */
export function ProjectTreeBody({ state, rows, labelledBy, selected, actions, onRetry, onCreate }: ProjectTreeBodyProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const hintId = useId();
  const [menu, setMenu] = useState<{ row: TreeRow; anchor: HTMLElement } | null>(null);

  const byKey = useMemo(() => new Map(rows.map((row) => [row.key, row])), [rows]);
  // A listed S7-Graph source is likely to be opened: the chart's layout worker gets ready now.
  const listsChart = rows.some((row) => row.type === 'file' && row.file.name.toLowerCase().endsWith('.graph'));
  useEffect(() => {
    if (listsChart) warmUpCharts();
  }, [listsChart]);
  const visibleKeys = useMemo(() => rows.map((row) => row.key), [rows]);

  const keyboardActions = useMemo(
    () => ({
      expand: (key: string) => {
        const row = byKey.get(key);
        if (!row || expandable(row) !== false) return false;
        actions.setOpen(row, true);
        return true;
      },
      collapse: (key: string) => {
        const row = byKey.get(key);
        if (!row || expandable(row) !== true) return false;
        actions.setOpen(row, false);
        return true;
      },
      activate: (key: string) => {
        const row = byKey.get(key);
        if (row) actions.activate(row);
      },
    }),
    [byKey, actions],
  );

  const keyboard = useTreeKeyboard(visibleKeys, keyboardActions);

  const openMenu = useCallback(
    (row: TreeRow, anchor: HTMLElement) => {
      if (actions.menuFor(row).length > 0) setMenu({ row, anchor });
    },
    [actions],
  );

  /** Shift+F10 or the context-menu key: the actions; F2 renames, Delete deletes. */
  const onKeyDown = (event: KeyboardEvent<HTMLElement>) => {
    const item = (event.target as HTMLElement).closest<HTMLElement>('[role="treeitem"]');
    const row = item ? byKey.get(item.dataset.treeKey ?? '') : undefined;
    if (item && row) {
      const handled = (() => {
        if (event.key === 'ContextMenu' || (event.key === 'F10' && event.shiftKey)) {
          openMenu(row, item);
          return true;
        }
        if (event.key === 'F2' && (row.type === 'file' || row.type === 'project')) {
          actions.rename(row);
          return true;
        }
        if (event.key === 'Delete' && (row.type === 'file' || row.type === 'project')) {
          actions.remove(row);
          return true;
        }
        return false;
      })();
      if (handled) {
        event.preventDefault();
        event.stopPropagation();
        return;
      }
    }
    keyboard.onKeyDown(event);
  };

  if (state.status === 'loading') {
    return (
      <p className="pane-message" role="status" data-testid="project-tree-loading">
        <span className="spinner" aria-hidden="true" />
        {t('projects.loading')}
      </p>
    );
  }

  if (state.status === 'error') {
    const unreachable = state.error.unreachable;
    return (
      <div className="pane-message pane-message--error" role="alert" data-testid="project-tree-error">
        <WarningIcon className="pane-message__icon" />
        <strong>{unreachable ? t('projects.unreachableTitle') : t('projects.loadFailedTitle')}</strong>
        <p>{unreachable ? t('projects.unreachableText') : errorText(state.error)}</p>
        <p className="pane-message__code">
          <code className="error-code">{state.error.code}</code>
        </p>
        <button type="button" className="button button--small" onClick={onRetry}>
          <RefreshIcon />
          <span>{t('common.retry')}</span>
        </button>
      </div>
    );
  }

  if (state.projects.length === 0) {
    return (
      <div className="pane-message" data-testid="project-tree-empty">
        <strong>{t('projects.emptyTitle')}</strong>
        <p>{t('projects.emptyText')}</p>
        <button type="button" className="button button--small" onClick={onCreate}>
          <PlusIcon />
          <span>{t('projects.createFirst')}</span>
        </button>
      </div>
    );
  }

  const menuLabel = menu ? t('projects.actions.menuLabel') : '';
  return (
    <>
      <ul
        role="tree"
        aria-labelledby={labelledBy}
        aria-describedby={hintId}
        className="tree"
        onKeyDown={onKeyDown}
        onFocus={keyboard.onFocus}
      >
        {rows.map((row) => (
          <TreeItem
            key={row.key}
            row={row}
            selected={selected === row.key}
            tabStop={keyboard.tabStop}
            menuOpen={menu?.row.key === row.key}
            hasActions={actions.menuFor(row).length > 0}
            onClick={actions.select}
            onDoubleClick={actions.open}
            onMenu={openMenu}
          />
        ))}
      </ul>
      <p id={hintId} className="visually-hidden">
        {t('projects.keysHint')}
      </p>
      {menu ? (
        <RowMenu
          anchor={menu.anchor}
          label={menuLabel}
          actions={actions.menuFor(menu.row)}
          testId="tree-menu"
          onClose={(restoreFocus) => {
            const anchor = menu.anchor;
            setMenu(null);
            if (restoreFocus && anchor.isConnected) anchor.focus();
          }}
        />
      ) : null}
    </>
  );
}
