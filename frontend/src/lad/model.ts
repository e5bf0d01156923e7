// Generated from backend/nasaq/lang/lad/ (model.py, fbd.py, layout.py, layout_fbd.py);
// do not edit. Regenerate with `.venv/bin/python -m nasaq.lang.lad.typescript --write`.

/**
 * A code block written in LAD or FBD: its header as in an STL source (kind, number or
 * name, title, the interface declaration text) and its networks.
 */
export interface LadBlock {
  language: 'LAD' | 'FBD';
  kind: 'OB' | 'FB' | 'FC';
  /** 'FC 10', '"Motor"', 'OB 1' as an STL source names it */
  name: string;
  /** FC only: VOID, INT, ... */
  return_type: string | null;
  title: string;
  /** The VAR sections as STL/SCL source text, copied as they are */
  declarations: string;
  networks: Network[];
}

/**
 * One network: a rung (LAD; FBD shows the same tree), an optional jump label at its
 * start (`LABEL`), its title and comment.
 *
 * A rung being drawn may have no outputs yet: an empty rung (a new network; it lowers to an
 * empty network, or to the label's `NOP 0`) or logic still waiting for its coil, which the
 * lowering reports (LAD211) as TIA Portal reports an unfinished network at compile time.
 *
 * A network without LAD shape stays STL, as in STEP 7's LAD view of an STL block: `stl`
 * holds its instructions as written (label included) and `stl_reason` the code of the
 * reason it does not convert (`LAD3xx`); it then has no logic and no outputs.
 */
export interface Network {
  title: string;
  comment: string;
  label: string | null;
  logic: Series;
  outputs: Output[];
  stl: string | null;
  stl_reason: string | null;
}

/** Elements one after the other (AND). Empty: the rail itself (always powered). */
export interface Series {
  elements: Element[];
}

/** One branch at the rung's end: optional conditions of its own, then its final element. */
export interface Output {
  conditions: Series;
  target: Final;
}

/** An element of a series, told apart by its `kind`. */
export type Element = Contact | StatusContact | Invert | EdgeContact | Midline | Box | Parallel;

/** A normally open (`negated` False, STL `A`) or normally closed (`AN`) contact. */
export interface Contact {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'contact';
  operand: string;
  negated: boolean;
}

/**
 * A contact on a status bit or a result of the last math instruction (STL `A OV`,
 * `A ==0` ...); `negated` is the normally closed form.
 */
export interface StatusContact {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'status';
  bit: 'OV' | 'OS' | 'BR' | 'UO' | '==0' | '<>0' | '>0' | '<0' | '>=0' | '<=0';
  negated: boolean;
}

/** `--|NOT|--`: inverts the power flow (STL `NOT`). */
export interface Invert {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'not';
}

/**
 * `--(P)--` / `--(N)--` in the rung: the power flow for one scan at a rising/falling
 * edge of the flow before it; `memory` keeps its previous state (STL `FP`/`FN`). The
 * address edge boxes (POS/NEG, with an M_BIT pin) are boxes.
 */
export interface EdgeContact {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'edge';
  edge: 'P' | 'N';
  memory: string;
}

/**
 * `--(#)--`: the power flow so far is written to `operand` and flows on (STL `=` in
 * the middle of a chain, reloaded with `A`).
 */
export interface Midline {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'midline';
  operand: string;
}

/**
 * An element with named pins (see `nasaq.lang.lad.boxes`): `name` is the box
 * (`CMP>=I`, `MOVE`, `ADD_I`, `S_ODT`, `SR`, `FC 10`, `"Motor"`, `SFB 4`);
 * `instance` the instance DB of an FB/SFB call (`DB 10`, or `#inst` for a
 * multi-instance). `inputs`/`outputs` map a pin to its operand; a Boolean input fed by
 * logic rather than an operand holds a :class:`Series` (in LAD: a branch drawn into the pin).
 */
export interface Box {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'box';
  name: string;
  instance: string | null;
  inputs: Record<string, string | Series>;
  outputs: Record<string, string>;
}

/**
 * Branches side by side (OR): every branch starts from the power flow into the parallel,
 * and the flow passes when it passes any branch (a wired OR, as in IEC 61131-3 ladder). An
 * element in a branch sees the flow at its position: a NOT after `a` in a branch gives
 * NOT(flow into the parallel AND a).
 */
