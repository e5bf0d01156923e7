/**
 * The pure parts of monitoring in the editor: which block a line belongs to, the breakpoint
 * store, the STL status rows and their pane, the SCL inline texts, the MON604 move offer.
 */
import { beforeEach, describe, expect, it } from 'vitest';
import type { BlockStatus, InstructionStatus } from '../../frontend/src/api/monitor';
import type { TreeBlock } from '../../frontend/src/api/types';
import { blockAtLine, blockName, blockToMonitor, sameBlockName } from '../../frontend/src/editor/monitoring/blockAtLine';
import {
  BREAKPOINTS_STORAGE_KEY,
  createBreakpointStore,
  requestsFor,
} from '../../frontend/src/editor/monitoring/breakpointStore';
import { formatValue, inlineText, inlineTexts, visibleTexts } from '../../frontend/src/editor/monitoring/inlineValues';
import { nextCodeLine } from '../../frontend/src/editor/monitoring/nextCodeLine';
import { StatusColumnPane, visibleLines } from '../../frontend/src/editor/monitoring/statusColumnPane';
import { formatAccu, formatStatusWord, statusRows } from '../../frontend/src/editor/monitoring/statusColumns';
import { formatPointer, registerRows } from '../../frontend/src/panels/DebugPanel';

const block = (kind: TreeBlock['kind'], number: number, file: string, line: number | null): TreeBlock => ({
  kind,
  number,
  name: '',
  title: '',
  language: 'stl',
  file,
  line,
});

describe('the block at a line', () => {
  const blocks = [
    block('FC', 1, 'lib.awl', 10),
    block('DB', 5, 'lib.awl', 30),
    block('FB', 2, 'lib.awl', 40),
    block('OB', 1, 'main.awl', 1),
    block('DB', 6, 'lib.awl', null),
  ];

  it('is the last code block header at or above the line, in the same file', () => {
    expect(blockAtLine(blocks, 'lib.awl', 10)?.number).toBe(1);
    expect(blockAtLine(blocks, 'lib.awl', 39)?.kind).toBe('FC'); // a DB is no code block
    expect(blockAtLine(blocks, 'lib.awl', 40)?.kind).toBe('FB');
    expect(blockAtLine(blocks, 'lib.awl', 500)?.kind).toBe('FB');
    expect(blockAtLine(blocks, 'main.awl', 3)?.kind).toBe('OB');
  });

  it('is the first block for a line above every header, none for a file without code', () => {
    expect(blockAtLine(blocks, 'lib.awl', 2)?.kind).toBe('FC');
    expect(blockAtLine(blocks, 'symbols.sdf', 2)).toBeNull();
  });

  it("follows the caret while it is in view, else the first visible line", () => {
    expect(blockToMonitor(blocks, 'lib.awl', 12, { first: 5, last: 25 })?.kind).toBe('FC');
    expect(blockToMonitor(blocks, 'lib.awl', 12, { first: 41, last: 60 })?.kind).toBe('FB');
    expect(blockToMonitor(blocks, 'lib.awl', 45, null)?.kind).toBe('FB');
  });

  it('names blocks as the protocol does', () => {
    expect(blockName({ kind: 'FC', number: 10 })).toBe('FC10');
    expect(sameBlockName('FC 10', 'fc10')).toBe(true);
    expect(sameBlockName('FC1', 'FC10')).toBe(false);
  });
});

