/**
 * The graphical LAD/FBD editor of one file: its blocks as a virtualised list of networks, the
 * favourites bar and the instruction catalogue, editing by mouse and by keyboard alone (TIA
 * Portal's keys), operands typed on the elements with completion, undo/redo, and online the
 * program status (power flow), network breakpoints and modify/force from the diagram.
 *
 * The model comes from {@link useLadDocument} (the file's text read by the server, every edit
 * written back to the text at once); this component holds only the view's state: selection,
 * the field being typed, collapsed networks, the display of operands.
 */
import { useCallback, useEffect, useMemo, useRef, useState, useSyncExternalStore, type DragEvent, type KeyboardEvent, type MouseEvent, type ReactNode } from 'react';
import { createPortal } from 'react-dom';
import { useTranslation } from 'react-i18next';
import type { Problem } from '../api/monitorClient';
import { useMonitor, useSession } from '../cpu/SessionContext';
import { NetworkList, type NetworkListHandle } from '../diagram/NetworkList';
import { arrowDirection, nextInDirection, type NavItem } from '../diagram/navigation';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { outlines } from '../editor/intellisense/outlineStore';
import { BreakpointDialog } from '../editor/monitoring/BreakpointDialog';
import { breakpoints, breakpointKey } from '../editor/monitoring/breakpointStore';
import { RowMenu, type MenuAction } from '../projects/RowMenu';
import { elementMenu, networkMenu } from './menus';
import { blockLines, problemsByNetwork, type Problems } from './problems';
import { FieldEditor, type Editing } from './FieldEditor';
import { useProjectContents } from '../projects/projectContents';
import { readStored, usePersistentFlag, writeStored } from '../ui/usePersistentState';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { CATALOGUE_MIME, CataloguePanel, type Command } from './Catalogue';
import { DISPLAYS, LadToolbar } from './LadToolbar';
import { copyNetworks, pasteNetworks } from './clipboard';
import { isPlaceholder } from './edits';
import { callInterface, callItems, connectPin } from './calls';
import { CATALOGUE_ITEMS, catalogueItem, emptyBox, type CatalogueItem } from './elements';
import { STATUS_BITS, withField } from './fields';
import { rungSize } from './geometry';
import { fbdBodyHeight, fbdLayoutVersion, subscribeFbdLayouts } from './fbdGeometry';
import { FbdView } from './FbdView';
import { navItemsOf } from './positions';
import { placeOfLine } from './reveal';
import type { RevealRequest } from '../editor/EditorTabsContext';
import * as commands from './ladCommands';
import { LadRung, type RungProblem } from './LadRung';
import { layoutOf } from './layoutCache';
import type { LadBlock, Network } from './model';
import { HEADER_H, COMMENT_LINE_H, NETWORK_PAD, NetworkView, commentLines, stlBodyHeight, type NetworkBreakpoint } from './NetworkView';
import { ModifyDialog } from './ModifyDialog';
import type { Complete } from './OperandEditor';
import { isInput, listCompleter, operandCompleter, operandLabel, outlineBlock, symbolIndex, type OperandDisplay } from './operands';
import { networkFlows } from './status';
import { findById, type Selection } from './ladCommands';
import type { LadDocument } from './useLadDocument';
import { useLadMonitoring, type LadMonitoring } from './useLadMonitoring';
import './lad.css';

const BLOCK_ROW_H = 46;
const END_ROW_H = 44;
const DISPLAY_KEY = 'nasaq.lad.display';
const CATALOGUE_KEY = 'nasaq.lad.catalogue';

type Row = { kind: 'block'; block: number } | { kind: 'network'; block: number; network: number } | { kind: 'end'; block: number };

export interface LadEditorProps {
  doc: LadDocument;
  /** The file's text (diagnostics are placed on blocks by its lines). */
  text: string;
  projectId: number | null;
  /** The project file (`Motor.lad`), for diagnostics, breakpoints and the hold. */
  file: string | null;
  mode: 'LAD' | 'FBD';
  active: boolean;
  /** A view of an STL source (nothing can be changed). */
  readOnly: boolean;
  /** The tab's monitoring switch is on. */
  monitoring: boolean;
  onMonitorProblem: (problem: Problem | null) => void;
  /** A place asked for (a diagnostic, a cross-reference, a lesson check): its network is selected. */
  reveal?: RevealRequest | null;
  /**
   * Embedded in another editor (S7-Graph's conditions and permanent instructions): no block
   * header and end rows; `fixedNetworks` also offers no adding of networks. `status` gives the
   * element states from the host's monitoring instead of the editor opening the block itself.
   */
  embedded?: { fixedNetworks: boolean; status: LadMonitoring | null; label: string; problems?: Problems };
}

interface MenuState {
  anchor: Element;
  label: string;
  actions: MenuAction[];
}

function storedDisplay(): OperandDisplay {
  const stored = readStored(DISPLAY_KEY);
  return DISPLAYS.includes(stored as OperandDisplay) ? (stored as OperandDisplay) : 'both';
}