export interface Parallel {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'parallel';
  branches: Series[];
}

/** The final element of an output, told apart by its `kind`. */
export type Final = Coil | Jump | Return | OpenDb | Box;

/**
 * A rung's end: `=`/`S`/`R` on a bit, a timer coil with its time value (`value`:
 * `S5T#5S` or an operand), a counter coil (`SC` with its preset value), or `SAVE`.
 */
export interface Coil {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'coil';
  coil: '=' | 'S' | 'R' | 'SP' | 'SE' | 'SD' | 'SS' | 'SF' | 'CU' | 'CD' | 'SC' | 'SAVE';
  operand: string;
  value: string | null;
}

/**
 * `--(JMP)--` to `label` when powered, `--(JMPN)--` when not (STL `JC`/`JCN`; a
 * jump straight from the rail is `JU`).
 */
export interface Jump {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'jump';
  negated: boolean;
  label: string;
}

/** `--(RET)--`: ends the block when powered (STL `BEC`). */
export interface Return {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'ret';
}

/** `--(OPN)--`: opens a data block (STL `OPN DB n`); it needs no power flow. */
export interface OpenDb {
  /** Unique in the network; empty: numbered on load */
  id: string;
  kind: 'opn';
  block: string;
}

/**
 * One network in FBD: the common logic and the final boxes fed from it (none yet while
 * the network is being drawn).
 */
export interface FbdNetwork {
  title: string;
  comment: string;
  label: string | null;
  logic: FbdNode;
  outputs: FbdFinal[];
  /** A network that stays STL (no LAD/FBD shape): its lines */
  stl: string | null;
  stl_reason: string | null;
}

/** A node of an FBD network, told apart by its `kind`. */
export type FbdNode =
  | FbdOperand
  | FbdStatus
  | FbdLogic
  | FbdNot
  | FbdEdge
  | FbdMidline
  | FbdBox
  | FbdBranch;

/** An operand on a Boolean pin; `negated` draws the negation circle (LAD: NC contact). */
export interface FbdOperand {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'operand';
  operand: string;
  negated: boolean;
}

/** A status bit on a Boolean pin (`OV`, `==0` ...), optionally negated. */
export interface FbdStatus {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'status';
  bit: 'OV' | 'OS' | 'BR' | 'UO' | '==0' | '<>0' | '>0' | '<0' | '>=0' | '<=0';
  negated: boolean;
}

/**
 * `AND`, `OR` or `XOR` (FBD only) of its inputs. An `OR` drawing a LAD parallel
 * whose branches act on the flow has `flow`: the AND box of the power flow into the
 * parallel, which every branch starts from through a T-branch of its wire
 * (`FbdBranch(source=flow.id)`); it is evaluated before the inputs.
 */
export interface FbdLogic {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'logic';
  op: 'AND' | 'OR' | 'XOR';
  inputs: FbdNode[];
  flow: FbdNode | null;
}

/** Negates its input (LAD `--|NOT|--`). */
export interface FbdNot {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'not';
  input: FbdNode;
}

/** `P`/`N` edge of its input, remembered in `memory` (STL `FP`/`FN`). */
export interface FbdEdge {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'edge';
  edge: 'P' | 'N';
  memory: string;
  input: FbdNode;
}

/** The `#` box: writes its input to `operand` and passes it on. */
export interface FbdMidline {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'midline';
  operand: string;
  input: FbdNode;
}

/**
 * Every element with named pins (`nasaq.lang.lad.model.Box`, one to one); `en` is the
 * flow into its flow pin (EN, or a timer's S ...), its output the ENO (or Q). A box without a
 * flow pin (comparators, POS/NEG: `en` None) is one more input of an AND, like a contact, as
 * STEP 7 draws it. A Boolean pin fed by logic holds a node.
 */
export interface FbdBox {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'box';
  name: string;
  instance: string | null;
  en: FbdNode | null;
  inputs: Record<string, string | FbdNode>;
  outputs: Record<string, string>;
}

/**
 * A T-branch: the wire of the network's common logic (:attr:`FbdNetwork.logic`) where an
 * output branches off it, or (`source` set) the wire of the AND box `source` that is the
 * `flow` of an OR, at the start of each of that OR's branches.
 */
export interface FbdBranch {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'branch';
  /** The tapped AND box; empty: the common logic */
  source: string;
}

