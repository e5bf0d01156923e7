/**
 * The trend plot: uPlot (bundled, loaded with the trend view's first chart) drawing each entry
 * against the simulated time. Drag across the plot to zoom in on a time span; double-click or
 * "Reset zoom" shows everything again. While zoomed, new samples do not move the view.
 */
import { useEffect, useMemo, useRef, useState } from 'react';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import type { TrendSample } from '../api/monitor';
import { TREND_COLORS } from './trendColors';
import { numericValue } from './watchFormat';


export interface TrendChartProps {
  entries: readonly string[];
  types: readonly string[];
  samples: readonly TrendSample[];
  timeLabel: string;
  resetZoomLabel: string;
}

/** uPlot's columns: simulated time in seconds, then one column per entry. */
export function trendColumns(samples: readonly TrendSample[], count: number): uPlot.AlignedData {
  const x = samples.map((sample) => sample.time_ms / 1000);
  const ys = Array.from({ length: count }, (_, index) => samples.map((sample) => numericValue(sample.values[index])));
  return [x, ...ys];
}

const HEIGHT = 130;

export default function TrendChart({ entries, types, samples, timeLabel, resetZoomLabel }: TrendChartProps) {
  const host = useRef<HTMLDivElement>(null);
  const plot = useRef<uPlot | null>(null);
  const zoomedRef = useRef(false);
  const [zoomed, setZoomed] = useState(false);
  const data = useMemo(() => trendColumns(samples, entries.length), [samples, entries.length]);
  const dataRef = useRef(data);
  dataRef.current = data;
  const shape = `${entries.join('\n')}|${types.join(',')}`;

  useEffect(() => {
    const element = host.current;
    if (!element) return;
    const options: uPlot.Options = {
      width: Math.max(200, element.clientWidth),
      height: HEIGHT,
      legend: { show: false },
      scales: { x: { time: false } },
      cursor: { drag: { x: true, y: false, setScale: true } },
      axes: [
        { label: timeLabel, labelSize: 18, size: 32, values: (_u, ticks) => ticks.map((tick) => `${+tick.toFixed(3)}`) },
        { size: 56 },
      ],
      series: [
        { label: timeLabel },
        ...entries.map((entry, index) => ({
          label: entry,
          stroke: TREND_COLORS[index % TREND_COLORS.length],
          width: 1.5,
          ...(types[index] === 'BOOL' && uPlot.paths.stepped ? { paths: uPlot.paths.stepped({ align: 1 }) } : {}),
        })),
      ],
      hooks: {
        setScale: [
          (u, key) => {
            if (key !== 'x') return;
            const xs = u.data[0];
            const first = xs[0];
            const last = xs[xs.length - 1];
            const scale = u.scales.x;
            const narrower =
              first !== undefined &&
              last !== undefined &&
              scale?.min != null &&
              scale.max != null &&
              (scale.min > first + 1e-9 || scale.max < last - 1e-9);
            zoomedRef.current = narrower;
            setZoomed(narrower);
          },
        ],
      },
    };
    const made = new uPlot(options, dataRef.current, element);
    plot.current = made;
    const observer =
      typeof ResizeObserver === 'undefined'
        ? null
        : new ResizeObserver(() => made.setSize({ width: Math.max(200, element.clientWidth), height: HEIGHT }));
    observer?.observe(element);
    return () => {
      observer?.disconnect();
      made.destroy();
      plot.current = null;
      zoomedRef.current = false;
    };
    // Rebuilt when the entries change; new samples go through setData below.
  }, [shape, timeLabel]);

  useEffect(() => {
    plot.current?.setData(data, !zoomedRef.current);
  }, [data]);

  return (
    <div className="trend-chart" dir="ltr">
      <div ref={host} className="trend-chart__plot" data-testid="trend-plot" data-samples={samples.length} />
      {zoomed ? (
        <button
          type="button"
          className="button button--small trend-chart__reset"
          data-testid="trend-reset-zoom"
          onClick={() => {
            zoomedRef.current = false;
            setZoomed(false);
            plot.current?.setData(dataRef.current, true);
          }}
        >
          {resetZoomLabel}
        </button>
      ) : null}
    </div>
  );
}
