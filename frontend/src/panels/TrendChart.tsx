/**
 * The trend plot: uPlot (bundled, loaded with the trend view's first chart) drawing each entry
 * against the simulated time: every BOOL in a lane of its own with its name (a logic-analyser
 * view), the other entries against one y-axis per unit (trendLayout.ts). Drag across the plot to
 * zoom in on a time span; double-click or "Reset zoom" shows everything again. While zoomed, new
 * samples do not move the view. The plot fills the panel, or the height the user gives it with
 * the handle below it (drag, or the arrow keys; Home fits it to the panel again).
 */
import { useEffect, useMemo, useRef, useState, type KeyboardEvent, type PointerEvent } from 'react';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import type { TrendSample } from '../api/monitor';
import { TREND_COLORS } from './trendColors';
import {
  LANE_PX,
  axisRange,
  laneCentre,
  lanesRange,
  lanesShare,
  tickText,
  trendColumns,
  trendLayout,
  trendValueText,
  type TrendUnit,
} from './trendLayout';

export interface TrendChartLabels {
  time: string;
  reset: string;
  resize: string;
  units: Record<TrendUnit, string>;
}

export interface TrendChartProps {
  entries: readonly string[];
  types: readonly string[];
  samples: readonly TrendSample[];
  labels: TrendChartLabels;
}

export const MIN_HEIGHT = 90;
export const MAX_HEIGHT = 900;
const KEY_STEP = 20;
const REDRAW_MS = 100;
const HEIGHT_KEY = 'nasaq.trend.height';

function storedHeight(): number | null {
  try {
    const value = Number(localStorage.getItem(HEIGHT_KEY));
    return Number.isFinite(value) && value >= MIN_HEIGHT ? Math.min(MAX_HEIGHT, value) : null;
  } catch {
    return null;
  }
}

function storeHeight(height: number | null): void {
  try {
    if (height === null) localStorage.removeItem(HEIGHT_KEY);
    else localStorage.setItem(HEIGHT_KEY, String(height));
  } catch {
    // Storage may be unavailable (private mode): the height lasts until the reload.
  }
}

const clampHeight = (value: number) => Math.round(Math.min(MAX_HEIGHT, Math.max(MIN_HEIGHT, value)));

interface Tip {
  left: number;
  top: number;
  flip: boolean;
  index: number;
}