/** A final box of an FBD network, by its `kind`. */
export type FbdFinal = FbdAssign | FbdJump | FbdReturn | FbdOpenDb | FbdBox;

/** The assignment box `=`, `S`, `R`, a timer/counter coil box or `SAVE`. */
export interface FbdAssign {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'assign';
  coil: '=' | 'S' | 'R' | 'SP' | 'SE' | 'SD' | 'SS' | 'SF' | 'CU' | 'CD' | 'SC' | 'SAVE';
  operand: string;
  value: string | null;
  input: FbdNode;
}

export interface FbdJump {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'jump';
  negated: boolean;
  label: string;
  input: FbdNode;
}

export interface FbdReturn {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'ret';
  input: FbdNode;
}

export interface FbdOpenDb {
  /** The LAD element's id; AND boxes get '&1', '&2' ... */
  id: string;
  kind: 'opn';
  block: string;
  input: FbdNode;
}

/** The whole rung: `columns` is where the right rail stands, `rows` the rung's height. */
export interface LadLayout {
  columns: number;
  rows: number;
  cells: LadCell[];
  parallels: LadRegion[];
  links: LadLink[];
  wires: LadWire[];
}

/** One element (or output target) on the grid; `kind` is the model's `kind`. */
export interface LadCell {
  id: string;
  kind: string;
  column: number;
  row: number;
  width: number;
  height: number;
  pins: LadPin[];
}

/** The rectangle a parallel (OR) occupies; its branches are cells inside it. */
export interface LadRegion {
  id: string;
  column: number;
  row: number;
  width: number;
  height: number;
}

/**
 * A vertical wire on the left edge of `column`, from `from_row` down to `to_row`.
 *
 * `flow` is the power flow it carries: `"<id>:in"` (the flow into element `id`) on the
 * left edge of parallel `id`, `"<id>"` (the flow out of it) on its right edge; the link
 * joining several outputs carries the flow out of the common logic, `"<id>"` of its last
 * element or `"rail"` (the left rail) when it is empty.
 */
export interface LadLink {
  column: number;
  from_row: number;
  to_row: number;
  flow: string;
}

/**
 * A horizontal wire on `row` filling the cells `from_column` .. `to_column` - 1.
 *
 * `flow` is the power flow it carries, written `"rail"` (the left rail), `"<id>"` (the
 * flow out of element `id`) or `"<id>:in"` (the flow into element `id`):
 *
 * * the wire finishing a shorter branch of a parallel carries the flow out of the branch's
 *   last element; an empty branch, the flow into the parallel (`"<parallel id>:in"`);
 * * the wire a box's power flow takes over the logic drawn into its pins, `"<box id>:in"`;
 *   the wire finishing the logic of a pin, the flow out of its last element (`"rail"` when
 *   empty: logic wired into a pin starts from the rail);
 * * the wire from an output's conditions to its final element, the flow out of the last
 *   condition, or without conditions, of the common logic (its last element, or `"rail"`).
 */
export interface LadWire {
  row: number;
  from_column: number;
  to_column: number;
  flow: string;
}

/**
 * Where a box pin meets its wire, with the operand written at it (if any); `open`: a pin
 * of a catalogued box that nothing is connected to (drawn so it can be connected, as TIA
 * Portal draws every pin of a box).
 */
export interface LadPin {
  name: string;
  side: 'left' | 'right';
  row: number;
  operand: string | null;
  open: boolean;
}

export interface FbdLayout {
  layers: number;
  nodes: FbdLayoutNode[];
  edges: FbdLayoutEdge[];
}

/**
 * A box: `title` is what is written in it (`&`, `>=1`, `S_ODT`, `=` ...),
 * `operand` what is written above it (the coil's bit, the edge memory, the jump label).
 */
export interface FbdLayoutNode {
  id: string;
  kind: string;
  title: string;
  operand: string | null;
  layer: number;
  order: number;
  width: number;
  height: number;
  ports: FbdPort[];
}

export interface FbdLayoutEdge {
  id: string;
  source: string;
  source_port: string;
  target: string;
  target_port: string;
}

/**
 * A pin: `id` is `<node>.<side>.<index>`; `label` the operand written at it,
 * `negated` its negation circle; `element` the LAD element that operand is (the contact or
 * status bit, so the editor selects it and shows its status there), None for a box's own
 * operand or a wire; `open`: a pin of a catalogued box nothing is connected to.
 */