describe('the breakpoint store', () => {
  let saved: Record<string, string>;
  const storage = {
    getItem: (key: string) => saved[key] ?? null,
    setItem: (key: string, value: string) => {
      saved[key] = value;
    },
  };
  beforeEach(() => {
    saved = {};
  });

  it('toggles, keeps conditions and enabled flags, and survives a reload', () => {
    const store = createBreakpointStore(storage);
    let changes = 0;
    store.subscribe(() => (changes += 1));
    store.toggle(1, 'Scale.scl', 17);
    store.put(1, 'Scale.scl', 20, { condition: '  #Raw > 100 ' });
    store.put(2, 'OB1.awl', 5, { enabled: false });
    expect(changes).toBe(3);
    expect(store.find(1, 'Scale.scl', 20)).toEqual({ projectId: 1, file: 'Scale.scl', line: 20, condition: '#Raw > 100', enabled: true });
    expect(store.ofFile(1, 'Scale.scl').map((bp) => bp.line)).toEqual([17, 20]);

    const again = createBreakpointStore(storage);
    expect(again.list()).toEqual(store.list());
    again.toggle(1, 'Scale.scl', 17);
    expect(again.find(1, 'Scale.scl', 17)).toBeUndefined();
    // An empty condition is none.
    again.put(1, 'Scale.scl', 20, { condition: '   ' });
    expect(again.find(1, 'Scale.scl', 20)?.condition).toBeNull();
  });

  it('moves a breakpoint to another line, replacing one there', () => {
    const store = createBreakpointStore(storage);
    store.put(1, 'a.scl', 3, { condition: 'x > 1' });
    store.toggle(1, 'a.scl', 7);
    store.move(1, 'a.scl', 3, 7);
    expect(store.ofFile(1, 'a.scl')).toEqual([{ projectId: 1, file: 'a.scl', line: 7, condition: 'x > 1', enabled: true }]);
    store.clear(2);
    expect(store.list()).toHaveLength(1);
    store.clear();
    expect(store.list()).toHaveLength(0);
  });

  it('ignores what it cannot read, and works without storage', () => {
    saved[BREAKPOINTS_STORAGE_KEY] = JSON.stringify([{ projectId: 1, file: 'x', line: 0, condition: null, enabled: true }, 'junk', { projectId: 1, file: 'ok.awl', line: 2, condition: null, enabled: true }]);
    expect(createBreakpointStore(storage).list().map((bp) => bp.file)).toEqual(['ok.awl']);
    saved[BREAKPOINTS_STORAGE_KEY] = '{not json';
    expect(createBreakpointStore(storage).list()).toEqual([]);
    const none = createBreakpointStore(null);
    none.toggle(1, 'a.awl', 1);
    expect(none.list()).toHaveLength(1);
  });

  it('asks the server for the enabled breakpoints of one project only', () => {
    const store = createBreakpointStore(storage);
    store.put(1, 'a.scl', 3, { condition: '#x = 2' });
    store.put(1, 'a.scl', 5, { enabled: false });
    store.toggle(2, 'b.awl', 4);
    expect(requestsFor(store.list(), 1)).toEqual([{ key: '1:a.scl:3', location: { file: 'a.scl', line: 3 }, condition: '#x = 2' }]);
  });
});

const instruction = (index: number, line: number | null, values: Partial<InstructionStatus> = {}): InstructionStatus => ({
  index,
  line,
  rlo: 0,
  sta: 0,
  accu1: 0,
  accu2: 0,
  stw: 0,
  ar1: 0,
  ar2: 0,
  operand: null,
  ...values,
});

const stl = (instructions: InstructionStatus[]): BlockStatus => ({ block: 'OB1', language: 'stl', elements: [], graph: null, scan: 7, instructions, lines: [] });

describe('the STL status rows', () => {
  it('formats ACCU values signed in decimal or as STEP 7 hexadecimal, the status word as 9 bits', () => {
    expect(formatAccu(42, 'dec')).toBe('42');
    expect(formatAccu(0xffffffff, 'dec')).toBe('-1');
    expect(formatAccu(0xffffffff, 'hex')).toBe('16#FFFF_FFFF');
    expect(formatAccu(42, 'hex')).toBe('16#0000_002A');
    expect(formatStatusWord(0b100000111)).toBe('100000111');
    expect(formatStatusWord(5)).toBe('000000101');
  });

  it('has one row per executed line, after its last instruction; lines that did not run have none', () => {
    const rows = statusRows(
      stl([
        instruction(0, 4, { rlo: 1, sta: 1, stw: 6 }),
        instruction(2, 5, { accu1: 3 }),
        instruction(1, 5, { accu1: 9 }),
        instruction(3, null),
      ]),
      'dec',
    );
    expect([...rows.keys()]).toEqual([4, 5]);
    expect(rows.get(4)).toEqual({ line: 4, rlo: '1', sta: '1', accu1: '0', accu2: '0', stw: '000000110' });
    expect(rows.get(5)?.accu1).toBe('3');
    expect(statusRows(null, 'dec').size).toBe(0);
    expect(statusRows({ ...stl([instruction(0, 4)]), language: 'scl' }, 'dec').size).toBe(0);
  });
});

