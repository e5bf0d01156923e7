/**
 * The virtualised list of networks every graphical editor shows a block as: only the networks
 * in and near the viewport are in the DOM, so a block of 500 networks opens and scrolls as fast as
 * one of five. Heights come from the editor (a LAD rung's height follows from its grid, an FBD
 * network's from its layout), so positions are known without measuring the DOM.
 */
import { forwardRef, useCallback, useEffect, useImperativeHandle, useMemo, useRef, useState, type ReactNode, type UIEvent } from 'react';

/** Pixels drawn above and below the viewport, so a short scroll shows drawn networks at once. */
const OVERSCAN_PX = 600;

export interface NetworkListHandle {
  /** Scrolls so that item `index` is in view (`start`: at the top; `nearest`: as little as needed). */
  scrollToIndex: (index: number, align?: 'start' | 'nearest') => void;
  /** The scrolling element (tests and benches read its scroll position). */
  element: () => HTMLDivElement | null;
}

export interface NetworkListProps {
  count: number;
  heightOf: (index: number) => number;
  renderItem: (index: number) => ReactNode;
  /** The items drawn in the viewport changed (monitoring subscribes only to these). */
  onVisibleChange?: (first: number, last: number) => void;
  /** What the heights depend on: a new value recomputes the offsets. */
  layoutKey?: unknown;
  className?: string;
  label: string;
  testId?: string;
}

/** The first index whose item ends below `y` (binary search on the prefix sums). */
function indexAt(offsets: readonly number[], y: number): number {
  let low = 0;
  let high = offsets.length - 2;
  while (low < high) {
    const middle = (low + high + 1) >> 1;
    if ((offsets[middle] ?? 0) <= y) low = middle;
    else high = middle - 1;
  }
  return Math.max(0, low);
}

export const NetworkList = forwardRef<NetworkListHandle, NetworkListProps>(function NetworkList(
  { count, heightOf, renderItem, onVisibleChange, layoutKey, className, label, testId },
  ref,
) {
  const scroller = useRef<HTMLDivElement>(null);
  const [view, setView] = useState({ top: 0, height: 800 });
  // offsets[i] is where item i starts; offsets[count] the total height.
  const offsets = useMemo(() => {
    const out = new Array<number>(count + 1);
    let y = 0;
    for (let i = 0; i < count; i += 1) {
      out[i] = y;
      y += heightOf(i);
    }
    out[count] = y;
    return out;
  }, [count, layoutKey, heightOf]);

  useEffect(() => {
    const element = scroller.current;
    if (!element) return;
    const measure = () => setView({ top: element.scrollTop, height: element.clientHeight || 800 });
    measure();
    if (typeof ResizeObserver === 'undefined') return;
    const observer = new ResizeObserver(measure);
    observer.observe(element);
    return () => observer.disconnect();
  }, []);

  const onScroll = useCallback((event: UIEvent<HTMLDivElement>) => {
    const element = event.currentTarget;
    setView((previous) =>
      previous.top === element.scrollTop && previous.height === element.clientHeight
        ? previous
        : { top: element.scrollTop, height: element.clientHeight || previous.height },
    );
  }, []);

  const total = offsets[count] ?? 0;
  const first = count === 0 ? 0 : indexAt(offsets, Math.max(0, view.top - OVERSCAN_PX));
  const last = count === 0 ? -1 : indexAt(offsets, view.top + view.height + OVERSCAN_PX);
  const visibleFirst = count === 0 ? 0 : indexAt(offsets, view.top);
  const visibleLast = count === 0 ? -1 : indexAt(offsets, Math.max(view.top, view.top + view.height - 1));

  const reported = useRef<string>('');
  useEffect(() => {
    const key = `${visibleFirst}:${visibleLast}`;
    if (key === reported.current) return;
    reported.current = key;
    onVisibleChange?.(visibleFirst, visibleLast);
  }, [visibleFirst, visibleLast, onVisibleChange]);

  useImperativeHandle(
    ref,
    () => ({
      scrollToIndex(index, align = 'nearest') {
        const element = scroller.current;
        if (!element || index < 0 || index >= count) return;
        const top = offsets[index] ?? 0;
        const bottom = offsets[index + 1] ?? top;
        let target = element.scrollTop;
        if (align === 'start' || top < element.scrollTop) target = top;
        else if (bottom > element.scrollTop + element.clientHeight) target = Math.min(top, bottom - element.clientHeight);
        if (target !== element.scrollTop) {
          element.scrollTop = target;
          setView({ top: element.scrollTop, height: element.clientHeight || 800 });
        }
      },
      element: () => scroller.current,
    }),
    [count, offsets],
  );

  const items: ReactNode[] = [];
  for (let index = first; index <= last && index < count; index += 1) {
    items.push(
      <div
        key={index}
        role="listitem"
        className="network-list__item"
        style={{ position: 'absolute', top: offsets[index], left: 0, right: 0, height: heightOf(index) }}
        data-index={index}
      >
        {renderItem(index)}
      </div>,
    );
  }

  return (
    <div ref={scroller} className={`network-list ${className ?? ''}`} onScroll={onScroll} data-testid={testId}>
      <div role="list" aria-label={label} className="network-list__body" style={{ position: 'relative', height: total }}>
        {items}
      </div>
    </div>
  );
});
