/**
 * The instructions of the LAD/FBD editors: the favourites bar (TIA Portal's, with its Shift+F
 * shortcuts) and the full catalogue with search, grouped as TIA groups them. A click inserts at
 * the selection; an entry can also be dragged onto a wire position of a rung. The element names
 * are translated; box names (S_ODT, MOVE, CMP>=I) stay as the standard writes them.
 */
import { useEffect, useId, useMemo, useRef, useState, type DragEvent, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { GROUPS, searchCatalogue, type CatalogueItem } from './elements';

/** The drag payload type of a catalogue entry (its key). */
export const CATALOGUE_MIME = 'application/x-nasaq-lad-item';

export type Command = 'openBranch' | 'closeBranch';

export interface FavouritesProps {
  items: readonly CatalogueItem[];
  disabled: boolean;
  onInsert: (item: CatalogueItem) => void;
  onCommand: (command: Command) => void;
  onDragStart: () => void;
  onDragEnd: () => void;
}

export function itemName(t: (key: string) => string, item: CatalogueItem): string {
  return item.nameKey ? t(item.nameKey) : item.symbol;
}

function startDrag(event: DragEvent, item: CatalogueItem, begin: () => void) {
  event.dataTransfer.setData(CATALOGUE_MIME, item.key);
  event.dataTransfer.setData('text/plain', item.symbol);
  event.dataTransfer.effectAllowed = 'copy';
  begin();
}

/** TIA Portal's favourites: NO and NC contact, coil, empty box, open and close branch. */
export function Favourites({ items, disabled, onInsert, onCommand, onDragStart, onDragEnd }: FavouritesProps) {
  const { t } = useTranslation();
  return (
    <div className="lad-favourites" role="group" aria-label={t('lad.toolbar.favourites')}>
      {items.map((item) => (
        <button
          key={item.key}
          type="button"
          className="lad-tool"
          disabled={disabled}
          draggable={!disabled}
          data-testid={`favourite-${item.key}`}
          title={`${itemName(t, item)}${item.shortcut ? ` (${item.shortcut})` : ''}`}
          aria-label={itemName(t, item)}
          aria-keyshortcuts={item.shortcut}
          onClick={() => onInsert(item)}
          onDragStart={(event) => startDrag(event, item, onDragStart)}
          onDragEnd={onDragEnd}
        >
          <span className="lad-tool__symbol" dir="ltr">
            {item.symbol}
          </span>
        </button>
      ))}
      <button type="button" className="lad-tool" disabled={disabled} data-testid="favourite-openBranch" title={`${t('lad.toolbar.openBranch')} (Shift+F8)`} aria-label={t('lad.toolbar.openBranch')} aria-keyshortcuts="Shift+F8" onClick={() => onCommand('openBranch')}>
        <span className="lad-tool__symbol" dir="ltr">
          ↳
        </span>
      </button>
      <button type="button" className="lad-tool" disabled={disabled} data-testid="favourite-closeBranch" title={`${t('lad.toolbar.closeBranch')} (Shift+F9)`} aria-label={t('lad.toolbar.closeBranch')} aria-keyshortcuts="Shift+F9" onClick={() => onCommand('closeBranch')}>
        <span className="lad-tool__symbol" dir="ltr">
          ↱
        </span>
      </button>
    </div>
  );
}

export interface CataloguePanelProps {
  items: readonly CatalogueItem[];
  disabled: boolean;
  /** Grows when Insert asks for the search field. */
  focusRequest: number;
  onInsert: (item: CatalogueItem) => void;
  onDragStart: () => void;
  onDragEnd: () => void;
  onClose: () => void;
}

/** The full catalogue: a search field and the groups; Enter in the field inserts the first match. */
export function CataloguePanel({ items, disabled, focusRequest, onInsert, onDragStart, onDragEnd, onClose }: CataloguePanelProps) {
  const { t } = useTranslation();
  const [search, setSearch] = useState('');
  const searchId = useId();
  const input = useRef<HTMLInputElement>(null);
  useEffect(() => {
    if (focusRequest > 0) input.current?.focus();
  }, [focusRequest]);
  const found = useMemo(() => searchCatalogue(items, search, (item) => itemName(t, item)), [items, search, t]);
  const onKeyDown = (event: KeyboardEvent<HTMLInputElement>) => {
    event.stopPropagation();
    if (event.key === 'Enter' && found[0] && !disabled) {
      event.preventDefault();
      onInsert(found[0]);
      setSearch('');
    } else if (event.key === 'Escape') {
      event.preventDefault();
      onClose();
    }
  };
  return (
    <aside className="lad-catalogue" aria-label={t('lad.catalogue.title')} data-testid="lad-catalogue">
      <div className="lad-catalogue__head">
        <label htmlFor={searchId} className="lad-catalogue__title">
          {t('lad.catalogue.title')}
        </label>
        <input
          id={searchId}
          ref={input}
          type="search"
          className="input lad-catalogue__search"
          placeholder={t('lad.catalogue.search')}
          value={search}
          dir="auto"
          data-testid="lad-catalogue-search"
          onChange={(event) => setSearch(event.target.value)}
          onKeyDown={onKeyDown}
        />
      </div>
      <div className="lad-catalogue__groups">
        {GROUPS.map((group) => {
          const inGroup = found.filter((item) => item.group === group);
          if (inGroup.length === 0) return null;
          return (
            <section key={group} className="lad-catalogue__group" aria-label={t(`lad.groups.${group}`)}>
              <h3 className="lad-catalogue__group-title">{t(`lad.groups.${group}`)}</h3>
              <ul className="lad-catalogue__list">
                {inGroup.map((item) => (
                  <li key={item.key}>
                    <button
                      type="button"
                      className="lad-catalogue__item"
                      disabled={disabled}
                      draggable={!disabled}
                      data-testid={`catalogue-${item.key}`}
                      onClick={() => onInsert(item)}
                      onDragStart={(event) => startDrag(event, item, onDragStart)}
                      onDragEnd={onDragEnd}
                    >
                      <span className="lad-catalogue__symbol" dir="ltr">
                        {item.symbol}
                      </span>
                      {item.nameKey ? <span className="lad-catalogue__name">{itemName(t, item)}</span> : null}
                    </button>
                  </li>
                ))}
              </ul>
            </section>
          );
        })}
        {found.length === 0 ? <p className="lad-catalogue__empty">{t('lad.catalogue.none')}</p> : null}
      </div>
    </aside>
  );
}