export default function TrendChart({ entries, types, samples, labels }: TrendChartProps) {
  const host = useRef<HTMLDivElement>(null);
  const plot = useRef<uPlot | null>(null);
  const zoomedRef = useRef(false);
  const [zoomed, setZoomed] = useState(false);
  const [tip, setTip] = useState<Tip | null>(null);
  const [height, setHeight] = useState<number | null>(storedHeight);
  const [shownHeight, setShownHeight] = useState(0);
  const layout = useMemo(() => trendLayout(types), [types]);
  const samplesRef = useRef(samples);
  samplesRef.current = samples;
  const layoutRef = useRef(layout);
  layoutRef.current = layout;
  const typesRef = useRef(types);
  typesRef.current = types;
  // The columns are made when the plot draws (at most 10 times a second), not at every frame.
  const columns = () => trendColumns(samplesRef.current, typesRef.current, layoutRef.current);
  const shape = `${entries.join('\n')}|${types.join(',')}`;
  // Rebuilt only when a text changes, not when the caller makes a new labels object.
  const labelsRef = useRef(labels);
  labelsRef.current = labels;
  const labelKey = JSON.stringify(labels);

  useEffect(() => {
    const element = host.current;
    if (!element) return;
    const { lanes, axes } = layout;
    const text = labelsRef.current;
    const laneOf = new Map(lanes.map((entry, lane) => [entry, lane]));
    const floors = new Map<string, number>();
    let share = 0;
    const size = () => ({ width: Math.max(200, element.clientWidth), height: Math.max(MIN_HEIGHT, element.clientHeight) });
    const measure = (plotHeight: number) => {
      share = lanesShare(lanes.length, plotHeight - 40, axes.length);
    };
    const first = size();
    measure(first.height);

    const scales: uPlot.Scales = { x: { time: false } };
    const yAxes: uPlot.Axis[] = [];
    if (lanes.length > 0) {
      scales.lanes = { auto: false, range: () => lanesRange(lanes.length, share) };
      const names = lanes.map((entry) => entries[entry] ?? '');
      const longest = Math.max(...names.map((name) => name.length));
      yAxes.push({
        scale: 'lanes',
        side: 3,
        size: Math.min(160, 14 + longest * 7),
        splits: () => lanes.map((_, lane) => laneCentre(lane, lanes.length)),
        values: (_u, splits) => splits.map((value) => names[lanes.length - 1 - Math.round((value - 0.5) / 1.5)] ?? ''),
        grid: { show: false },
        ticks: { show: false },
      });
    }
    axes.forEach((axis, order) => {
      const key = `unit-${axis.unit}`;
      scales[key] = {
        range: (_u, min, max) => {
          const found = axisRange(min, max, share);
          floors.set(key, found.floor);
          return found.range;
        },
      };
      const onLeft = lanes.length === 0 ? order % 2 === 0 : order % 2 === 1;
      yAxes.push({
        scale: key,
        side: onLeft ? 3 : 1,
        size: 56,
        label: text.units[axis.unit],
        labelSize: 16,
        stroke: axes.length > 1 ? TREND_COLORS[(axis.series[0] ?? 0) % TREND_COLORS.length] : undefined,
        grid: { show: order === 0 },
        filter: (_u, splits) => splits.map((value) => (value >= (floors.get(key) ?? -Infinity) ? value : null)),
        values: (_u, splits) => splits.map((value) => (value === null ? '' : tickText(value, axis.unit))),
      });
    });

    const options: uPlot.Options = {
      ...first,
      legend: { show: false },
      scales,
      cursor: { drag: { x: true, y: false, setScale: true } },
      axes: [
        { label: text.time, labelSize: 18, size: 32, values: (_u, ticks) => ticks.map((tick) => `${+tick.toFixed(3)}`) },
        ...yAxes,
      ],
      series: [
        { label: text.time },
        ...entries.map((entry, index) => {
          const lane = laneOf.get(index);
          const unit = layout.axes.find((axis) => axis.series.includes(index))?.unit;
          return {
            label: entry,
            scale: lane !== undefined ? 'lanes' : `unit-${unit}`,
            stroke: TREND_COLORS[index % TREND_COLORS.length],
            width: 1.5,
            ...(lane !== undefined && uPlot.paths.stepped ? { paths: uPlot.paths.stepped({ align: 1 }) } : {}),
          };
        }),
      ],
      hooks: {
        // The lanes' baselines: a faint line under each, as a logic analyser draws them.
        draw: [
          (u) => {
            if (lanes.length === 0) return;
            const ctx = u.ctx;
            ctx.save();
            ctx.strokeStyle = '#d5dde3';
            ctx.lineWidth = 1;
            lanes.forEach((_, lane) => {
              const y = Math.round(u.valToPos((lanes.length - 1 - lane) * 1.5, 'lanes', true)) + 0.5;
              ctx.beginPath();
              ctx.moveTo(u.bbox.left, y);
              ctx.lineTo(u.bbox.left + u.bbox.width, y);
              ctx.stroke();
            });
            ctx.restore();
          },
        ],
        setCursor: [
          (u) => {
            const index = u.cursor.idx;
            const left = u.cursor.left ?? -1;
            if (index === null || index === undefined || left < 0) {
              setTip(null);
              return;
            }
            const next = {
              index,
              left: u.over.offsetLeft + left,
              top: u.over.offsetTop + (u.cursor.top ?? 0),
              flip: left > u.over.clientWidth / 2,
            };
            setTip((shown) =>
              shown && shown.index === next.index && shown.left === next.left && shown.top === next.top ? shown : next,
            );
          },
        ],
        setScale: [
          (u, key) => {
            if (key !== 'x') return;
            const xs = u.data[0];
            const start = xs[0];
            const end = xs[xs.length - 1];
            const scale = u.scales.x;
            const narrower =
              start !== undefined &&
              end !== undefined &&
              scale?.min != null &&
              scale.max != null &&
              (scale.min > start + 1e-9 || scale.max < end - 1e-9);
            zoomedRef.current = narrower;
            setZoomed(narrower);
          },
        ],
      },
    };
    const made = new uPlot(options, columns(), element);
    plot.current = made;
    setShownHeight(first.height);
    const observer =
      typeof ResizeObserver === 'undefined'
        ? null
        : new ResizeObserver(() => {
            const next = size();
            if (next.width === made.width && next.height === made.height) return;
            measure(next.height);
            made.setSize(next);
            setShownHeight(next.height);
          });
    observer?.observe(element);
    return () => {
      observer?.disconnect();
      made.destroy();
      plot.current = null;
      zoomedRef.current = false;
      setTip(null);
    };
    // Rebuilt when the entries change; new samples go through setData below.
  }, [shape, labelKey]);

  // New samples come with every frame (up to 30 a second): the plot redraws at most 10 times.
  const redraw = useRef<ReturnType<typeof setTimeout> | null>(null);
  useEffect(() => {
    if (redraw.current !== null) return;
    redraw.current = setTimeout(() => {
      redraw.current = null;
      plot.current?.setData(columns(), !zoomedRef.current);
    }, REDRAW_MS);
  }, [samples]);
  useEffect(
    () => () => {
      if (redraw.current !== null) clearTimeout(redraw.current);
    },
    [],
  );

  const resizeTo = (next: number | null) => {
    const value = next === null ? null : clampHeight(next);
    setHeight(value);
    storeHeight(value);
  };

  const onKeyDown = (event: KeyboardEvent<HTMLDivElement>) => {
    const current = height ?? shownHeight;
    const moves: Record<string, number | null> = {
      ArrowDown: current + KEY_STEP,
      ArrowUp: current - KEY_STEP,
      PageDown: current + KEY_STEP * 5,
      PageUp: current - KEY_STEP * 5,
      Home: null,
    };
    if (!(event.key in moves)) return;
    event.preventDefault();
    resizeTo(moves[event.key] ?? null);
  };

  const onPointerDown = (event: PointerEvent<HTMLDivElement>) => {
    if (event.button !== 0) return;
    event.preventDefault();
    const startY = event.clientY;
    const startHeight = host.current?.clientHeight ?? shownHeight;
    const move = (moved: globalThis.PointerEvent) => resizeTo(startHeight + moved.clientY - startY);
    const end = () => {
      window.removeEventListener('pointermove', move);
      window.removeEventListener('pointerup', end);
      window.removeEventListener('pointercancel', end);
    };
    window.addEventListener('pointermove', move);
    window.addEventListener('pointerup', end);
    window.addEventListener('pointercancel', end);
  };

  const sample = tip ? samplesRef.current[tip.index] : undefined;
  // Fitted to a low panel, the plot still gives every lane and the axes room (the panel scrolls).
  const fitFloor = Math.max(MIN_HEIGHT, 60 + layout.lanes.length * LANE_PX + (layout.axes.length > 0 ? 90 : 0));

  return (
    <div className={`trend-chart${height === null ? ' trend-chart--fit' : ''}`} dir="ltr">
      <div
        ref={host}
        className="trend-chart__plot"
        data-testid="trend-plot"
        data-samples={samples.length}
        data-lanes={layout.lanes.map((entry) => entries[entry]).join('\n')}
        data-axes={layout.axes.map((axis) => axis.unit).join(' ')}
        data-height={shownHeight}
        style={height === null ? { minBlockSize: `${fitFloor}px` } : { blockSize: `${height}px` }}
      />
      {tip && sample ? (
        <div
          className={`trend-chart__tip${tip.flip ? ' trend-chart__tip--flip' : ''}`}
          data-testid="trend-tooltip"
          style={{ left: tip.left, top: tip.top }}
        >
          <div className="trend-chart__tip-time">
            {labels.time}: {+(sample.time_ms / 1000).toFixed(3)}
          </div>
          {entries.map((entry, index) => (
            <div key={entry} className="trend-chart__tip-row">
              <span className="trend-entry__swatch" style={{ background: TREND_COLORS[index % TREND_COLORS.length] }} />
              <code>{entry}</code> <span>{trendValueText(sample.values[index], types[index])}</span>
            </div>
          ))}
        </div>
      ) : null}
      <div
        className="trend-chart__handle"
        role="separator"
        aria-orientation="horizontal"
        aria-label={labels.resize}
        title={labels.resize}
        aria-valuemin={MIN_HEIGHT}
        aria-valuemax={MAX_HEIGHT}
        aria-valuenow={height ?? shownHeight}
        tabIndex={0}
        data-testid="trend-resize"
        onKeyDown={onKeyDown}
        onPointerDown={onPointerDown}
        onDoubleClick={() => resizeTo(null)}
      />
      {zoomed ? (
        <button
          type="button"
          className="button button--small trend-chart__reset"
          data-testid="trend-reset-zoom"
          onClick={() => {
            zoomedRef.current = false;
            setZoomed(false);
            plot.current?.setData(columns(), true);
          }}
        >
          {labels.reset}
        </button>
      ) : null}
    </div>
  );
}
