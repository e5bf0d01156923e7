import type { MouseEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { ChevronIcon, EyeIcon, ProjectIcon, TableIcon, WarningIcon } from '../ui/icons';
import { BlockIcon, MoreIcon, SourceFileIcon } from './treeIcons';
import { blockLabel, type TreeRow } from './treeRows';

interface TreeItemProps {
  row: TreeRow;
  selected: boolean;
  tabStop: string | null;
  /** The row's menu is open. */
  menuOpen: boolean;
  /** The row has actions (a context menu). */
  hasActions: boolean;
  onClick: (row: TreeRow) => void;
  onDoubleClick: (row: TreeRow) => void;
  onMenu: (row: TreeRow, item: HTMLElement) => void;
}

function testIdOf(row: TreeRow): string | undefined {
  switch (row.type) {
    case 'project':
      return `project-node-${row.projectId}`;
    case 'folder':
      return `folder-node-${row.projectId}-${row.folder.id}`;
    case 'block':
      return `block-node-${row.projectId}-${blockLabel(row.block)}`;
    case 'file':
      return `file-node-${row.projectId}-${row.file.name}`;
    default:
      return `project-contents-${row.type}-${row.projectId}`;
  }
}

function RowContent({ row }: { row: TreeRow }) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  switch (row.type) {
    case 'project':
      return (
        <>
          <ProjectIcon className="tree-icon tree-icon--project" />
          <span className="tree-label">
            <bdi>{row.project.name}</bdi>
          </span>
        </>
      );
    case 'folder':
      return (
        <>
          <row.folder.Icon className="tree-icon" />
          <span className="tree-label" title={t(row.folder.labelKey)}>
            {t(row.folder.labelKey)}
          </span>
          <span className="tree-count" aria-hidden="true">
            {row.count}
          </span>
        </>
      );
    case 'block':
      return (
        <>
          <BlockIcon className="tree-icon tree-icon--block" />
          <span className="tree-label">
            <bdi>{blockLabel(row.block)}</bdi>
            {row.block.name ? (
              <>
                {' '}
                <bdi className="tree-secondary">{row.block.name}</bdi>
              </>
            ) : null}
          </span>
          <span className="tree-language" aria-hidden="true">
            {row.block.language.toUpperCase()}
          </span>
        </>
      );
    case 'file': {
      const Icon = row.file.language === 'symbols' ? TableIcon : row.file.language === 'watch' ? EyeIcon : SourceFileIcon;
      return (
        <>
          <Icon className="tree-icon tree-icon--file" />
          <span className="tree-label">
            <bdi>{row.file.name}</bdi>
          </span>
        </>
      );
    }
    case 'loading':
      return (
        <>
          <span className="spinner" aria-hidden="true" />
          <span className="tree-label">{t('projects.contents.loading')}</span>
        </>
      );
    case 'error':
      return (
        <>
          <WarningIcon className="tree-icon tree-icon--error" />
          <span className="tree-label tree-label--wrap">
            <code className="error-code">{row.error.code}</code> {errorText(row.error)} {t('projects.contents.retry')}
          </span>
        </>
      );
  }
}

/**
 * One row of the flat project tree (levels given by aria-level): a project, a folder, a block or
 * a file. Its accessible name is its own text; the three-dot button is the mouse's way to the
 * actions, which the keyboard opens with Shift+F10 or the context-menu key.
 */
export function TreeItem({ row, selected, tabStop, menuOpen, hasActions, onClick, onDoubleClick, onMenu }: TreeItemProps) {
  const { t } = useTranslation();
  const expanded = row.type === 'project' ? row.expanded : row.type === 'folder' ? row.expanded : null;
  const selectable = row.type !== 'loading' && row.type !== 'error';
  const item = (event: MouseEvent) => (event.currentTarget as HTMLElement).closest<HTMLElement>('[role="treeitem"]');
  const classes = ['tree-row', `tree-row--level-${row.level}`];
  if (selected) classes.push('tree-row--selected');
  return (
    <li
      role="treeitem"
      aria-level={row.level}
      aria-setsize={row.setsize}
      aria-posinset={row.posinset}
      aria-expanded={expanded === null ? undefined : expanded}
      aria-selected={selectable ? selected : undefined}
      aria-disabled={row.type === 'loading' ? true : undefined}
      aria-haspopup={hasActions ? 'menu' : undefined}
      tabIndex={tabStop === row.key ? 0 : -1}
      data-tree-key={row.key}
      data-testid={testIdOf(row)}
      className={`tree-item tree-item--${row.type}`}
      title={row.type === 'project' ? row.project.description || undefined : row.type === 'block' ? row.block.title || undefined : undefined}
    >
      <div
        className={classes.join(' ')}
        onClick={() => onClick(row)}
        onDoubleClick={() => onDoubleClick(row)}
        onContextMenu={(event) => {
          const target = item(event);
          if (!hasActions || !target) return;
          event.preventDefault();
          onMenu(row, target);
        }}
      >
        {expanded === null ? (
          <span className="tree-twisty tree-twisty--none" aria-hidden="true" />
        ) : (
          <ChevronIcon className={expanded ? 'tree-twisty tree-twisty--open' : 'tree-twisty'} />
        )}
        <RowContent row={row} />
        {hasActions ? (
          <button
            type="button"
            className={menuOpen ? 'tree-row__menu tree-row__menu--open' : 'tree-row__menu'}
            tabIndex={-1}
            aria-hidden="true"
            title={t('projects.actions.menuTitle')}
            onClick={(event) => {
              event.stopPropagation();
              const target = item(event);
              if (target) onMenu(row, target);
            }}
            onDoubleClick={(event) => event.stopPropagation()}
          >
            <MoreIcon size={14} />
          </button>
        ) : null}
      </div>
    </li>
  );
}
