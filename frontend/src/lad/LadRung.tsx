/**
 * One LAD rung drawn as SVG from its grid layout: the left power rail, contacts, coils, boxes
 * with their pins, parallels' links and the filler wires. Always left to right, whatever the page's
 * direction, as printed ladder diagrams are. Every element is a focusable button (roving focus:
 * only the selected one is in the tab order) with a name a screen reader says; its power-flow
 * state is on `data-flow`. The editor owns selection, edits and status; this only draws.
 */
import { memo, type DragEvent, type MouseEvent, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import { flowClass, flowState, type Flow } from '../diagram/powerFlow';
import { flowPins } from './boxes';
import { isPlaceholder } from './edits';
import { CELL_W, RAIL_X, WIRE_Y, cellRect, columnX, insertSpots, rungSize, wireY, type InsertSpot } from './geometry';
import type { LadCell, LadLayout, Network } from './model';
import type { ElementState, FlowMap } from './status';
import { walk, type Element, type Final, type InsertPoint } from './tree';

/** How an operand is shown: the symbol or address as written, and the other form below it. */
export interface OperandLabel {
  main: string;
  second?: string;
}

export interface RungProblem {
  code: string;
  message: string;
  severity: 'error' | 'warning' | 'info';
}

export interface LadRungProps {
  network: Network;
  layout: LadLayout;
  /** Test ids and names: `lad-<block>-<network>-<element id>`. */
  prefix: string;
  selectedId: string | null;
  /** The wire position the next element goes to (marked on the rung). */
  insertAt: InsertPoint | null;
  /** Operand text as the display mode (symbolic / absolute) wants it. */
  label: (operand: string) => OperandLabel;
  problems: ReadonlyMap<string, readonly RungProblem[]>;
  /** Online: the flows and the elements' states; undefined offline. */
  flows?: FlowMap;
  states?: ReadonlyMap<string, ElementState>;
  /** A value as the status format shows it. */
  formatValue?: (value: unknown) => string;
  /** Operands forced in the CPU (as written in the rung). */
  forced?: (operand: string) => boolean;
  /** Something is being dragged over the editor: show the drop positions. */
  dragging: boolean;
  onSelect: (id: string) => void;
  onSelectPoint: (point: InsertPoint) => void;
  /** Double click on an element or one of its texts: edit it (`operand`, `pin:<name>`, `instance`, `name`, `value`). */
  onEdit: (id: string, field: string) => void;
  onContextMenu: (id: string, event: MouseEvent) => void;
  /** A catalogue entry dropped on a wire position. */
  onDrop: (point: InsertPoint, event: DragEvent) => void;
  /** The mouse started moving an element (pressed on it and moved): the drop positions show. */
  onMoveStart: (id: string) => void;
  /** The moved element was let go on a wire position. */
  onMoveTo: (point: InsertPoint) => void;
}

/** How far the mouse must move with the button down before it drags the element. */
const DRAG_THRESHOLD = 6;

type Props = LadRungProps;

const TEXT_MAX = 13;
/** What an unconnected pin of a box shows (TIA Portal's "..."): a double click connects it. */
const OPEN_PIN = '...';

function clip(text: string, max = TEXT_MAX): string {
  return text.length > max ? `${text.slice(0, max - 1)}…` : text;
}

/** A value written beside an element or pin: numbers and texts; a bit's value is its colour. */
function valueText(props: Props, value: unknown): string | null {
  if (value === undefined || value === null || typeof value === 'boolean' || !props.formatValue) return null;
  return props.formatValue(value);
}

/** The SVG of a wire carrying `flow`. */
function Line({ x1, y1, x2, y2, flow }: { x1: number; y1: number; x2: number; y2: number; flow: Flow }) {
  return <line className={`lad-wire ${flowClass(flow)}`} x1={x1} y1={y1} x2={x2} y2={y2} />;
}

function OperandText({ x, y, operand, props, anchor = 'middle', id, field }: { x: number; y: number; operand: string; props: Props; anchor?: 'start' | 'middle' | 'end'; id: string; field: string }) {
  const shown = props.label(operand);
  const placeholder = isPlaceholder(operand);
  const forced = props.forced?.(operand) ?? false;
  return (
    <g
      className={`lad-operand${placeholder ? ' lad-operand--missing' : ''}`}
      data-testid={`${props.prefix}-${id}-${field.replace(':', '-')}`}
      onDoubleClick={(event) => {
        event.stopPropagation();
        props.onEdit(id, field);
      }}
    >
      <title>{shown.second ? `${shown.main} (${shown.second})` : shown.main}</title>
      <text x={x} y={y} textAnchor={anchor} className="lad-operand__main">
        {clip(shown.main)}
      </text>
      {shown.second ? (
        <text x={x} y={y + 12} textAnchor={anchor} className="lad-operand__second">
          {clip(shown.second)}
        </text>
      ) : null}
      {forced ? (
        <text x={anchor === 'end' ? x + 4 : x + 42} y={y} className="lad-forced" data-testid={`forced-${operand}`}>
          F
        </text>
      ) : null}
    </g>
  );
}

const COIL_LETTER: Record<string, string> = { '=': '', S: 'S', R: 'R', SAVE: 'SAVE', SP: 'SP', SE: 'SE', SD: 'SD', SS: 'SS', SF: 'SF', CU: 'CU', CD: 'CD', SC: 'SC' };

/** The symbol of a one-cell element, drawn around the wire at (cx, wy). */
function Symbol({ element, cx, wy, on }: { element: Element | Final; cx: number; wy: number; on: Flow }) {
  const cls = `lad-symbol ${flowClass(on)}`;
  switch (element.kind) {
    case 'contact':
    case 'status':
      return (
        <g className={cls}>
          <line x1={cx - 9} y1={wy - 13} x2={cx - 9} y2={wy + 13} />
          <line x1={cx + 9} y1={wy - 13} x2={cx + 9} y2={wy + 13} />
          {element.negated ? <line x1={cx - 9} y1={wy + 13} x2={cx + 9} y2={wy - 13} /> : null}
        </g>
      );
    case 'not':
      return (
        <g className={cls}>
          <rect x={cx - 17} y={wy - 11} width={34} height={22} className="lad-frame" />
          <text x={cx} y={wy + 4} textAnchor="middle" className="lad-symbol__text">
            NOT
          </text>
        </g>
      );
    default: {
      const letter =
        element.kind === 'coil'
          ? COIL_LETTER[element.coil] ?? element.coil
          : element.kind === 'edge'
            ? element.edge
            : element.kind === 'midline'
              ? '#'
              : element.kind === 'jump'
                ? element.negated
                  ? 'JMPN'
                  : 'JMP'
                : element.kind === 'ret'
                  ? 'RET'
                  : element.kind === 'opn'
                    ? 'OPN'
                    : '';
      const wide = letter.length > 2;
      const half = wide ? 22 : 11;
      return (
        <g className={cls}>
          <path d={`M ${cx - half + 4} ${wy - 13} Q ${cx - half - 4} ${wy} ${cx - half + 4} ${wy + 13}`} className="lad-arc" />
          <path d={`M ${cx + half - 4} ${wy - 13} Q ${cx + half + 4} ${wy} ${cx + half - 4} ${wy + 13}`} className="lad-arc" />
          {letter ? (
            <text x={cx} y={wy + 4} textAnchor="middle" className="lad-symbol__text">
              {letter}
            </text>
          ) : null}
        </g>
      );
    }
  }
}

function operandOf(element: Element | Final): { text: string; field: string } | null {
  switch (element.kind) {
    case 'contact':
    case 'midline':
      return { text: element.operand, field: 'operand' };
    case 'status':
      return { text: element.bit, field: 'bit' };
    case 'edge':
      return { text: element.memory, field: 'operand' };
    case 'coil':
      return element.coil === 'SAVE' ? null : { text: element.operand, field: 'operand' };
    case 'jump':
      return { text: element.label, field: 'label' };
    case 'opn':
      return { text: element.block, field: 'operand' };
    default:
      return null;
  }
}

function describe(t: (key: string, options?: Record<string, unknown>) => string, element: Element | Final): string {
  const operand = operandOf(element)?.text ?? '';
  if (element.kind === 'box') return t('lad.element.box', { name: element.name, instance: element.instance ?? '' });
  if (element.kind === 'coil') return t(`lad.element.coil_${coilKey(element.coil)}`, { operand, value: element.value ?? '' });
  if (element.kind === 'contact') return t(element.negated ? 'lad.element.contactNC' : 'lad.element.contact', { operand });
  if (element.kind === 'status') return t(element.negated ? 'lad.element.statusNC' : 'lad.element.status', { operand });
  return t(`lad.element.${element.kind}`, { operand, edge: element.kind === 'edge' ? element.edge : '' });
}

function coilKey(coil: string): string {
  return coil === '=' ? 'assign' : coil.toLowerCase();
}

function BoxShape({ cell, element, props }: { cell: LadCell; element: Extract<Element | Final, { kind: 'box' }>; props: Props }) {
  const rect = cellRect(cell);
  const left = rect.x + 58;
  const right = rect.x + rect.width - 58;
  const top = rect.y + 22;
  const bottom = rect.y + rect.height - 8;
  const state = props.states?.get(element.id);
  const into = props.flows?.get(`${element.id}:in`);
  const out = props.flows?.get(element.id);
  const pins: ReactNode[] = [];
  for (const pin of cell.pins) {
    const y = wireY(pin.row);
    const top = pin.row === cell.row;
    const leftSide = pin.side === 'left';
    const pinFlow: Flow = top ? (leftSide ? into : out) : undefined;
    const value = state?.pins[pin.name];
    const shown = valueText(props, value);
    pins.push(
      <g key={`${pin.side}-${pin.name}`} className="lad-pin" data-pin={pin.name}>
        <Line x1={leftSide ? rect.x : right} y1={y} x2={leftSide ? left : rect.x + rect.width} y2={y} flow={pinFlow} />
        <text x={leftSide ? left + 4 : right - 4} y={y + 4} textAnchor={leftSide ? 'start' : 'end'} className="lad-pin__name">
          {pin.name}
        </text>
        {(pin.operand !== null && pin.operand !== undefined) || pin.open ? (
          <OperandText
            x={leftSide ? left - 4 : right + 4}
            y={y - 6}
            operand={pin.operand ?? OPEN_PIN}
            props={props}
            anchor={leftSide ? 'end' : 'start'}
            id={element.id}
            field={`pin:${pin.name}`}
          />
        ) : null}
        {shown !== null ? (
          <text x={leftSide ? left - 4 : right + 4} y={y + 14} textAnchor={leftSide ? 'end' : 'start'} className="lad-value" data-testid={`value-${props.prefix}-${element.id}-${pin.name}`}>
            {shown}
          </text>
        ) : null}
      </g>,
    );
  }
  if (!flowPins(element.name)[0] && cell.pins.every((pin) => pin.row !== cell.row || pin.side !== 'left')) {
    pins.push(<Line key="flow-in" x1={rect.x} y1={wireY(cell.row)} x2={left} y2={wireY(cell.row)} flow={into} />);
  }
  if (cell.pins.every((pin) => pin.row !== cell.row || pin.side !== 'right')) {
    pins.push(<Line key="flow-out" x1={right} y1={wireY(cell.row)} x2={rect.x + rect.width} y2={wireY(cell.row)} flow={out} />);
  }
  const title = element.name;
  return (
    <>
      {element.instance !== null && element.instance !== undefined ? (
        <OperandText x={(left + right) / 2} y={rect.y + 14} operand={element.instance} props={props} id={element.id} field="instance" />
      ) : null}
      <rect x={left} y={top} width={right - left} height={bottom - top} className={`lad-frame lad-box ${flowClass(out)}`} />
      <text
        x={(left + right) / 2}
        y={top + 14}
        textAnchor="middle"
        className={`lad-box__title${isPlaceholder(title) ? ' lad-operand--missing' : ''}`}
        onDoubleClick={(event) => {
          event.stopPropagation();
          props.onEdit(element.id, 'name');
        }}
      >
        {clip(title, 11)}
      </text>
      {valueText(props, state?.value) !== null && !cell.pins.some((pin) => valueText(props, state?.pins[pin.name]) !== null) ? (
        <text x={(left + right) / 2} y={bottom - 4} textAnchor="middle" className="lad-value" data-testid={`value-${props.prefix}-${element.id}`}>
          {valueText(props, state?.value)}
        </text>
      ) : null}
      {pins}
    </>
  );
}

function ElementShape({ cell, element, props }: { cell: LadCell; element: Element | Final; props: Props }) {
  const { t } = useTranslation();
  const rect = cellRect(cell);
  const selected = props.selectedId === element.id;
  const problems = props.problems.get(element.id) ?? [];
  const severity = problems.some((p) => p.severity === 'error') ? 'error' : problems.length > 0 ? 'warning' : null;
  const into = props.flows?.get(`${element.id}:in`);
  const out = props.flows?.get(element.id);
  const state = props.states?.get(element.id);
  const cx = rect.x + CELL_W / 2;
  const wy = wireY(cell.row);
  const operand = operandOf(element);
  const isTarget = element.kind === 'coil' || element.kind === 'jump' || element.kind === 'ret' || element.kind === 'opn';
  // A contact is drawn closed (green) when it conducts; the wire after it shows the flow.
  let symbolFlow: Flow = out;
  if ((element.kind === 'contact' || element.kind === 'status') && props.states) {
    symbolFlow = state ? ((state.value === true || state.value === 1) !== element.negated ? 1 : 0) : null;
  } else if (isTarget) symbolFlow = into;
  const label = describe(t, element) + (problems[0] ? ` — ${problems[0].code}: ${problems[0].message}` : '');
  const value = element.kind !== 'box' && element.kind !== 'contact' ? valueText(props, state?.value) : null;
  return (
    <g
      role="button"
      tabIndex={selected ? 0 : -1}
      aria-label={label}
      aria-pressed={selected}
      id={`${props.prefix}-${element.id}`}
      data-testid={`${props.prefix}-${element.id}`}
      data-kind={element.kind}
      data-flow={flowState(out)}
      data-flow-in={flowState(into)}
      data-contact={element.kind === 'contact' || element.kind === 'status' ? flowState(symbolFlow) : undefined}
      data-problem={severity ?? undefined}
      className={`lad-element${selected ? ' lad-element--selected' : ''}${severity ? ` lad-element--${severity}` : ''}`}
      onPointerDown={(event) => {
        if (event.button !== 0 || isTarget) return;
        const startX = event.clientX;
        const startY = event.clientY;
        const onMove = (move: PointerEvent) => {
          if (Math.abs(move.clientX - startX) + Math.abs(move.clientY - startY) < DRAG_THRESHOLD) return;
          window.removeEventListener('pointermove', onMove);
          props.onMoveStart(element.id);
        };
        window.addEventListener('pointermove', onMove);
        window.addEventListener('pointerup', () => window.removeEventListener('pointermove', onMove), { once: true });
      }}
      onClick={(event) => {
        event.stopPropagation();
        props.onSelect(element.id);
      }}
      onDoubleClick={(event) => {
        event.stopPropagation();
        props.onEdit(element.id, element.kind === 'box' ? 'name' : operand?.field ?? 'operand');
      }}
      onContextMenu={(event) => {
        event.preventDefault();
        event.stopPropagation();
        props.onSelect(element.id);
        props.onContextMenu(element.id, event);
      }}
    >
      <title>{label}</title>
      <rect className="lad-element__hit" x={rect.x + 1} y={rect.y + 1} width={rect.width - 2} height={rect.height - 2} rx={4} />
      {element.kind === 'box' ? (
        <BoxShape cell={cell} element={element} props={props} />
      ) : (
        <>
          <Line x1={rect.x} y1={wy} x2={cx - (isTarget ? 14 : 9)} y2={wy} flow={into} />
          <Symbol element={element} cx={cx} wy={wy} on={symbolFlow} />
          {isTarget ? null : <Line x1={cx + 9} y1={wy} x2={rect.x + rect.width} y2={wy} flow={out} />}
          {operand ? <OperandText x={cx} y={rect.y + 14} operand={operand.text} props={props} id={element.id} field={operand.field} /> : null}
          {element.kind === 'coil' && element.value !== null && element.value !== undefined ? (
            <OperandText x={cx} y={wy + 26} operand={element.value} props={props} id={element.id} field="value" />
          ) : null}
          {value !== null ? (
            <text x={cx + 20} y={wy - 16} className="lad-value" data-testid={`value-${props.prefix}-${element.id}`}>
              {value}
            </text>
          ) : null}
        </>
      )}
    </g>
  );
}

function Marker({ spot }: { spot: InsertSpot }) {
  const y = wireY(spot.row);
  return (
    <g className="lad-insert-marker" data-testid="lad-insert-marker" aria-hidden="true">
      <line x1={spot.x} y1={y - 16} x2={spot.x} y2={y + 16} />
      <path d={`M ${spot.x - 6} ${y - 24} L ${spot.x + 6} ${y - 24} L ${spot.x} ${y - 16} Z`} />
    </g>
  );
}

/** A wire position as text: `logic-2`, `c1-0` (output 1's conditions), `logic.0b1-0` (branch 1 of element 0). */
export function pointKey(point: InsertPoint): string {
  const series = point.series;
  const root = series.root === 'logic' ? 'logic' : `${series.target ? 't' : 'c'}${series.root}`;
  const steps = series.steps.map((step) => ('branch' in step ? `.${step.element}b${step.branch}` : `.${step.element}p${step.pin}`)).join('');
  return `${root}${steps}-${point.index}`;
}

function samePoint(a: InsertPoint, b: InsertPoint): boolean {
  return a.index === b.index && JSON.stringify(a.series) === JSON.stringify(b.series);
}

/** One rung. */
export const LadRung = memo(function LadRung(props: Props) {
  const { network, layout } = props;
  const { width, height } = rungSize(layout);
  const elements = new Map<string, Element | Final>();
  walk(network, (element) => elements.set(element.id, element));
  const spots = insertSpots(network, layout);
  const marker = props.insertAt ? spots.find((spot) => samePoint(spot.point, props.insertAt as InsertPoint)) : undefined;
  const rail = props.flows?.get('rail');
  return (
    <svg
      className="lad-rung"
      width={width}
      height={height}
      viewBox={`0 0 ${width} ${height}`}
      direction="ltr"
      data-testid={`${props.prefix}-rung`}
      onClick={() => {
        const end = spots[spots.length - 1];
        if (end) props.onSelectPoint(end.point);
      }}
    >
      <line className={`lad-rail ${flowClass(rail)}`} x1={RAIL_X} y1={0} x2={RAIL_X} y2={height} />
      {/* The wire from the rail to the first column. */}
      <Line x1={RAIL_X} y1={WIRE_Y} x2={columnX(0)} y2={WIRE_Y} flow={rail} />
      {network.logic.elements.length === 0 && network.outputs.length === 0 ? (
        <Line x1={columnX(0)} y1={WIRE_Y} x2={columnX(0) + CELL_W / 2} y2={WIRE_Y} flow={rail} />
      ) : null}
      {layout.wires.map((wire, k) => (
        <Line key={`w${k}`} x1={columnX(wire.from_column)} y1={wireY(wire.row)} x2={columnX(wire.to_column)} y2={wireY(wire.row)} flow={props.flows?.get(wire.flow)} />
      ))}
      {layout.links.map((link, k) => (
        <Line key={`l${k}`} x1={columnX(link.column)} y1={wireY(link.from_row)} x2={columnX(link.column)} y2={wireY(link.to_row)} flow={props.flows?.get(link.flow)} />
      ))}
      {layout.cells.map((cell) => {
        const element = elements.get(cell.id);
        return element ? <ElementShape key={cell.id} cell={cell} element={element} props={props} /> : null;
      })}
      {marker ? <Marker spot={marker} /> : null}
      {spots.map((spot) => (
        <rect
          key={pointKey(spot.point)}
          className={props.dragging ? 'lad-drop' : 'lad-spot'}
          data-testid={`${props.prefix}-drop-${pointKey(spot.point)}`}
          x={spot.x - (props.dragging ? 12 : 6)}
          y={wireY(spot.row) - (props.dragging ? 18 : 8)}
          width={props.dragging ? 24 : 12}
          height={props.dragging ? 36 : 16}
          rx={props.dragging ? 4 : 0}
          onClick={(event) => {
            event.stopPropagation();
            props.onSelectPoint(spot.point);
          }}
          onDragOver={(event) => {
            event.preventDefault();
            event.currentTarget.classList.add('lad-drop--over');
          }}
          onDragLeave={(event) => event.currentTarget.classList.remove('lad-drop--over')}
          onDrop={(event) => {
            event.preventDefault();
            event.stopPropagation();
            props.onDrop(spot.point, event as unknown as DragEvent);
          }}
          onPointerEnter={(event) => props.dragging && event.currentTarget.classList.add('lad-drop--over')}
          onPointerLeave={(event) => event.currentTarget.classList.remove('lad-drop--over')}
          onPointerUp={(event) => {
            if (!props.dragging) return;
            event.stopPropagation();
            props.onMoveTo(spot.point);
          }}
        />
      ))}
    </svg>
  );
});
