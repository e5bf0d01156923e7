// Generated from backend/nasaq/monitor/protocol.py; do not edit. Regenerate with
// `.venv/bin/python -m nasaq.monitor.typescript --write`.

export const PROTOCOL_VERSION = 1;

export type ClientMessage =
  | SubscribeCpu
  | Watch
  | OpenBlock
  | Trend
  | SessionState
  | Run
  | Stop
  | Restart
  | SetTime
  | SetInput
  | Modify
  | Force
  | Unforce
  | SetBreakpoint
  | ClearBreakpoint
  | Continue
  | Step
  | RunScans
  | PlantOperate
  | PlantFault
  | PlantReset
  | GraphControl;

/** CPU state in every frame where it changed (mode, scans, clock, cycle statistic). */
export interface SubscribeCpu {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'subscribe_cpu';
  on?: boolean;
}

/**
 * Replaces the watch list: addresses (`MW10`, `DB1.DBW2`, `T1`), symbols
 * (`"Motor"`), DB and instance-DB members (`DB1.level`, `"Tank".level`, `DB5.t1.ET`)
 * and, while the CPU holds, locals of the held block (`#count`).
 */
export interface Watch {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'watch';
  entries: string[];
}

/**
 * The block whose status (per STL instruction, per SCL line, per LAD/FBD element) the
 * frames carry; None: none. `networks`: only these networks (1-based) are recorded and
 * reported, the ones an editor shows; None: all of them.
 */
export interface OpenBlock {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'open_block';
  block: string | null;
  networks?: number[] | null;
}

/**
 * Values sampled at the end of every scan, sent as batches of samples. The same entries as
 * the session already records (another tab's, or a reloaded page's) start with the samples
 * recorded so far: the first frame carries that history.
 */
export interface Trend {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'trend';
  entries: string[];
}

/**
 * What the session keeps for whoever attaches (a reload, a second tab, another browser):
 * the ack lists its breakpoints and the entries of the trend it records.
 */
export interface SessionState {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'session_state';
}

export interface Run {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'run';
}

export interface Stop {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'stop';
}

/** Warm restart (OB100), or cold restart (OB102) with `cold`; the CPU goes to RUN. */
export interface Restart {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'restart';
  cold?: boolean;
}

export interface SetTime {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'set_time';
  mode: 'virtual' | 'real' | 'fast' | 'pause';
  cycle_ms?: number | null;
}

/** Drives a peripheral input (`I0.3`, `IW4`, or an input's symbol). */
export interface SetInput {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'set_input';
  address: string;
  value: boolean | number | string | null;
}

/** Writes a value once (memory, DB member, or a local of the held block). */
export interface Modify {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'modify';
  target: string;
  value: boolean | number | string | null;
}

export interface Force {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'force';
  address: string;
  value: boolean | number | string | null;
}

/** Removes the force of `address`, or every force when it is None. */
export interface Unforce {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'unforce';
  address?: string | null;
}

/**
 * `condition`: `<operand> <op> <value>` with op one of = == <> < > <= >=, the operand an
 * address, symbol, `#local`, or a register (RLO, STA, ACCU1, ACCU2, AR1, AR2, OV, OS, BR).
 */
export interface SetBreakpoint {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'set_breakpoint';
  location: Location;
  condition?: string | null;
}

/** Clears breakpoint `id`, or all of them when it is None. */
export interface ClearBreakpoint {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'clear_breakpoint';
  id?: number | null;
}

export interface Continue {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'continue';
}

/**
 * From a hold: to the next STL instruction, SCL statement, network, or the next scan's end.
 * `into` enters called blocks; without it a step stays in the block (or returns to its caller).
 * From STOP or pause, `scan` runs one scan. `transition`: from a hold or a running (or
 * paused) CPU, runs until a step of any S7-Graph FB is about to become active (one transition
 * fires), then holds there.
 */
export interface Step {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'step';
  by: 'instruction' | 'statement' | 'network' | 'scan' | 'transition';
  into?: boolean;
}

/** Runs `count` scans, then pauses. */
export interface RunScans {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'run_scans';
  count: number;
}

/**
 * The operator panel: presses, releases or turns a plant's control. `value` is the level
 * the PLC input sees (an NC stop button pressed is 0), a word control's value 0..65535.
 */
export interface PlantOperate {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'plant_operate';
  control: string;
  value: number | boolean;
}

/** Injects (`on`) or clears an injectable fault of the plant (a stuck sensor, a jam). */
export interface PlantFault {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'plant_fault';
  fault: string;
  on?: boolean;
}

/**
 * Puts the plant back in its initial state: its raised faults cleared, the faults the
 * plant file injects from the start injected again.
 */
