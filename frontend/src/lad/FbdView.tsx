/**
 * One FBD network drawn as SVG: boxes (AND, OR, NOT, assignments, timers, MOVE ...) with their
 * pins, operands written at the pins (a circle where an input is negated), wires routed by elkjs.
 * The same network model as LAD: a box drawing a LAD element carries its id, so selection, edits,
 * diagnostics and program status are the LAD editor's. Always left to right.
 */
import { memo, useSyncExternalStore, type MouseEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { flowClass, flowState, type Flow } from '../diagram/powerFlow';
import { isPlaceholder } from './edits';
import { LABEL_CHARS, fbdGeometryOf, fbdLayoutVersion, portText, subscribeFbdLayouts, type FbdGeometry, type PlacedNode } from './fbdGeometry';
import type { FbdLayout, Network } from './model';
import type { ElementState, FlowMap } from './status';

export interface FbdViewProps {
  network: Network;
  prefix: string;
  selectedId: string | null;
  onSelect: (id: string) => void;
  /** Double click: edit a box's type or operand, an input's operand. */
  onEdit: (id: string, field: string) => void;
  onContextMenu: (id: string, event: MouseEvent) => void;
  /** The elements' problems, by element id. */
  problems: ReadonlyMap<string, readonly { severity: string }[]>;
  flows: FlowMap | undefined;
  states?: ReadonlyMap<string, ElementState>;
  /** Operand text as the display mode wants it. */
  label?: (operand: string) => string;
}

function problemSeverity(problems: readonly { severity: string }[] | undefined): 'error' | 'warning' | null {
  if (!problems || problems.length === 0) return null;
  return problems.some((problem) => problem.severity === 'error') ? 'error' : 'warning';
}

function clip(text: string): string {
  return text.length > LABEL_CHARS ? `${text.slice(0, LABEL_CHARS - 1)}…` : text;
}

function truth(value: unknown): boolean {
  return value === true || (typeof value === 'number' && value !== 0);
}

/**
 * The signal on every box output of the FBD graph, from the elements' states: AND/OR/NOT from
 * their inputs, every box that stands for a LAD element from what the CPU reported for it.
 */
export function fbdSignals(graph: FbdLayout, states: ReadonlyMap<string, ElementState> | undefined): Map<string, Flow> {
  const out = new Map<string, Flow>();
  if (!states) return out;
  const nodes = new Map(graph.nodes.map((node) => [node.id, node]));
  const feeding = new Map(graph.edges.map((edge) => [edge.target_port, edge.source]));
  const processed = states.size > 0;
  const visiting = new Set<string>();
  const portValue = (port: FbdLayout['nodes'][number]['ports'][number]): Flow => {
    const source = feeding.get(port.id);
    if (source) return value(source);
    if (!processed) return null;
    if (port.element) {
      const state = states.get(port.element);
      if (!state) return null;
      return truth(state.value) !== port.negated ? 1 : 0;
    }
    return null;
  };
  const value = (id: string): Flow => {
    if (out.has(id)) return out.get(id);
    const node = nodes.get(id);
    if (!node || visiting.has(id)) return null;
    visiting.add(id);
    const inputs = node.ports.filter((port) => port.side === 'WEST').map(portValue);
    let result: Flow;
    if (node.kind === 'logic') {
      if (inputs.length === 0) result = processed ? 1 : null;
      else if (node.title === '>=1') result = inputs.some((v) => v === 1) ? 1 : inputs.every((v) => v === 0) ? 0 : null;
      else if (node.title === 'XOR') result = inputs.some((v) => v === null) ? null : (inputs.filter((v) => v === 1).length % 2 === 1 ? 1 : 0);
      else result = inputs.some((v) => v === null) ? null : inputs.every((v) => v === 1) ? 1 : 0;
    } else if (node.kind === 'not') {
      const input = inputs[0];
      result = input === null || input === undefined ? null : input ? 0 : 1;
    } else {
      const state = states.get(node.id);
      result = state && state.out !== null ? (state.out ? 1 : 0) : state ? (inputs[0] ?? null) : null;
    }
    visiting.delete(id);
    out.set(id, result);
    return result;
  };
  for (const node of graph.nodes) value(node.id);
  return out;
}

function Box({ placed, props, signals, signalOf }: { placed: PlacedNode; props: FbdViewProps; signals: Map<string, Flow>; signalOf: (portId: string) => Flow }) {
  const { t } = useTranslation();
  const { node } = placed;
  const selectable = !node.id.startsWith('&') && !/^n\d+$/.test(node.id);
  const selected = props.selectedId === node.id;
  const online = props.flows !== undefined;
  const own: Flow = online ? signals.get(node.id) ?? null : undefined;
  const state = props.states?.get(node.id);
  const label = (text: string) => (props.label ? props.label(text) : text);
  const severity = problemSeverity(props.problems.get(node.id));
  const x = placed.x;
  const y = placed.y;
  return (
    <g
      role={selectable ? 'button' : undefined}
      tabIndex={selectable ? (selected ? 0 : -1) : undefined}
      aria-label={selectable ? t('lad.fbd.box', { title: node.title, operand: node.operand ?? '' }) : undefined}
      aria-pressed={selectable ? selected : undefined}
      id={selectable ? `${props.prefix}-${node.id}` : undefined}
      data-testid={`${props.prefix}-${node.id}`}
      data-kind={node.kind}
      data-flow={flowState(own)}
      data-problem={severity ?? undefined}
      className={`fbd-box${selected ? ' fbd-box--selected' : ''}${severity ? ` fbd-box--${severity}` : ''}`}
      onClick={(event) => {
        event.stopPropagation();
        if (selectable) props.onSelect(node.id);
      }}
      onDoubleClick={(event) => {
        event.stopPropagation();
        if (selectable) props.onEdit(node.id, node.kind === 'box' ? 'name' : node.kind === 'jump' ? 'label' : 'operand');
      }}
      onContextMenu={(event) => {
        if (!selectable) return;
        event.preventDefault();
        event.stopPropagation();
        props.onSelect(node.id);
        props.onContextMenu(node.id, event);
      }}
    >
      {node.operand !== null && node.operand !== undefined ? (
        <text x={x + placed.width / 2} y={y - 5} textAnchor="middle" className={`fbd-operand${isPlaceholder(node.operand) ? ' lad-operand--missing' : ''}`}>
          {label(node.operand)}
        </text>
      ) : null}
      <rect x={x} y={y} width={placed.width} height={placed.height} className={`fbd-frame ${flowClass(own)}`} rx={2} />
      <text x={x + placed.width / 2} y={y + 16} textAnchor="middle" className="fbd-title">
        {node.title}
      </text>
      {node.ports.map((port) => {
        const at = placed.ports.get(port.id);
        if (!at) return null;
        const west = port.side === 'WEST';
        const flow = online ? signalOf(port.id) : undefined;
        const pinValue = state?.pins[port.name];
        const stub = west ? at.x - 12 : at.x + 12;
        const selectPort = port.element && port.element !== node.id ? port.element : null;
        const text = portText(port);
        return (
          <g
            key={port.id}
            className={`fbd-port${selectPort && props.selectedId === selectPort ? ' fbd-port--selected' : ''}`}
            data-testid={selectPort ? `${props.prefix}-${selectPort}` : undefined}
            data-flow={selectPort ? flowState(flow) : undefined}
            role={selectPort ? 'button' : undefined}
            tabIndex={selectPort ? (props.selectedId === selectPort ? 0 : -1) : undefined}
            id={selectPort ? `${props.prefix}-${selectPort}` : undefined}
            aria-label={selectPort ? t('lad.fbd.input', { operand: port.label ?? '', pin: port.name }) : undefined}
            data-problem={selectPort ? (problemSeverity(props.problems.get(selectPort)) ?? undefined) : undefined}
            onClick={(event) => {
              if (!selectPort) return;
              event.stopPropagation();
              props.onSelect(selectPort);
            }}
            onDoubleClick={(event) => {
              if (!selectPort) return;
              event.stopPropagation();
              props.onEdit(selectPort, 'operand');
            }}
            onContextMenu={(event) => {
              if (!selectPort) return;
              event.preventDefault();
              event.stopPropagation();
              props.onSelect(selectPort);
              props.onContextMenu(selectPort, event);
            }}
          >
            <line x1={stub} y1={at.y} x2={at.x} y2={at.y} className={`fbd-wire ${flowClass(flow)}`} />
            {port.negated ? <circle cx={at.x - 4} cy={at.y} r={3.5} className="fbd-negation" /> : null}
            {node.kind !== 'logic' ? (
              <text x={west ? at.x + 4 : at.x - 4} y={at.y + 4} textAnchor={west ? 'start' : 'end'} className="fbd-pin">
                {port.name}
              </text>
            ) : null}
            {text !== null && at.label ? (
              <text
                x={at.label.x + (west ? at.label.width - 4 : 4)}
                y={at.label.y + 11}
                textAnchor={west ? 'end' : 'start'}
                className={`fbd-operand${isPlaceholder(text) ? ' lad-operand--missing' : ''}${port.open ? ' fbd-operand--open' : ''}`}
                data-testid={port.open || node.kind === 'box' ? `${props.prefix}-${node.id}-pin-${port.name}` : undefined}
                onDoubleClick={(event) => {
                  if (node.kind !== 'box' || selectPort) return;
                  event.stopPropagation();
                  props.onEdit(node.id, `pin:${port.name}`);
                }}
              >
                <title>{text}</title>
                {clip(port.open ? text : label(text))}
              </text>
            ) : null}
            {typeof pinValue === 'number' || typeof pinValue === 'string' ? (
              <text x={west ? at.x - 4 : at.x + 4} y={at.y - 4} textAnchor={west ? 'end' : 'start'} className="lad-value">
                {String(pinValue)}
              </text>
            ) : null}
          </g>
        );
      })}
    </g>
  );
}

function Drawing({ geometry, props }: { geometry: FbdGeometry; props: FbdViewProps }) {
  const signals = fbdSignals(geometry.graph, props.flows ? props.states : undefined);
  const feeding = new Map(geometry.graph.edges.map((edge) => [edge.target_port, edge.source]));
  const portFlow = new Map<string, Flow>();
  for (const node of geometry.graph.nodes) {
    for (const port of node.ports) {
      if (port.side === 'EAST') portFlow.set(port.id, signals.get(node.id));
      else {
        const source = feeding.get(port.id);
        if (source) portFlow.set(port.id, signals.get(source));
        else if (port.element && props.states) {
          const state = props.states.get(port.element);
          portFlow.set(port.id, state ? (truth(state.value) ? 1 : 0) : null);
        }
      }
    }
  }
  const signalOf = (portId: string): Flow => (props.flows ? (portFlow.get(portId) ?? null) : undefined);
  return (
    <svg className="fbd-network" width={geometry.width} height={geometry.height + 8} viewBox={`0 -8 ${geometry.width} ${geometry.height + 8}`} direction="ltr" data-testid={`${props.prefix}-diagram`}>
      {geometry.edges.map((edge) => (
        <polyline
          key={edge.id}
          className={`fbd-wire ${flowClass(props.flows ? (signals.get(edge.source) ?? null) : undefined)}`}
          points={edge.points.map((point) => `${point.x},${point.y}`).join(' ')}
        />
      ))}
      {geometry.nodes.map((placed) => (
        <Box key={placed.node.id} placed={placed} props={props} signals={signals} signalOf={signalOf} />
      ))}
    </svg>
  );
}

/** The FBD body of a network: drawn once elkjs has placed it (a moment for a large network). */
export const FbdView = memo(function FbdView(props: FbdViewProps) {
  const { t } = useTranslation();
  useSyncExternalStore(subscribeFbdLayouts, fbdLayoutVersion, fbdLayoutVersion);
  const geometry = fbdGeometryOf(props.network);
  if (!geometry) return <p className="fbd-pending">{t('lad.fbd.laying')}</p>;
  return <Drawing geometry={geometry} props={props} />;
});