/** The reveal requests already applied (each request is a new object). */
const revealsDone = new WeakSet<RevealRequest>();

function prefixOf(block: number, network: number): string {
  return `${block + 1}-${network + 1}`;
}

export function LadEditor({ doc, text, projectId, file, mode, active, readOnly, monitoring, onMonitorProblem, reveal = null, embedded }: LadEditorProps) {
  const { t, i18n } = useTranslation();
  const { dir, language } = useUiLanguage();
  const blocks: readonly LadBlock[] = doc.blocks ?? [];
  const editable = !readOnly && doc.state.status === 'ready' && !doc.pending;
  const list = useRef<NetworkListHandle>(null);
  const root = useRef<HTMLDivElement>(null);
  const [selection, setSelection] = useState<Selection>({ block: 0, network: 0, id: null, point: null });
  const [editing, setEditing] = useState<Editing | null>(null);
  const [collapsed, setCollapsed] = useState<ReadonlySet<string>>(new Set());
  const [menu, setMenu] = useState<MenuState | null>(null);
  // Embedded editors (S7-Graph's conditions) are small: their catalogue starts closed.
  const [catalogueOpen, setCatalogueOpen] = useState(() => !embedded && readStored(CATALOGUE_KEY) !== 'false');
  const [catalogueFocus, setCatalogueFocus] = useState(0);
  const [display, setDisplayState] = useState<OperandDisplay>(storedDisplay);
  const [dragging, setDragging] = useState(false);
  const [visible, setVisible] = useState<{ first: number; last: number }>({ first: 0, last: 0 });
  const [breakpointDialog, setBreakpointDialog] = useState<{ block: string; network: number } | null>(null);
  const [notice, setNotice] = useState<string | null>(null);
  /** The operand whose value the Modify dialog asks for. */
  const [modifying, setModifying] = useState<string | null>(null);
  const wantFocus = useRef(false);
  /** An element of this editor by its id (several editors can be on a page: S7-Graph's step view). */
  const byId = useCallback((id: string) => root.current?.querySelector<HTMLElement>(`[id="${id}"]`) ?? null, []);
  const message = useDiagnosticMessage();
  const { command } = useSession();

  const setDisplay = (next: OperandDisplay) => {
    setDisplayState(next);
    writeStored(DISPLAY_KEY, next);
  };
  const toggleCatalogue = (open: boolean) => {
    setCatalogueOpen(open);
    if (!embedded) writeStored(CATALOGUE_KEY, String(open));
  };

  // -- the project: outline (symbols, members, blocks to call) and diagnostics ------------------
  const outline = useSyncExternalStore(
    outlines.subscribe,
    () => (projectId === null ? null : outlines.get(projectId)),
    () => null,
  );
  const symbols = useMemo(() => symbolIndex(outline), [outline]);
  const contents = useProjectContents(projectId);
  const items = useMemo(() => [...CATALOGUE_ITEMS, ...callItems(outline)], [outline]);
  const favourites = useMemo(
    () => ['contact', 'contactNC', 'coil:='].map((key) => catalogueItem(key)).filter((item): item is CatalogueItem => !!item),
    [],
  );
  const emptyBoxItem = useMemo<CatalogueItem>(() => ({ key: 'emptyBox', group: 'move', symbol: '??', nameKey: 'lad.items.emptyBox', final: false, make: emptyBox, shortcut: 'Shift+F5' }), []);

  // -- rows of the list --------------------------------------------------------------------------
  const rows = useMemo(() => {
    const out: Row[] = [];
    blocks.forEach((block, b) => {
      if (!embedded) out.push({ kind: 'block', block: b });
      block.networks.forEach((_, n) => out.push({ kind: 'network', block: b, network: n }));
      if (!embedded?.fixedNetworks) out.push({ kind: 'end', block: b });
    });
    return out;
  }, [blocks, embedded]);
  const rowOf = useCallback((b: number, n: number) => rows.findIndex((row) => row.kind === 'network' && row.block === b && row.network === n), [rows]);

  // FBD heights are known once elkjs has laid a network out: the list is measured again then.
  const fbdVersion = useSyncExternalStore(subscribeFbdLayouts, fbdLayoutVersion, fbdLayoutVersion);
  const bodyHeight = useCallback(
    (network: Network) => {
      if (network.stl !== null) return stlBodyHeight(network);
      if (mode === 'FBD') return fbdBodyHeight(network);
      return rungSize(layoutOf(network)).height + 16;
    },
    [mode, fbdVersion],
  );
  const heightOf = useCallback(
    (index: number) => {
      const row = rows[index];
      if (!row) return 0;
      if (row.kind === 'block') return BLOCK_ROW_H;
      if (row.kind === 'end') return END_ROW_H;
      const network = blocks[row.block]?.networks[row.network];
      if (!network) return 0;
      const key = `${row.block}:${row.network}`;
      if (collapsed.has(key)) return HEADER_H + NETWORK_PAD;
      const editingHere = editing?.block === row.block && editing.network === row.network && editing.id === 'header';
      const commentHeight = editingHere && editing.field === 'comment' ? Math.max(3, commentLines(network) + 1) * COMMENT_LINE_H + 8 : commentLines(network) * COMMENT_LINE_H;
      const stlEditing = editingHere && editing.field === 'stl' ? 2 * 17 : 0;
      return HEADER_H + commentHeight + bodyHeight(network) + stlEditing + NETWORK_PAD;
    },
    [rows, blocks, collapsed, editing, bodyHeight],
  );

  // -- which block and networks are on screen (monitoring follows them) --------------------------
  const onVisibleChange = useCallback((first: number, last: number) => setVisible({ first, last }), []);
  const shown = useMemo(() => {
    let block: number | null = null;
    const networks: number[] = [];
    for (let index = visible.first; index <= visible.last; index += 1) {
      const row = rows[index];
      if (!row || row.kind !== 'network') continue;
      if (block === null) block = row.block;
      if (row.block === block) networks.push(row.network + 1);
    }
    if (block === null && blocks.length > 0) block = 0;
    return { block, networks };
  }, [visible, rows, blocks.length]);
  const shownBlock = shown.block === null ? null : (blocks[shown.block] ?? null);
  const resolved = shownBlock ? outlineBlock(outline, shownBlock.name) : null;
  const ownMonitor = useLadMonitoring({
    enabled: !embedded && monitoring && active && projectId !== null && file !== null,
    projectId: projectId ?? -1,
    file: file ?? '',
    block: shownBlock?.name ?? null,
    networks: shown.networks,
    resolvedName: resolved ? `${resolved.kind}${resolved.number}` : null,
    onProblem: onMonitorProblem,
  });
  const monitor = embedded ? (embedded.status ?? OFFLINE) : ownMonitor;
  const forcedList = useMonitor((state) => state.cpu?.forced ?? null);
  const forced = useMemo(() => {
    if (!monitor.online || !forcedList || forcedList.length === 0) return undefined;
    const set = new Set(forcedList.map((f) => f.address.replace(/\s+/g, '').toUpperCase()));
    return (operand: string) => {
      const label = operandLabel(operand, 'absolute', symbols).main;
      return set.has(label.replace(/\s+/g, '').toUpperCase());
    };
  }, [monitor.online, forcedList, symbols]);
  // The status values in decimal or hexadecimal: the same choice as the STL status columns'.
  const [hex, setHex] = usePersistentFlag('nasaq.debug.accuHex', false);
  const formatValue = useCallback(
    (value: unknown) => {
      if (typeof value === 'boolean') return value ? '1' : '0';
      if (typeof value === 'number') {
        if (!Number.isInteger(value)) return value.toPrecision(6);
        return hex ? `16#${(value >>> 0).toString(16).toUpperCase()}` : String(value);
      }
      return String(value);
    },
    [hex],
  );

  // -- diagnostics on elements and networks ------------------------------------------------------
  const blockStarts = useMemo(() => blockLines(text), [text]);
  const ownProblems = useMemo(() => problemsByNetwork(contents?.diagnostics ?? [], file, blockStarts, message), [contents?.diagnostics, file, blockStarts, message]);
  const problems = embedded?.problems ?? ownProblems;

  // -- breakpoints --------------------------------------------------------------------------------
  const breakpointList = useSyncExternalStore(breakpoints.subscribe, breakpoints.list, breakpoints.list);
  const reports = useMonitor((state) => state.breakpoints);
  const connected = useMonitor((state) => state.connection === 'open');
  const breakpointOf = useCallback(
    (block: LadBlock, number: number): NetworkBreakpoint | null => {
      if (projectId === null || !file) return null;
      const found = breakpointList.find((bp) => bp.projectId === projectId && bp.file === file && bp.block === block.name && bp.line === number);
      if (!found) return null;
      const report = reports[breakpointKey(projectId, file, number, block.name)];
      return { condition: found.condition, enabled: found.enabled, state: !connected ? 'offline' : (report?.state ?? 'pending') };
    },
    [breakpointList, reports, connected, projectId, file],
  );

  // -- applying commands --------------------------------------------------------------------------
  const selectionRef = useRef(selection);
  selectionRef.current = selection;
  const apply = useCallback(
    (make: (blocks: readonly LadBlock[], selection: Selection) => commands.Outcome | null, label: string) => {
      if (!editable) return;
      let outcome: commands.Outcome | null = null;
      doc.edit((current) => {
        outcome = make(current, selectionRef.current);
        return outcome ? outcome.blocks : current;
      }, label);
      const done = outcome as commands.Outcome | null;
      if (!done) return;
      wantFocus.current = true;
      setSelection(done.selection);
      if (done.edit) setEditing({ block: done.selection.block, network: done.selection.network, id: done.edit.id, field: done.edit.field });
    },
    [doc, editable],
  );

  const insert = useCallback((item: CatalogueItem) => apply((b, s) => commands.insertItem(b, s, item), t('lad.undo.insert', { what: item.symbol })), [apply, t]);
  const runCommand = useCallback((which: Command) => apply((b, s) => commands.branchCommand(b, s, which), t(`lad.toolbar.${which}`)), [apply, t]);
  const addNetwork = useCallback(() => apply((b, s) => commands.insertNetwork(b, s), t('lad.undo.addNetwork')), [apply, t]);

  // -- selection and focus -------------------------------------------------------------------------
  const select = useCallback((next: Selection) => {
    wantFocus.current = true;
    setSelection(next);
    setMenu(null);
  }, []);

  // A place asked for from outside (by line, network, element): selected once the blocks are
  // read, once per request (a view switched back and forth does not jump there again).
  useEffect(() => {
    if (!reveal || revealsDone.has(reveal) || blocks.length === 0) return;
    revealsDone.add(reveal);
    const place = placeOfLine(text, reveal.line, reveal.network);
    const network = blocks[place.block]?.networks[place.network];
    if (!network) return;
    const id = reveal.element && findById(network, reveal.element) ? reveal.element : null;
    select({ block: place.block, network: place.network, id, point: null });
  }, [reveal, blocks, text, select]);

  useEffect(() => {
    if (!wantFocus.current || editing || !active) return;
    wantFocus.current = false;
    const row = rowOf(selection.block, selection.network);
    if (row >= 0) list.current?.scrollToIndex(row);
    const prefix = prefixOf(selection.block, selection.network);
    const target = selection.id ? `lad-${prefix}-${selection.id}` : `${prefix}-header`;
    requestAnimationFrame(() => {
      // A field opened meanwhile (a double click right after a click) keeps the focus.
      if (document.activeElement?.closest('.operand-editor, .network__field')) return;
      const element = byId(target) as (HTMLElement & SVGElement) | null;
      element?.focus({ preventScroll: true });
      if (!element) root.current?.querySelector<HTMLElement>('.lad-editor__list')?.focus();
    });
  }, [selection, editing, rowOf, active, blocks]);

  // Keep the selection inside the model when networks go away (undo, delete).
  useEffect(() => {
    const block = blocks[selection.block];
    if (!block) return;
    if (selection.network >= block.networks.length && block.networks.length > 0) setSelection({ ...selection, network: block.networks.length - 1, id: null, point: null });
    else {
      const network = block.networks[selection.network];
      if (network && selection.id && !findById(network, selection.id)) setSelection({ ...selection, id: null, point: null });
    }
  }, [blocks, selection]);

  // -- keyboard -------------------------------------------------------------------------------------
  const navItems = useCallback(
    (b: number, n: number): NavItem<string>[] => {
      const network = blocks[b]?.networks[n];
      return network ? navItemsOf(network, mode) : [];
    },
    [blocks, mode],
  );

  const moveSelection = useCallback(
    (key: string) => {
      const direction = arrowDirection(key);
      if (!direction) return false;
      const { block: b, network: n, id } = selectionRef.current;
      const navs = navItems(b, n);
      const from = navs.find((item) => item.key === (id ?? 'header'));
      const next = from ? nextInDirection(navs, from, direction) : null;
      if (next) {
        select({ block: b, network: n, id: next.key === 'header' ? null : next.key, point: null });
        return true;
      }
      if (direction === 'up' || direction === 'down') {
        // Leave the network: the neighbouring network's header (down) or last element (up).
        const block = blocks[b];
        const target = direction === 'down' ? n + 1 : n - 1;
        if (block && target >= 0 && target < block.networks.length) {
          if (direction === 'down') select({ block: b, network: target, id: null, point: null });
          else {
            const items = navItems(b, target).filter((item) => item.key !== 'header');
            const last = items.sort((x, y) => x.y - y.y || x.x - y.x)[0];
            select({ block: b, network: target, id: last?.key ?? null, point: null });
          }
          return true;
        }
        const otherBlock = direction === 'down' ? b + 1 : b - 1;
        const other = blocks[otherBlock];
        if (other && other.networks.length > 0) {
          select({ block: otherBlock, network: direction === 'down' ? 0 : other.networks.length - 1, id: null, point: null });
          return true;
        }
      }
      return false;
    },
    [blocks, navItems, select],
  );

  const editSelected = useCallback(() => {
    const { block: b, network: n, id } = selectionRef.current;
    const network = blocks[b]?.networks[n];
    if (!network || readOnly) return;
    if (!id) {
      setEditing({ block: b, network: n, id: 'header', field: network.stl !== null ? 'stl' : 'title' });
      return;
    }
    const element = findById(network, id);
    if (!element) return;
    const field = element.kind === 'box' ? 'name' : element.kind === 'status' ? 'bit' : element.kind === 'jump' ? 'label' : 'operand';
    if (element.kind === 'not' || element.kind === 'ret' || element.kind === 'parallel' || (element.kind === 'coil' && element.coil === 'SAVE')) return;
    setEditing({ block: b, network: n, id, field });
  }, [blocks, readOnly]);

  const toggleBreakpoint = useCallback(() => {
    const { block: b, network: n } = selectionRef.current;
    const block = blocks[b];
    if (!block || projectId === null || !file) return;
    breakpoints.toggle(projectId, file, n + 1, block.name);
  }, [blocks, projectId, file]);

  const clipboardAction = useCallback(
    (kind: 'copy' | 'cut' | 'paste') => {
      const { block: b, network: n, id } = selectionRef.current;
      const block = blocks[b];
      const network = block?.networks[n];
      if (!block) return;
      if (kind === 'paste') {
        void pasteNetworks().then((pasted) => {
          if (pasted && pasted.length > 0) apply((all, s) => commands.insertNetwork(all, s, pasted), t('lad.undo.paste'));
          else setNotice(t('lad.notice.nothingToPaste'));
        });
        return;
      }
      if (!network || id) return;
      copyNetworks(block, [network]);
      if (kind === 'cut') apply((all, s) => commands.deleteNetwork(all, s), t('lad.undo.cut'));
    },
    [blocks, apply, t],
  );

  const onKeyDown = useCallback(
    (event: KeyboardEvent<HTMLDivElement>) => {
      if (event.defaultPrevented || editing) return;
      const target = event.target as HTMLElement;
      if (target.closest('input, textarea, .operand-editor, .lad-catalogue')) return;
      const ctrl = event.ctrlKey || event.metaKey;
      const key = event.key;
      let handled = true;
      if (ctrl && !event.shiftKey && key.toLowerCase() === 'z') {
        wantFocus.current = true;
        doc.undo();
      } else if (ctrl && (key.toLowerCase() === 'y' || (event.shiftKey && key.toLowerCase() === 'z'))) {
        wantFocus.current = true;
        doc.redo();
      }
      else if (ctrl && key.toLowerCase() === 'c') clipboardAction('copy');
      else if (ctrl && key.toLowerCase() === 'x') clipboardAction('cut');
      else if (ctrl && key.toLowerCase() === 'v') clipboardAction('paste');
      else if (ctrl && key.toLowerCase() === 'r') addNetwork();
      else if (event.altKey && (key === 'ArrowUp' || key === 'ArrowDown') && !selectionRef.current.id) apply((b, s) => commands.moveNetwork(b, s, key === 'ArrowUp' ? -1 : 1), t('lad.undo.moveNetwork'));
      else if (event.altKey && (key === 'ArrowLeft' || key === 'ArrowRight')) apply((b, s) => commands.shiftSelected(b, s, key === 'ArrowLeft' ? -1 : 1), t('lad.undo.move'));
      else if (!ctrl && !event.altKey && arrowDirection(key)) handled = moveSelection(key);
      else if (event.shiftKey && key === 'F2') insert(catalogueItem('contact') as CatalogueItem);
      else if (event.shiftKey && key === 'F3') insert(catalogueItem('contactNC') as CatalogueItem);
      else if (event.shiftKey && key === 'F7') insert(catalogueItem('coil:=') as CatalogueItem);
      else if (event.shiftKey && key === 'F5') insert(emptyBoxItem);
      else if (event.shiftKey && key === 'F8') runCommand('openBranch');
      else if (event.shiftKey && key === 'F9') runCommand('closeBranch');
      else if (!event.shiftKey && key === 'F9') toggleBreakpoint();
      else if (key === 'Enter' || key === 'F2') editSelected();
      else if (key === 'Delete') apply((b, s) => commands.deleteSelected(b, s), t('lad.undo.delete'));
      else if (key === 'Insert') {
        toggleCatalogue(true);
        setCatalogueFocus((n) => n + 1);
      } else if (key === 'Escape') select({ ...selectionRef.current, point: null });
      else handled = false;
      if (handled) {
        event.preventDefault();
        event.stopPropagation();
      }
    },
    [editing, doc, clipboardAction, addNetwork, apply, t, moveSelection, insert, emptyBoxItem, runCommand, toggleBreakpoint, editSelected, select],
  );

  // -- field editing ---------------------------------------------------------------------------------
  const commitField = useCallback(
    (edit: Editing, text: string) => {
      setEditing(null);
      wantFocus.current = true;
      if (edit.id === 'header') {
        const field = edit.field;
        const value = field === 'title' ? text.replace(/\s*\n\s*/g, ' ').trim() : field === 'label' ? text.trim() : text;
        if (field === 'label' && value !== '' && !/^[A-Za-z_]\w*$/.test(value)) {
          setNotice(t('lad.notice.badLabel', { label: value }));
          return;
        }
        const change: Partial<Network> = field === 'title' ? { title: value } : field === 'comment' ? { comment: value.replace(/\s+$/, '') } : field === 'label' ? { label: value || null } : { stl: value };
        apply((b) => commands.changeNetwork(b, { block: edit.block, network: edit.network, id: null, point: null }, change), t(`lad.undo.${field}`));
        return;
      }
      const network = blocks[edit.block]?.networks[edit.network];
      const element = network ? findById(network, edit.id) : null;
      if (!element) return;
      const result = withField(element, edit.field, text, (name) => callInterface(name, outline));
      if ('error' in result) {
        setNotice(t(`lad.notice.${result.error}`, { text }));
        return;
      }
      apply((b) => commands.replaceSelected(b, { block: edit.block, network: edit.network, id: edit.id, point: null }, edit.id, result.element), t('lad.undo.operand'));
      // A box that just got its type asks for the operand above it.
      if (result.element.kind === 'box' && edit.field === 'name' && result.element.instance && isPlaceholder(result.element.instance)) {
        setEditing({ ...edit, field: 'instance' });
      }
    },
    [apply, blocks, t, outline],
  );

  const completerFor = useCallback(
    (edit: Editing, block: LadBlock): Complete => {
      if (edit.field === 'name') {
        return listCompleter(items.filter((item) => item.key.startsWith('box:') || item.key.startsWith('call:')).map((item) => ({ label: item.symbol, insert: item.key.replace(/^(box|call):/, '') })));
      }
      if (edit.field === 'bit') return listCompleter(STATUS_BITS.map((bit) => ({ label: bit, insert: bit })));
      if (edit.field === 'label') {
        const labels = block.networks.map((network) => network.label).filter((label): label is string => !!label);
        return listCompleter(labels.map((label) => ({ label, insert: label })));
      }
      return operandCompleter(outline, outlineBlock(outline, block.name), i18n.language);
    },
    [items, outline, i18n.language],
  );

  // -- context menus ---------------------------------------------------------------------------------
  const onElementMenu = useCallback(
    (b: number, n: number, id: string, event: MouseEvent) => {
      const network = blocks[b]?.networks[n];
      const element = network ? findById(network, id) : null;
      if (!element) return;
      const at: Selection = { block: b, network: n, id, point: null };
      const actions = elementMenu({
        t,
        element,
        editable,
        online: monitor.online,
        callPins: element.kind === 'box' ? callInterface(element.name, outline) : null,
        isInput: (operand) => isInput(operand, symbols.byName),
        on: {
          edit: editSelected,
          negate: () => {
            if (element.kind === 'contact' || element.kind === 'status') apply((all) => commands.replaceSelected(all, at, id, { ...element, negated: !element.negated }), t('lad.menu.negate'));
          },
          write: (operand, value, input) => void command(input ? { type: 'set_input', address: operand, value } : { type: 'modify', target: operand, value }),
          force: (operand, value) => void command({ type: 'force', address: operand, value }),
          unforce: (operand) => void command({ type: 'unforce', address: operand }),
          connect: (pin) => {
            if (element.kind !== 'box') return;
            apply((all) => commands.replaceSelected(all, at, id, connectPin(element, pin)), t('lad.menu.connect', { pin: pin.name, type: pin.type }));
            setEditing({ block: b, network: n, id, field: `pin:${pin.name}` });
          },
          modify: setModifying,
          remove: () => apply((all) => commands.deleteSelected(all, at), t('lad.undo.delete')),
        },
      });
      if (actions.length === 0) return;
      const anchor = byId(`lad-${prefixOf(b, n)}-${id}`) ?? (event.target as Element);
      setMenu({ anchor, label: t('lad.menu.element'), actions });
    },
    [blocks, editable, t, editSelected, apply, monitor.online, command, symbols, outline],
  );

  const onHeaderMenu = useCallback(
    (b: number, n: number, event: MouseEvent) => {
      const block = blocks[b];
      if (!block) return;
      const at: Selection = { block: b, network: n, id: null, point: null };
      const actions = networkMenu({
        t,
        editable,
        breakpoints: projectId !== null && !!file,
        on: {
          insert: addNetwork,
          editField: (field) => setEditing({ block: b, network: n, id: 'header', field }),
          move: (delta) => apply((all) => commands.moveNetwork(all, at, delta), t('lad.undo.moveNetwork')),
          clipboard: clipboardAction,
          toggleBreakpoint,
          breakpointCondition: () => setBreakpointDialog({ block: block.name, network: n + 1 }),
          remove: () => apply((all) => commands.deleteNetwork(all, at), t('lad.undo.deleteNetwork')),
        },
      });
      const anchor = byId(`${prefixOf(b, n)}-header`) ?? (event.target as Element);
      setMenu({ anchor, label: t('lad.menu.network'), actions });
    },
    [blocks, editable, t, addNetwork, apply, clipboardAction, projectId, file, toggleBreakpoint],
  );

  // -- drag and drop -----------------------------------------------------------------------------------
  const draggedElement = useRef<{ block: number; network: number; id: string } | null>(null);
  const onDrop = useCallback(
    (b: number, n: number, point: commands.Selection['point'], event: DragEvent) => {
      setDragging(false);
      if (!point) return;
      const key = event.dataTransfer.getData(CATALOGUE_MIME);
      const item = key ? items.find((entry) => entry.key === key) : undefined;
      if (item) {
        apply((all) => commands.insertItemAt(all, { block: b, network: n, id: null, point: null }, item, point), t('lad.undo.insert', { what: item.symbol }));
        return;
      }
    },
    [items, apply, t],
  );

  // -- rendering ----------------------------------------------------------------------------------------
  const renderRow = (index: number): ReactNode => {
    const row = rows[index];
    if (!row) return null;
    const block = blocks[row.block];
    if (!block) return null;
    if (row.kind === 'block') {
      return (
        <header className="lad-block" data-testid={`lad-block-${row.block + 1}`} dir={dir} lang={language}>
          <span className="lad-block__name" dir="ltr">
            {block.name}
          </span>
          <span className="lad-block__language">{block.language}</span>
          {block.title ? (
            <span className="lad-block__title" dir="auto">
              {block.title}
            </span>
          ) : null}
          {problems.block.get(row.block)?.map((problem, k) => (
            <span key={k} className="lad-block__problem">
              <code className="error-code">{problem.code}</code> {problem.message}
            </span>
          ))}
        </header>
      );
    }
    if (row.kind === 'end') {
      return (
        <div className="lad-end" dir={dir} lang={language}>
          {editable ? (
            <button
              type="button"
              className="button button--small"
              data-testid={`lad-add-network-${row.block + 1}`}
              onClick={() => apply((all) => commands.insertNetwork(all, { block: row.block, network: (all[row.block]?.networks.length ?? 1) - 1, id: null, point: null }), t('lad.undo.addNetwork'))}
            >
              {t('lad.toolbar.addNetwork')}
            </button>
          ) : null}
        </div>
      );
    }
    const network = block.networks[row.network];
    if (!network) return null;
    const b = row.block;
    const n = row.network;
    const prefix = prefixOf(b, n);
    const here = selection.block === b && selection.network === n;
    const key = `${b}:${n}`;
    const networkProblems = problems.networks.get(key);
    const editingHere = editing && editing.block === b && editing.network === n ? editing : null;
    const states = monitor.online ? monitor.statesOf(n + 1) : undefined;
    const flows = states && network.stl === null ? networkFlows(network, states) : undefined;
    let body: ReactNode = null;
    if (network.stl === null) {
      const fieldEditor =
        editingHere && editingHere.id !== 'header' ? (
          <FieldEditor edit={editingHere} network={network} mode={mode} completer={completerFor(editingHere, block)} onCommit={commitField} onCancel={() => setEditing(null)} />
        ) : null;
      if (mode === 'FBD') {
        body = (
          <div className="lad-rung-frame">
            <FbdView
              network={network}
              prefix={`fbd-${prefix}`}
              selectedId={here ? selection.id : null}
              onSelect={(id) => select({ block: b, network: n, id, point: null })}
              onEdit={(id, field) => {
                if (readOnly) return;
                select({ block: b, network: n, id, point: null });
                setEditing({ block: b, network: n, id, field });
              }}
              onContextMenu={(id, event) => onElementMenu(b, n, id, event)}
              flows={flows}
              {...(states ? { states } : {})}
              label={(operand) => operandLabel(operand, display, symbols).main}
              problems={networkProblems?.elements ?? EMPTY_PROBLEMS}
            />
            {fieldEditor}
          </div>
        );
      } else {
        const layout = layoutOf(network);
        body = (
          <div className="lad-rung-frame">
            <LadRung
              network={network}
              layout={layout}
              prefix={`lad-${prefix}`}
              selectedId={here ? selection.id : null}
              insertAt={here && editable ? commands.insertionPoint(network, selection) : null}
              label={(operand) => operandLabel(operand, display, symbols)}
              problems={networkProblems?.elements ?? EMPTY_PROBLEMS}
              {...(flows ? { flows, states } : {})}
              formatValue={formatValue}
              {...(forced ? { forced } : {})}
              dragging={dragging && editable}
              onSelect={(id) => select({ block: b, network: n, id, point: null })}
              onSelectPoint={(point) => select({ block: b, network: n, id: null, point })}
              onEdit={(id, field) => {
                if (readOnly) return;
                select({ block: b, network: n, id, point: null });
                setEditing({ block: b, network: n, id, field });
              }}
              onContextMenu={(id, event) => onElementMenu(b, n, id, event)}
              onDrop={(point, event) => onDrop(b, n, point, event)}
              onMoveStart={(id) => {
                if (!editable) return;
                draggedElement.current = { block: b, network: n, id };
                setDragging(true);
                window.addEventListener(
                  'pointerup',
                  () =>
                    requestAnimationFrame(() => {
                      draggedElement.current = null;
                      setDragging(false);
                    }),
                  { once: true },
                );
              }}
              onMoveTo={(point) => {
                const moved = draggedElement.current;
                draggedElement.current = null;
                setDragging(false);
                if (moved && moved.block === b && moved.network === n) {
                  apply((all) => commands.moveElement(all, { block: b, network: n, id: moved.id, point: null }, moved.id, point), t('lad.undo.move'));
                }
              }}
            />
            {fieldEditor}
          </div>
        );
      }
    }
    return (
      <NetworkView
        network={network}
        number={n + 1}
        prefix={prefix}
        collapsed={collapsed.has(key)}
        headerSelected={here && selection.id === null}
        held={monitor.heldNetwork === n + 1 && shown.block === b}
        breakpoint={breakpointOf(block, n + 1)}
        problems={networkProblems?.network ?? EMPTY_LIST}
        elementProblems={networkProblems?.elementCount ?? 0}
        editing={editingHere?.id === 'header' ? editingHere.field : null}
        reasonText={network.stl_reason ? reasonText(t, network.stl_reason) : null}
        readOnly={!editable}
        body={body}
        onSelectHeader={() => select({ block: b, network: n, id: null, point: null })}
        onToggleCollapse={() =>
          setCollapsed((current) => {
            const next = new Set(current);
            if (next.has(key)) next.delete(key);
            else next.add(key);
            return next;
          })
        }
        onEdit={(field) => setEditing({ block: b, network: n, id: 'header', field })}
        onCommit={(field, value) => commitField({ block: b, network: n, id: 'header', field }, value)}
        onCancelEdit={() => setEditing(null)}
        onHeaderMenu={(event) => onHeaderMenu(b, n, event)}
      />
    );
  };

  if (doc.state.status === 'unreadable' || doc.state.status === 'failed' || (doc.state.status === 'loading' && !doc.blocks)) {
    return null; // the source view shows why (and the text view)
  }

  return (
    <div
      ref={root}
      className={`lad-editor lad-editor--${mode.toLowerCase()}${monitor.online ? ' lad-editor--online' : ''}`}
      data-testid="lad-editor"
      data-mode={mode}
      data-online={monitor.online ? 'true' : 'false'}
      onDragEnd={() => setDragging(false)}
      onDragOver={(event) => {
        if (editable && event.dataTransfer.types.includes(CATALOGUE_MIME) && !dragging) setDragging(true);
      }}
    >
      <LadToolbar
        editable={editable}
        canUndo={doc.canUndo}
        canRedo={doc.canRedo}
        onUndo={doc.undo}
        onRedo={doc.redo}
        {...(embedded?.fixedNetworks ? {} : { onAddNetwork: addNetwork })}
        favourites={favourites}
        emptyBox={emptyBoxItem}
        onInsert={insert}
        onCommand={runCommand}
        onDragging={setDragging}
        display={display}
        onDisplay={setDisplay}
        hex={monitor.online ? hex : null}
        onHex={setHex}
        catalogueOpen={catalogueOpen}
        onCatalogue={toggleCatalogue}
        notice={notice}
        onNoticeEnd={() => setNotice(null)}
      />
      <div className="lad-editor__main" dir={dir} lang={language}>
        <div className="lad-editor__list" onKeyDown={onKeyDown} tabIndex={-1} dir="ltr">
          <NetworkList
            ref={list}
            count={rows.length}
            heightOf={heightOf}
            renderItem={renderRow}
            onVisibleChange={onVisibleChange}
            layoutKey={blocks}
            label={embedded?.label ?? t('lad.list.label')}
            testId="lad-networks"
          />
        </div>
        {catalogueOpen ? (
          <CataloguePanel
            items={items}
            disabled={!editable}
            focusRequest={catalogueFocus}
            onInsert={(item) => insert(item)}
            onDragStart={() => setDragging(true)}
            onDragEnd={() => setDragging(false)}
            onClose={() => {
              wantFocus.current = true;
              setSelection({ ...selectionRef.current });
            }}
          />
        ) : null}
      </div>
      {menu ? (
        <RowMenu
          anchor={menu.anchor}
          label={menu.label}
          actions={menu.actions}
          testId="lad-menu"
          onClose={(restore) => {
            setMenu(null);
            if (restore) {
              wantFocus.current = true;
              setSelection({ ...selectionRef.current });
            }
          }}
        />
      ) : null}
      {/* In the page's body: the editor's frame is always left to right, the dialogs are not. */}
      {modifying !== null
        ? createPortal(<ModifyDialog operand={modifying} onModify={(value) => void command({ type: 'modify', target: modifying, value })} onClose={() => setModifying(null)} />, document.body)
        : null}
      {breakpointDialog && projectId !== null && file
        ? createPortal(
            <BreakpointDialog projectId={projectId} file={file} line={breakpointDialog.network} block={breakpointDialog.block} onClose={() => setBreakpointDialog(null)} />,
            document.body,
          )
        : null}
    </div>
  );
}

const OFFLINE: LadMonitoring = { online: false, statesOf: () => undefined, heldNetwork: null };
const EMPTY_PROBLEMS: ReadonlyMap<string, readonly RungProblem[]> = new Map();
const EMPTY_LIST: readonly RungProblem[] = [];

function reasonText(t: (key: string) => string, code: string): string {
  return t(`lad.reasons.${code}`);
}

