/**
 * What is selected in a Graph editor: a step or a transition of one sequencer of one block. The
 * shell holds it and passes it to the chart, the step view and the dialogs, so switching views
 * keeps the selection.
 */
export type GraphItem = { kind: 'step'; name: string } | { kind: 'transition'; name: string };

export interface GraphSelection {
  /** Index in the document's blocks. */
  block: number;
  /** Index in the block's sequencers. */
  sequencer: number;
  item: GraphItem | null;
}

export function sameItem(a: GraphItem | null, b: GraphItem | null): boolean {
  return a === b || (a !== null && b !== null && a.kind === b.kind && a.name === b.name);
}
