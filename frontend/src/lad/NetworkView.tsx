/**
 * One network of a block in the graphical editor: its header (number, title, jump label,
 * breakpoint, problems, collapse), its comment, and its body: the LAD rung, the FBD diagram, or
 * the STL lines of a network that has no LAD shape, with the reason. Titles and comments follow
 * the direction of what the user typed (`dir="auto"`); the diagram is always left to right.
 */
import { memo, useEffect, useRef, useState, type KeyboardEvent, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { ChevronIcon } from '../ui/icons';
import type { Network } from './model';

/** Pixel heights of a network's parts (the virtual list positions networks with them). */
export const HEADER_H = 34;
export const COMMENT_LINE_H = 19;
export const STL_LINE_H = 17;
export const NETWORK_PAD = 14;
export const REASON_H = 24;

export function commentLines(network: Network): number {
  return network.comment ? network.comment.split('\n').length : 0;
}

export function stlBodyHeight(network: Network): number {
  const lines = (network.stl ?? '').split('\n').length;
  return lines * STL_LINE_H + 12 + (network.stl_reason ? REASON_H : 0);
}

export interface NetworkBreakpoint {
  condition: string | null;
  enabled: boolean;
  state: 'pending' | 'set' | 'refused' | 'offline';
}

export interface NetworkViewProps {
  network: Network;
  /** 1-based, as STEP 7 numbers networks. */
  number: number;
  /** Test ids: `network-<prefix>`. */
  prefix: string;
  collapsed: boolean;
  headerSelected: boolean;
  /** The CPU holds in this network. */
  held: boolean;
  breakpoint: NetworkBreakpoint | null;
  /** Problems of the network as a whole (not of one element). */
  problems: readonly { code: string; message: string; severity: string }[];
  elementProblems: number;
  /** The field of the header being edited (`title`, `comment`, `stl`, `label`), or null. */
  editing: string | null;
  reasonText: string | null;
  readOnly: boolean;
  body: ReactNode;
  onSelectHeader: () => void;
  onToggleCollapse: () => void;
  onEdit: (field: 'title' | 'comment' | 'stl' | 'label') => void;
  onCommit: (field: 'title' | 'comment' | 'stl' | 'label', value: string) => void;
  onCancelEdit: () => void;
  onHeaderMenu: (event: React.MouseEvent) => void;
}

function HeaderField({ value, multiline, label, onCommit, onCancel, testId, code }: { value: string; multiline: boolean; label: string; onCommit: (v: string) => void; onCancel: () => void; testId: string; code?: boolean }) {
  const [text, setText] = useState(value);
  const ref = useRef<HTMLInputElement & HTMLTextAreaElement>(null);
  const done = useRef(false);
  useEffect(() => {
    ref.current?.focus();
    ref.current?.select();
  }, []);
  const finish = (commit: boolean) => {
    if (done.current) return;
    done.current = true;
    if (commit) onCommit(text);
    else onCancel();
  };
  const onKeyDown = (event: KeyboardEvent) => {
    event.stopPropagation();
    if (event.key === 'Escape') {
      event.preventDefault();
      finish(false);
    } else if (event.key === 'Enter' && (!multiline || event.ctrlKey)) {
      event.preventDefault();
      finish(true);
    }
  };
  const common = {
    ref,
    value: text,
    'aria-label': label,
    dir: code ? 'ltr' : 'auto',
    spellCheck: !code,
    className: `input network__field${multiline ? ' network__field--multi' : ''}${code ? ' network__field--code' : ''}`,
    'data-testid': testId,
    onChange: (event: React.ChangeEvent<HTMLInputElement | HTMLTextAreaElement>) => setText(event.target.value),
    onKeyDown,
    onBlur: () => finish(true),
  };
  return multiline ? <textarea {...common} rows={Math.max(2, text.split('\n').length)} /> : <input {...common} />;
}

export const NetworkView = memo(function NetworkView(props: NetworkViewProps) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const { network, number, prefix } = props;
  const errors = props.problems.length + props.elementProblems;
  return (
    <section
      className={`network${props.held ? ' network--held' : ''}${props.headerSelected ? ' network--selected' : ''}`}
      data-testid={`network-${prefix}`}
      data-held={props.held ? 'true' : undefined}
      aria-label={t('lad.network.label', { number, title: network.title })}
    >
      <div className="network__header" dir={dir} lang={language}>
        <button
          type="button"
          className="network__toggle"
          aria-expanded={!props.collapsed}
          aria-label={props.collapsed ? t('lad.network.expand', { number }) : t('lad.network.collapse', { number })}
          onClick={props.onToggleCollapse}
          tabIndex={-1}
        >
          <ChevronIcon className={`network__chevron${props.collapsed ? '' : ' network__chevron--open'}`} />
        </button>
        <button
          type="button"
          className="network__name"
          id={`${prefix}-header`}
          tabIndex={props.headerSelected ? 0 : -1}
          aria-pressed={props.headerSelected}
          data-testid={`network-${prefix}-header`}
          onClick={props.onSelectHeader}
          onContextMenu={(event) => {
            event.preventDefault();
            props.onSelectHeader();
            props.onHeaderMenu(event);
          }}
          onDoubleClick={() => !props.readOnly && props.onEdit('title')}
        >
          {t('lad.network.name', { number })}
        </button>
        {props.breakpoint ? (
          <span
            className={`network__breakpoint network__breakpoint--${props.breakpoint.enabled ? props.breakpoint.state : 'disabled'}`}
            data-testid={`network-${prefix}-breakpoint`}
            title={props.breakpoint.condition ? t('lad.network.breakpointIf', { condition: props.breakpoint.condition }) : t('lad.network.breakpoint')}
            role="img"
            aria-label={props.breakpoint.condition ? t('lad.network.breakpointIf', { condition: props.breakpoint.condition }) : t('lad.network.breakpoint')}
          />
        ) : null}
        {props.editing === 'title' ? (
          <HeaderField value={network.title} multiline={false} label={t('lad.network.titleLabel', { number })} onCommit={(v) => props.onCommit('title', v)} onCancel={props.onCancelEdit} testId={`network-${prefix}-title-input`} />
        ) : (
          <span className="network__title" dir="auto" data-testid={`network-${prefix}-title`} onDoubleClick={() => !props.readOnly && props.onEdit('title')}>
            {network.title || <span className="network__placeholder">{t('lad.network.noTitle')}</span>}
          </span>
        )}
        {props.editing === 'label' ? (
          <HeaderField value={network.label ?? ''} multiline={false} label={t('lad.network.labelLabel', { number })} onCommit={(v) => props.onCommit('label', v)} onCancel={props.onCancelEdit} testId={`network-${prefix}-label-input`} code />
        ) : network.label ? (
          <code className="network__label" dir="ltr" title={t('lad.network.jumpLabel')} onDoubleClick={() => !props.readOnly && props.onEdit('label')}>
            {network.label}:
          </code>
        ) : null}
        {errors > 0 ? (
          <span className="network__problems" data-testid={`network-${prefix}-problems`} title={props.problems.map((p) => `${p.code}: ${p.message}`).join('\n')}>
            {t('lad.network.problems', { count: errors })}
          </span>
        ) : null}
      </div>
      {props.collapsed ? null : (
        <>
          {props.editing === 'comment' ? (
            <HeaderField value={network.comment} multiline label={t('lad.network.commentLabel', { number })} onCommit={(v) => props.onCommit('comment', v)} onCancel={props.onCancelEdit} testId={`network-${prefix}-comment-input`} />
          ) : network.comment ? (
            <p className="network__comment" dir="auto" data-testid={`network-${prefix}-comment`} onDoubleClick={() => !props.readOnly && props.onEdit('comment')}>
              {network.comment}
            </p>
          ) : null}
          {props.problems.length > 0 ? (
            <ul className="network__messages" dir={dir} lang={language}>
              {props.problems.map((problem, k) => (
                <li key={k} className={`network__message network__message--${problem.severity}`}>
                  <code className="error-code">{problem.code}</code> {problem.message}
                </li>
              ))}
            </ul>
          ) : null}
          {network.stl !== null ? (
            <div className="network__stl-kept" data-testid={`network-${prefix}-stl`}>
              {props.reasonText ? (
                <p className="network__reason" dir={dir} lang={language}>
                  {network.stl_reason ? <code className="error-code">{network.stl_reason}</code> : null} {props.reasonText}
                </p>
              ) : null}
              {props.editing === 'stl' ? (
                <HeaderField value={network.stl} multiline label={t('lad.network.stlLabel', { number })} onCommit={(v) => props.onCommit('stl', v)} onCancel={props.onCancelEdit} testId={`network-${prefix}-stl-input`} code />
              ) : (
                <pre className="network__stl" dir="ltr" onDoubleClick={() => !props.readOnly && props.onEdit('stl')}>
                  {network.stl}
                </pre>
              )}
            </div>
          ) : (
            <div className="network__body" dir="ltr">
              {props.body}
            </div>
          )}
        </>
      )}
    </section>
  );
});