export interface FbdPort {
  id: string;
  name: string;
  side: 'WEST' | 'EAST';
  index: number;
  label: string | null;
  negated: boolean;
  element: string | null;
  open: boolean;
}

/** A parameter of a system block (`backend/nasaq/lang/system_blocks.py`). */
export interface SystemPin {
  section: 'IN' | 'OUT' | 'IN_OUT';
  name: string;
  type: string;
}

/** A system function (block) the CPU runs, as a LAD/FBD call box calls it. */
export interface SystemBlock {
  kind: 'SFB' | 'SFC';
  number: number;
  name: string;
  pins: SystemPin[];
}

export const SYSTEM_BLOCKS: readonly SystemBlock[] = [
  { kind: 'SFB', number: 0, name: 'CTU', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'INT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'INT' }] },
  { kind: 'SFB', number: 1, name: 'CTD', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LOAD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'INT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'INT' }] },
  { kind: 'SFB', number: 2, name: 'CTUD', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LOAD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'INT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'INT' }] },
  { kind: 'SFB', number: 3, name: 'TP', pins: [{ section: 'IN', name: 'IN', type: 'BOOL' }, { section: 'IN', name: 'PT', type: 'TIME' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'ET', type: 'TIME' }] },
  { kind: 'SFB', number: 4, name: 'TON', pins: [{ section: 'IN', name: 'IN', type: 'BOOL' }, { section: 'IN', name: 'PT', type: 'TIME' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'ET', type: 'TIME' }] },
  { kind: 'SFB', number: 5, name: 'TOF', pins: [{ section: 'IN', name: 'IN', type: 'BOOL' }, { section: 'IN', name: 'PT', type: 'TIME' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'ET', type: 'TIME' }] },
  { kind: 'SFB', number: 1000, name: 'R_TRIG', pins: [{ section: 'IN', name: 'CLK', type: 'BOOL' }, { section: 'OUT', name: 'Q', type: 'BOOL' }] },
  { kind: 'SFB', number: 1001, name: 'F_TRIG', pins: [{ section: 'IN', name: 'CLK', type: 'BOOL' }, { section: 'OUT', name: 'Q', type: 'BOOL' }] },
  { kind: 'SFB', number: 1100, name: 'PID_Compact', pins: [{ section: 'IN', name: 'Setpoint', type: 'REAL' }, { section: 'IN', name: 'Input', type: 'REAL' }, { section: 'IN', name: 'Input_PER', type: 'WORD' }, { section: 'IN', name: 'ManualEnable', type: 'BOOL' }, { section: 'IN', name: 'ManualValue', type: 'REAL' }, { section: 'IN', name: 'Reset', type: 'BOOL' }, { section: 'OUT', name: 'ScaledInput', type: 'REAL' }, { section: 'OUT', name: 'Output', type: 'REAL' }, { section: 'OUT', name: 'Output_PER', type: 'WORD' }, { section: 'OUT', name: 'Output_PWM', type: 'BOOL' }, { section: 'OUT', name: 'SetpointLimit_H', type: 'BOOL' }, { section: 'OUT', name: 'SetpointLimit_L', type: 'BOOL' }, { section: 'OUT', name: 'InputWarning_H', type: 'BOOL' }, { section: 'OUT', name: 'InputWarning_L', type: 'BOOL' }, { section: 'OUT', name: 'State', type: 'INT' }, { section: 'OUT', name: 'Error', type: 'DWORD' }] },
  { kind: 'SFB', number: 1101, name: 'CTRL_HSC', pins: [{ section: 'IN', name: 'HSC', type: 'HW_HSC' }, { section: 'IN', name: 'DIR', type: 'BOOL' }, { section: 'IN', name: 'CV', type: 'BOOL' }, { section: 'IN', name: 'RV', type: 'BOOL' }, { section: 'IN', name: 'PERIOD', type: 'BOOL' }, { section: 'IN', name: 'NEW_DIR', type: 'INT' }, { section: 'IN', name: 'NEW_CV', type: 'DINT' }, { section: 'IN', name: 'NEW_RV', type: 'DINT' }, { section: 'IN', name: 'NEW_PERIOD', type: 'INT' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }] },
  { kind: 'SFB', number: 14, name: 'GET', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'WORD' }, { section: 'OUT', name: 'NDR', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ADDR_1', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR_2', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR_3', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR_4', type: 'ANY' }, { section: 'IN_OUT', name: 'RD_1', type: 'ANY' }, { section: 'IN_OUT', name: 'RD_2', type: 'ANY' }, { section: 'IN_OUT', name: 'RD_3', type: 'ANY' }, { section: 'IN_OUT', name: 'RD_4', type: 'ANY' }] },
  { kind: 'SFB', number: 15, name: 'PUT', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'WORD' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ADDR_1', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR_2', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR_3', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR_4', type: 'ANY' }, { section: 'IN_OUT', name: 'SD_1', type: 'ANY' }, { section: 'IN_OUT', name: 'SD_2', type: 'ANY' }, { section: 'IN_OUT', name: 'SD_3', type: 'ANY' }, { section: 'IN_OUT', name: 'SD_4', type: 'ANY' }] },
  { kind: 'SFB', number: 1150, name: 'TCON', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'WORD' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'CONNECT', type: 'ANY' }] },
  { kind: 'SFB', number: 1151, name: 'TDISCON', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'WORD' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }] },
  { kind: 'SFB', number: 1152, name: 'TSEND', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'WORD' }, { section: 'IN', name: 'LEN', type: 'INT' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'DATA', type: 'ANY' }] },
  { kind: 'SFB', number: 1153, name: 'TRCV', pins: [{ section: 'IN', name: 'EN_R', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'WORD' }, { section: 'IN', name: 'LEN', type: 'INT' }, { section: 'IN', name: 'ADHOC', type: 'BOOL' }, { section: 'OUT', name: 'NDR', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'OUT', name: 'RCVD_LEN', type: 'INT' }, { section: 'IN_OUT', name: 'DATA', type: 'ANY' }] },
  { kind: 'SFB', number: 1154, name: 'TSEND_C', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'CONT', type: 'BOOL' }, { section: 'IN', name: 'LEN', type: 'UDINT' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'CONNECT', type: 'ANY' }, { section: 'IN_OUT', name: 'DATA', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR', type: 'ANY' }, { section: 'IN_OUT', name: 'COM_RST', type: 'BOOL' }] },
  { kind: 'SFB', number: 1155, name: 'TRCV_C', pins: [{ section: 'IN', name: 'EN_R', type: 'BOOL' }, { section: 'IN', name: 'CONT', type: 'BOOL' }, { section: 'IN', name: 'LEN', type: 'UDINT' }, { section: 'IN', name: 'ADHOC', type: 'BOOL' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'OUT', name: 'RCVD_LEN', type: 'UDINT' }, { section: 'IN_OUT', name: 'CONNECT', type: 'ANY' }, { section: 'IN_OUT', name: 'DATA', type: 'ANY' }, { section: 'IN_OUT', name: 'ADDR', type: 'ANY' }, { section: 'IN_OUT', name: 'COM_RST', type: 'BOOL' }] },
  { kind: 'SFB', number: 1160, name: 'DataLogCreate', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'RECORDS', type: 'UDINT' }, { section: 'IN', name: 'FORMAT', type: 'UINT' }, { section: 'IN', name: 'TIMESTAMP', type: 'UINT' }, { section: 'IN', name: 'NAME', type: 'ANY' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ID', type: 'DWORD' }, { section: 'IN_OUT', name: 'HEADER', type: 'ANY' }, { section: 'IN_OUT', name: 'DATA', type: 'ANY' }] },
  { kind: 'SFB', number: 1161, name: 'DataLogOpen', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'MODE', type: 'UINT' }, { section: 'IN', name: 'NAME', type: 'ANY' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ID', type: 'DWORD' }, { section: 'IN_OUT', name: 'DATA', type: 'ANY' }] },
  { kind: 'SFB', number: 1162, name: 'DataLogWrite', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ID', type: 'DWORD' }] },
  { kind: 'SFB', number: 1163, name: 'DataLogClose', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ID', type: 'DWORD' }] },
  { kind: 'SFB', number: 1164, name: 'DataLogNewFile', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'RECORDS', type: 'UDINT' }, { section: 'IN', name: 'NAME', type: 'ANY' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ID', type: 'DWORD' }, { section: 'IN_OUT', name: 'DATA', type: 'ANY' }] },
  { kind: 'SFB', number: 1165, name: 'DataLogDelete', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'IN', name: 'NAME', type: 'ANY' }, { section: 'IN', name: 'DelFile', type: 'BOOL' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ID', type: 'DWORD' }] },
  { kind: 'SFB', number: 1166, name: 'DataLogClear', pins: [{ section: 'IN', name: 'REQ', type: 'BOOL' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'BUSY', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'IN_OUT', name: 'ID', type: 'DWORD' }] },
  { kind: 'SFB', number: 1200, name: 'CTU_SINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'SINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'SINT' }] },
  { kind: 'SFB', number: 1201, name: 'CTD_SINT', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'SINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'SINT' }] },
  { kind: 'SFB', number: 1202, name: 'CTUD_SINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'SINT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'SINT' }] },
  { kind: 'SFB', number: 1203, name: 'CTU_USINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'USINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'USINT' }] },
  { kind: 'SFB', number: 1204, name: 'CTD_USINT', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'USINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'USINT' }] },
  { kind: 'SFB', number: 1205, name: 'CTUD_USINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'USINT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'USINT' }] },
  { kind: 'SFB', number: 1206, name: 'CTU_UINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'UINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'UINT' }] },
  { kind: 'SFB', number: 1207, name: 'CTD_UINT', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'UINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'UINT' }] },
  { kind: 'SFB', number: 1208, name: 'CTUD_UINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'UINT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'UINT' }] },
  { kind: 'SFB', number: 1209, name: 'CTU_DINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'DINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'DINT' }] },
  { kind: 'SFB', number: 1210, name: 'CTD_DINT', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'DINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'DINT' }] },
  { kind: 'SFB', number: 1211, name: 'CTUD_DINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'DINT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'DINT' }] },
  { kind: 'SFB', number: 1212, name: 'CTU_UDINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'UDINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'UDINT' }] },
  { kind: 'SFB', number: 1213, name: 'CTD_UDINT', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'UDINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'UDINT' }] },
  { kind: 'SFB', number: 1214, name: 'CTUD_UDINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'UDINT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'UDINT' }] },
  { kind: 'SFB', number: 1215, name: 'CTU_LINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'LINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'LINT' }] },
  { kind: 'SFB', number: 1216, name: 'CTD_LINT', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'LINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'LINT' }] },
  { kind: 'SFB', number: 1217, name: 'CTUD_LINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'LINT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'LINT' }] },
  { kind: 'SFB', number: 1218, name: 'CTU_ULINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'ULINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'ULINT' }] },
  { kind: 'SFB', number: 1219, name: 'CTD_ULINT', pins: [{ section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'ULINT' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'ULINT' }] },
  { kind: 'SFB', number: 1220, name: 'CTUD_ULINT', pins: [{ section: 'IN', name: 'CU', type: 'BOOL' }, { section: 'IN', name: 'CD', type: 'BOOL' }, { section: 'IN', name: 'R', type: 'BOOL' }, { section: 'IN', name: 'LD', type: 'BOOL' }, { section: 'IN', name: 'PV', type: 'ULINT' }, { section: 'OUT', name: 'QU', type: 'BOOL' }, { section: 'OUT', name: 'QD', type: 'BOOL' }, { section: 'OUT', name: 'CV', type: 'ULINT' }] },
  { kind: 'SFB', number: 1221, name: 'TP_LTIME', pins: [{ section: 'IN', name: 'IN', type: 'BOOL' }, { section: 'IN', name: 'PT', type: 'LTIME' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'ET', type: 'LTIME' }] },
  { kind: 'SFB', number: 1222, name: 'TON_LTIME', pins: [{ section: 'IN', name: 'IN', type: 'BOOL' }, { section: 'IN', name: 'PT', type: 'LTIME' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'ET', type: 'LTIME' }] },
  { kind: 'SFB', number: 1223, name: 'TOF_LTIME', pins: [{ section: 'IN', name: 'IN', type: 'BOOL' }, { section: 'IN', name: 'PT', type: 'LTIME' }, { section: 'OUT', name: 'Q', type: 'BOOL' }, { section: 'OUT', name: 'ET', type: 'LTIME' }] },
  { kind: 'SFB', number: 1130, name: 'Filter_PT1', pins: [{ section: 'IN', name: 'Input', type: 'REAL' }, { section: 'IN', name: 'SubstituteOutput', type: 'REAL' }, { section: 'IN', name: 'SubstituteOutputActive', type: 'BOOL' }, { section: 'IN', name: 'Reset', type: 'BOOL' }, { section: 'OUT', name: 'Output', type: 'REAL' }, { section: 'OUT', name: 'ErrorBits', type: 'DWORD' }, { section: 'OUT', name: 'Error', type: 'BOOL' }] },
  { kind: 'SFB', number: 1131, name: 'Filter_DT1', pins: [{ section: 'IN', name: 'Input', type: 'REAL' }, { section: 'IN', name: 'SubstituteOutput', type: 'REAL' }, { section: 'IN', name: 'SubstituteOutputActive', type: 'BOOL' }, { section: 'IN', name: 'Reset', type: 'BOOL' }, { section: 'OUT', name: 'Output', type: 'REAL' }, { section: 'OUT', name: 'ErrorBits', type: 'DWORD' }, { section: 'OUT', name: 'Error', type: 'BOOL' }] },
  { kind: 'SFB', number: 1132, name: 'Filter_PT2', pins: [{ section: 'IN', name: 'Input', type: 'REAL' }, { section: 'IN', name: 'SubstituteOutput', type: 'REAL' }, { section: 'IN', name: 'SubstituteOutputActive', type: 'BOOL' }, { section: 'IN', name: 'Reset', type: 'BOOL' }, { section: 'OUT', name: 'Output', type: 'REAL' }, { section: 'OUT', name: 'ErrorBits', type: 'DWORD' }, { section: 'OUT', name: 'Error', type: 'BOOL' }] },
  { kind: 'SFC', number: 1, name: 'READ_CLK', pins: [{ section: 'OUT', name: 'RET_VAL', type: 'INT' }, { section: 'OUT', name: 'CDT', type: 'DATE_AND_TIME' }] },
  { kind: 'SFC', number: 43, name: 'RE_TRIGR', pins: [] },
  { kind: 'SFC', number: 46, name: 'STP', pins: [] },
  { kind: 'SFC', number: 64, name: 'TIME_TCK', pins: [{ section: 'OUT', name: 'RET_VAL', type: 'TIME' }] },
  { kind: 'SFC', number: 780, name: 'RUNTIME', pins: [{ section: 'IN_OUT', name: 'MEM', type: 'LREAL' }, { section: 'OUT', name: 'RET_VAL', type: 'LREAL' }] },
  { kind: 'SFC', number: 6, name: 'RD_SINFO', pins: [{ section: 'OUT', name: 'RET_VAL', type: 'INT' }, { section: 'OUT', name: 'TOP_SI', type: 'SI_classic' }, { section: 'OUT', name: 'START_UP_SI', type: 'SI_classic' }] },
  { kind: 'SFC', number: 750, name: 'AG_SEND', pins: [{ section: 'IN', name: 'ACT', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'INT' }, { section: 'IN', name: 'LADDR', type: 'WORD' }, { section: 'IN', name: 'SEND', type: 'ANY' }, { section: 'IN', name: 'LEN', type: 'INT' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }] },
  { kind: 'SFC', number: 751, name: 'AG_RECV', pins: [{ section: 'IN', name: 'ID', type: 'INT' }, { section: 'IN', name: 'LADDR', type: 'WORD' }, { section: 'IN', name: 'RECV', type: 'ANY' }, { section: 'OUT', name: 'NDR', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'OUT', name: 'LEN', type: 'INT' }] },
  { kind: 'SFC', number: 752, name: 'AG_CNTRL', pins: [{ section: 'IN', name: 'ACT', type: 'BOOL' }, { section: 'IN', name: 'ID', type: 'INT' }, { section: 'IN', name: 'LADDR', type: 'WORD' }, { section: 'IN', name: 'CMD', type: 'INT' }, { section: 'OUT', name: 'DONE', type: 'BOOL' }, { section: 'OUT', name: 'ERROR', type: 'BOOL' }, { section: 'OUT', name: 'STATUS', type: 'WORD' }, { section: 'OUT', name: 'RESULT1', type: 'DWORD' }, { section: 'OUT', name: 'RESULT2', type: 'DWORD' }] },
];
