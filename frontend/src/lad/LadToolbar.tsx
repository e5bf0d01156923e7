/**
 * The diagram editor's toolbar: undo and redo, insert a network, TIA Portal's favourites (with
 * the empty box), how operands are shown, the status values' number format while online, the
 * instruction catalogue, and the notice of the last refused edit. It follows the interface
 * language's direction; the symbols on its buttons stay left to right.
 */
import { useTranslation } from 'react-i18next';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { Favourites, type Command } from './Catalogue';
import type { CatalogueItem } from './elements';
import type { OperandDisplay } from './operands';

export const DISPLAYS: readonly OperandDisplay[] = ['both', 'symbolic', 'absolute'];

export interface LadToolbarProps {
  editable: boolean;
  canUndo: boolean;
  canRedo: boolean;
  onUndo: () => void;
  onRedo: () => void;
  /** Absent: the networks are given (S7-Graph's conditions), none can be added. */
  onAddNetwork?: () => void;
  favourites: readonly CatalogueItem[];
  emptyBox: CatalogueItem;
  onInsert: (item: CatalogueItem) => void;
  onCommand: (command: Command) => void;
  onDragging: (dragging: boolean) => void;
  display: OperandDisplay;
  onDisplay: (display: OperandDisplay) => void;
  /** Hexadecimal values (online only; null offline). */
  hex: boolean | null;
  onHex: (hex: boolean) => void;
  catalogueOpen: boolean;
  onCatalogue: (open: boolean) => void;
  notice: string | null;
  onNoticeEnd: () => void;
}

export function LadToolbar(props: LadToolbarProps) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const { editable, display, hex } = props;
  const displayIndex = DISPLAYS.indexOf(display);
  return (
    <div className="lad-toolbar" role="toolbar" aria-label={t('lad.toolbar.label')} dir={dir} lang={language}>
      <button type="button" className="lad-tool" disabled={!editable || !props.canUndo} onClick={props.onUndo} data-testid="lad-undo" aria-keyshortcuts="Control+Z" title={`${t('lad.toolbar.undo')} (Ctrl+Z)`}>
        {t('lad.toolbar.undo')}
      </button>
      <button type="button" className="lad-tool" disabled={!editable || !props.canRedo} onClick={props.onRedo} data-testid="lad-redo" aria-keyshortcuts="Control+Y" title={`${t('lad.toolbar.redo')} (Ctrl+Y)`}>
        {t('lad.toolbar.redo')}
      </button>
      <span className="lad-toolbar__sep" />
      {props.onAddNetwork ? (
        <>
          <button type="button" className="lad-tool" disabled={!editable} onClick={props.onAddNetwork} data-testid="lad-insert-network" aria-keyshortcuts="Control+R" title={`${t('lad.toolbar.addNetwork')} (Ctrl+R)`}>
            {t('lad.toolbar.addNetwork')}
          </button>
          <span className="lad-toolbar__sep" />
        </>
      ) : null}
      <Favourites
        items={props.favourites}
        disabled={!editable}
        onInsert={props.onInsert}
        onCommand={props.onCommand}
        onDragStart={() => props.onDragging(true)}
        onDragEnd={() => props.onDragging(false)}
      />
      <button type="button" className="lad-tool" disabled={!editable} onClick={() => props.onInsert(props.emptyBox)} data-testid="favourite-emptyBox" aria-keyshortcuts="Shift+F5" title={`${t('lad.items.emptyBox')} (Shift+F5)`} aria-label={t('lad.items.emptyBox')}>
        <span className="lad-tool__symbol" dir="ltr">
          [??]
        </span>
      </button>
      <span className="lad-toolbar__sep" />
      <button
        type="button"
        className="lad-tool"
        data-testid="lad-display"
        data-display={display}
        onClick={() => props.onDisplay(DISPLAYS[(displayIndex + 1) % DISPLAYS.length] ?? 'both')}
        title={t('lad.toolbar.displayTitle')}
      >
        {t(`lad.display.${display}`)}
      </button>
      {hex !== null ? (
        <button type="button" className="lad-tool" aria-pressed={hex} data-testid="lad-hex" title={t('lad.toolbar.formatTitle')} onClick={() => props.onHex(!hex)}>
          {hex ? t('debug.status.hex') : t('debug.status.dec')}
        </button>
      ) : null}
      <button type="button" className="lad-tool" aria-pressed={props.catalogueOpen} data-testid="lad-catalogue-toggle" onClick={() => props.onCatalogue(!props.catalogueOpen)}>
        {t('lad.catalogue.title')}
      </button>
      {props.notice ? (
        <span className="lad-toolbar__notice" role="status" onAnimationEnd={props.onNoticeEnd}>
          {props.notice}
        </span>
      ) : null}
    </div>
  );
}