export interface PlantReset {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'plant_reset';
}

/**
 * S7-Graph's Control Sequencer (Debug > Control Sequencer) on the instance DB `db` of a
 * Graph FB (`DB1` or its symbol): select a mode (`auto`, `man`, `tap`, `top`),
 * acknowledge a supervision error (`ack`), switch step `step` on or off in MAN
 * (`step_on`, `step_off`), `push` (T_PUSH once), `init` or `off` the sequencer for
 * one call, switch its interlock or supervision check on or off. The FB acts at its next call
 * (the instance DB's mailbox, `nasaq/lang/graph/SEMANTICS.md` §4).
 */
export interface GraphControl {
  /** Echoed in the ack or error that answers it */
  ref?: number | null;
  type: 'graph_control';
  db: string;
  op: 'auto' | 'man' | 'tap' | 'top' | 'ack' | 'step_on' | 'step_off' | 'push' | 'init' | 'off' | 'interlock_on' | 'interlock_off' | 'supervision_on' | 'supervision_off';
  step?: number | null;
}

/**
 * Where a breakpoint goes: a source line (`file` + `line`, STL or SCL), or a block with
 * an STL instruction index or a network (1-based), or a block with a line of its source; or
 * `step`, a step number of an S7-Graph FB (`block`, or `file` when the file holds one
 * Graph FB): the CPU holds when that step is about to become active, however it is.
 */
export interface Location {
  file?: string | null;
  block?: string | null;
  line?: number | null;
  network?: number | null;
  instruction?: number | null;
  step?: number | null;
}

export type ServerMessage = Hello | Ack | ProtocolError | Frame;

export interface Hello {
  type: 'hello';
  session: string;
  /** This connection's number (e.g. for the trend CSV export) */
  client: number;
  protocol: number;
  max_frames_per_second: number;
  max_watch_entries: number;
}

export interface Ack {
  type: 'ack';
  ref: number | null;
  result: Record<string, unknown> | null;
}

/** A message the server could not carry out; `code` is from the diagnostics catalogue. */
export interface ProtocolError {
  type: 'error';
  ref: number | null;
  code: string;
  key: string;
  message: string;
  params: Record<string, unknown>;
}

export interface Frame {
  type: 'frame';
  seq: number;
  cpu: CpuState | null;
  watch: Record<string, WatchValue> | null;
  block: BlockStatus | null;
  trend: TrendSample[] | null;
  hold: HoldState | null;
  /** The hold of the previous frame has ended */
  released: boolean;
  diagnostics: DiagnosticEntry[] | null;
  /** The virtual plant, when it changed (null: unchanged or none) */
  plant: PlantFrame | null;
  /** A download took the plant away (the project has none now) */
  plant_removed: boolean;
}

export interface CpuState {
  mode: 'RUN' | 'STOP' | 'HOLD';
  time_mode: 'virtual' | 'real' | 'fast' | 'pause';
  cycle_ms: number;
  scans: number;
  time_ms: number;
  stop_code: string | null;
  stop_reason: string | null;
  cycle: CycleStats | null;
  forced: ForcedValue[];
}

/** A watch entry's value; `forced` when a force holds it; `error` when it has none. */
export interface WatchValue {
  value: boolean | number | string | null;
  forced: boolean;
  error: string | null;
}

/**
 * One sampled execution of the open block: rows for the instructions that ran, and for a
 * LAD/FBD block the status of each element that ran (an element absent did not run); for an
 * S7-Graph FB, `graph` (null for every other block, and for a Graph FB that did not run).
 */
export interface BlockStatus {
  block: string;
  language: 'stl' | 'scl' | 'lad' | 'fbd' | 'graph';
  scan: number;
  instructions: InstructionStatus[];
  lines: LineStatus[];
  elements: ElementStatus[];
  graph: GraphStatus | null;
}

export interface TrendSample {
  scan: number;
  time_ms: number;
  values: Array<boolean | number | string | null>;
}

/**
 * Where the CPU holds mid-scan: the innermost block first in `call_stack`. At a step
 * activation of an S7-Graph FB (a step breakpoint, a single step by transition):
 * `graph_step` is the number of the step about to become active, `graph_block` its FB.
 */
export interface HoldState {
  reason: 'breakpoint' | 'step';
  breakpoint: number | null;
  location: StackFrame;
  registers: Record<string, number>;
  locals: Variable[];
  call_stack: StackFrame[];
  graph_step: number | null;
  graph_block: string | null;
}