describe('the status column pane', () => {
  const geometry = (first: number, last: number, scrollTop = 0) => ({
    getScrollTop: () => scrollTop,
    getTopForLineNumber: (line: number) => (line - 1) * 20,
    getVisibleRanges: () => [{ startLineNumber: first, endLineNumber: last }],
  });

  it('draws only the visible lines at their heights, and reuses its rows', () => {
    const body = document.createElement('div');
    const pane = new StatusColumnPane(body, 20);
    const many = statusRows(stl(Array.from({ length: 5000 }, (_, k) => instruction(k, k + 1, { rlo: k % 2 }))), 'dec');
    expect(pane.render(many, geometry(101, 130, 2000))).toBe(30);
    const rows = [...body.querySelectorAll<HTMLElement>('.stl-status__row')];
    expect(rows).toHaveLength(30);
    expect(rows[0]!.dataset.line).toBe('101');
    expect(rows[0]!.style.transform).toBe('translateY(0px)');
    expect(rows[1]!.style.transform).toBe('translateY(20px)');
    expect(rows[0]!.querySelector('[data-column="rlo"]')!.textContent).toBe('0');
    expect(rows[1]!.querySelector('[data-column="rlo"]')!.textContent).toBe('1');

    // Scrolled a little: the same elements, new places and texts.
    expect(pane.render(many, geometry(102, 111, 2020))).toBe(10);
    const again = [...body.querySelectorAll<HTMLElement>('.stl-status__row')];
    expect(again[0]).toBe(rows[0]);
    expect(again[0]!.dataset.line).toBe('102');
    expect(again.filter((row) => !row.hidden)).toHaveLength(10);
    pane.clear();
    expect(body.children).toHaveLength(0);
  });

  it('knows the visible lines across folded ranges', () => {
    expect(
      visibleLines({ getScrollTop: () => 0, getTopForLineNumber: () => 0, getVisibleRanges: () => [
        { startLineNumber: 3, endLineNumber: 9 },
        { startLineNumber: 20, endLineNumber: 31 },
      ] }),
    ).toEqual({ first: 3, last: 31 });
    expect(visibleLines({ getScrollTop: () => 0, getTopForLineNumber: () => 0, getVisibleRanges: () => [] })).toBeNull();
  });
});

describe('the SCL inline values', () => {
  it('writes values as SCL does', () => {
    expect(formatValue(true)).toBe('TRUE');
    expect(formatValue(false)).toBe('FALSE');
    expect(formatValue(42)).toBe('42');
    expect(formatValue(42.5)).toBe('42.5');
    expect(formatValue(0.1 + 0.2)).toBe('0.3');
    expect(formatValue('AB')).toBe("'AB'");
    expect(formatValue(null)).toBe('?');
  });

  it('lists a line’s variables by name, and only the visible lines', () => {
    expect(inlineText({ Pump: true, Level: 42.5 })).toBe('Level = 42.5  Pump = TRUE');
    const texts = inlineTexts({
      block: 'FC10',
      language: 'scl',
      elements: [],
      graph: null,
      scan: 3,
      instructions: [],
      lines: [
        { line: 17, values: { Raw: 13824, Low: 0, High: 100, Scale: 50 } },
        { line: 18, values: {} },
        { line: 40, values: { x: 1 } },
      ],
    });
    expect([...texts.keys()]).toEqual([17, 40]);
    expect(texts.get(17)).toBe('High = 100  Low = 0  Raw = 13824  Scale = 50');
    expect(visibleTexts(texts, 1, 30)).toEqual([[17, texts.get(17)]]);
    expect(inlineTexts(stl([])).size).toBe(0);
  });
});

describe('the debug panel’s formats and the MON604 move offer', () => {
  it('shows the registers in STEP 7’s order', () => {
    expect(registerRows({ accu1: 42, accu2: 0xffffffff, ar1: (12 << 3) | 3, ar2: 0, stw: 7, rlo: 1, sta: 0 })).toEqual([
      ['ACCU1', '16#0000_002A  (42)'],
      ['ACCU2', '16#FFFF_FFFF  (-1)'],
      ['AR1', 'P#12.3'],
      ['AR2', 'P#0.0'],
      ['STW', '000000111'],
      ['RLO', '1'],
      ['STA', '0'],
    ]);
    expect(formatPointer(8)).toBe('P#1.0');
  });

  it('reads the next line with code from MON604', () => {
    expect(nextCodeLine({ code: 'MON604', params: { where: 'a.scl line 3', hint: ' (the next line with code is 17)' } })).toBe(17);
    expect(nextCodeLine({ code: 'MON604', params: { next_line: 9 } })).toBe(9);
    expect(nextCodeLine({ code: 'MON604', params: { where: 'a.scl line 99', hint: '' } })).toBeNull();
    expect(nextCodeLine({ code: 'MON612', params: { hint: '12' } })).toBeNull();
    expect(nextCodeLine(null)).toBeNull();
  });
});
