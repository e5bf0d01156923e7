/**
 * The layout worker started and warmed up on a chart's shape before a user waits for a chart:
 * loading elkjs and its first layouts take longer than a large chart's own layout. It happens
 * when the project tree lists a `.graph` file (a chart is then likely to be opened) or at the
 * latest when a `.graph` tab opens, never at page load: a page that shows no diagram loads no
 * elkjs (a classroom's network). The worker answers a real request before each further
 * warm-up piece, so warming never delays a chart.
 */
import { warmUpLayout } from '../diagram/elk/elkClient';
import { sequencerGraph, warmUpSequencer } from './chartGraph';

/** Layouts of the warm-up chart: enough for V8 to compile elkjs's code for charts (measured in node: the fourth is ~3x faster than the first). */
const WARM_UP_LAYOUTS = 8;
let warmedUp = false;

export function warmUpCharts(): void {
  if (warmedUp || typeof Worker === 'undefined') return;
  warmedUp = true;
  warmUpLayout(sequencerGraph(warmUpSequencer()), WARM_UP_LAYOUTS);
}