export interface DiagnosticEntry {
  time_ms: number;
  code: string;
  /** English; the UI says `key` with `params` in its language */
  message: string;
  block: string | null;
  network: number | null;
  line: number | null;
  key: string;
  params: Record<string, string | number | boolean | null>;
}

/**
 * The session's virtual plant as the drawing animates it: `state` (levels, positions,
 * counts; what a scenario's `plant.<name>` expects), every signal's value (sensors and panel
 * controls as the PLC inputs get them, actuators as the outputs drive them), the active faults
 * and the wiring (signal -> address).
 */
export interface PlantFrame {
  kind: string;
  /** Virtual time the plant has run */
  time_ms: number;
  state: Record<string, boolean | number | string>;
  signals: Record<string, number>;
  faults: string[];
  wiring: Record<string, string>;
}

/** Wall-clock milliseconds the scans took (the program's work, not the cycle wait). */
export interface CycleStats {
  last_ms: number;
  min_ms: number;
  max_ms: number;
  avg_ms: number;
}

export interface ForcedValue {
  address: string;
  value: number;
}

/** The registers as STL instruction `index` left them (STEP 7's block status columns). */
export interface InstructionStatus {
  index: number;
  line: number | null;
  rlo: number;
  sta: number;
  accu1: number;
  accu2: number;
  stw: number;
  ar1: number;
  ar2: number;
  operand: boolean | number | string | null;
}

/** An SCL line: the variables its code read or wrote, with their last values. */
export interface LineStatus {
  line: number;
  values: Record<string, boolean | number | string | null>;
}

/**
 * A LAD/FBD element in one sampled execution, as TIA Portal draws its power flow.
 *
 * `value`: the operand as the element read or wrote it (a contact's or status contact's
 * bit, a coil's bit after it, a midline's bit, an edge's memory bit, POS/NEG the bit it
 * watches; a timer or counter box or coil: its current value as the watch shows it).
 * `out`: the element's Boolean result (contacts: null, the client computes the flow from
 * `value` and the tree; NOT, an edge, a midline: the power flow out of it; a compare or
 * POS/NEG box: its result, which the flow passes in series; an EN/ENO box or a call: its ENO;
 * a timer, counter or flip-flop box: its Q; a coil, jump or RET: the power flow into it).
 * `pins`: a box's pins by name, inputs as read and outputs as written (a pin whose
 * instructions did not run, as in a box whose EN was 0, is absent). An S7-Graph FB's conditions
 * report the same way by origin (`T3/e2`, `S2/C/e1`, `S2/V/e1`, `PRE1/e2`), and its
 * action rows as `S2/A1`: `value` the operand as the row left it, `out` whether a bit row
 * drove its bit (`PROTOCOL.md`, S7-Graph element status).
 */
export interface ElementStatus {
  /** 1-based network; 0 for an S7-Graph FB's elements */
  network: number;
  /**
   * The element id in its network (e1, e2 ... in reading order); in an S7-Graph FB the origin: T3/e2, S2/C/e1, S2/V/e1, S2/A1, PRE1/e2, POST1/e1
   */
  id: string;
  value: boolean | number | string | null;
  out: boolean | null;
  pins: Record<string, boolean | number | string | null>;
}

/**
 * The sequencer state of an S7-Graph FB, read from the instance DB its sampled call used
 * (`db`) at the end of that scan: the operating mode and every step and transition.
 */
export interface GraphStatus {
  /** The instance read, 'DB1'; a multi-instance: 'DB1' and 'at' */
  db: string;
  /** Byte offset of the instance in db (multi-instance) */
  at: number;
  mode: 'AUTO' | 'MAN' | 'TAP' | 'TOP' | null;
  steps: GraphStepStatus[];
  transitions: GraphTransitionStatus[];
}

export interface StackFrame {
  block: string;
  instruction: number;
  line: number | null;
  file: string | null;
  network: number | null;
}

export interface Variable {
  name: string;
  type: string;
  value: boolean | number | string | null;
}

/**
 * A step of an S7-Graph FB as the chart draws it online: `disturbed` is an active step
 * with an interlock error (`interlock_error`, LA) or a supervision error not yet
 * acknowledged (`supervision_error`, VA). `t_ms`/`u_ms`: its time active (current or
 * last activation), and the same without the time spent disturbed.
 */
export interface GraphStepStatus {
  number: number;
  name: string;
  state: 'inactive' | 'active' | 'disturbed';
  t_ms: number;
  u_ms: number;
  interlock_error: boolean;
  supervision_error: boolean;
}

/** A transition: `tt`, its condition was evaluated true in the FB's last call. */
export interface GraphTransitionStatus {
  number: number;
  name: string;
  tt: boolean;
}
