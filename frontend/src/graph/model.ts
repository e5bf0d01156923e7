// Generated from backend/nasaq/lang/graph/model.py; do not edit.
// Regenerate with `.venv/bin/python -m nasaq.lang.graph.typescript --write`.

import type { Network, Series } from '../lad/model';

export type { Network, Series };

/** A function block written in S7-Graph. */
export interface GraphBlock {
  /** 'FB 1' or '"Seq_drill"' as an STL source names it */
  name: string;
  title: string;
  comment: string;
  settings: Settings;
  /** The user's VAR sections as STL source text, copied as they are */
  declarations: string;
  /** Permanent pre-instructions */
  pre: Network[];
  sequencers: Sequencer[];
  /** Permanent post-instructions */
  post: Network[];
}

/** Options > Block Settings of S7-Graph that change the compiled FB. */
export interface Settings {
  /** The FB parameter set */
  parameters: 'MINIMUM' | 'STANDARD' | 'MAXIMUM' | 'USER_DEFINED';
  /** A step whose incoming and outgoing transitions are true at once is passed */
  skip_steps: boolean;
  /** A supervision error stays until acknowledged (ACK_EF) */
  acknowledge_required: boolean;
  /** An interlock error also blocks the step's transitions */
  interlock_blocks: boolean;
}

/**
 * One sequencer of the FB: steps and transitions in chart order (top to bottom, left to
 * right). Transitions sharing a source step are evaluated in this order (priority).
 */
export interface Sequencer {
  name: string;
  comment: string;
  steps: Step[];
  transitions: Transition[];
}

/**
 * A step: its number (unique in the FB, what S_SEL/S_NO and ON/OFF `S<n>` use), its
 * name (unique in the FB, the member of the instance DB), whether it is an initial step, its
 * interlock (marker C), supervision (marker V; true = error) and actions in execution order.
 */
export interface Step {
  number: number;
  name: string;
  initial: boolean;
  comment: string;
  interlock: Series | null;
  supervision: Series | null;
  actions: Action[];
}

/**
 * A transition from `source` (one step, or several: simultaneous convergence, all must be
 * active) to `target` (one step, several: simultaneous divergence, or none: sequence end,
 * S7-Graph's branch stop). `condition` None passes at once (a compile warning).
 */
export interface Transition {
  number: number;
  name: string;
  comment: string;
  /** Step names */
  source: string[];
  /** Step names; [] = sequence end */
  target: string[];
  /** Drawn as a jump arrow to target[0] */
  jump: boolean;
  condition: Series | null;
}

/**
 * One row of a step's action table: `[event] qualifier[C] operand [, time]`.
 *
 * `operand` is the address or symbol (`Q 0.0`, `"Belt_A"`, `#count`), the block of a
 * CALL (`FC 1`, `FB 2, DB 2`, `"Motor"`), the step of ON/OFF (`S3` or a step name, or
 * `S_ALL`), the timer/counter (`T 0`, `C 1`), or for an arithmetic action (qualifier N)
 * the whole assignment (`#A := #A + 1`, `#E := SIN(MD 0)`). `time` is the D/L time
 * (`T#5S` or an operand), the CS preset (`C#26` or an operand) or the TL/TD time
 * (`S5T#8S` or an operand).
 */
export interface Action {
  /** Unique in its step: a1, a2 ... (numbered on load) */
  id: string;
  event: 'S1' | 'S0' | 'V1' | 'V0' | 'L1' | 'L0' | 'A1' | 'R1' | null;
  qualifier: 'N' | 'S' | 'R' | 'D' | 'L' | 'CALL' | 'ON' | 'OFF' | 'CS' | 'CU' | 'CD' | 'CR' | 'TL' | 'TD' | 'TR';
  /** The C suffix: only while interlock OK */
  interlock: boolean;
  operand: string;
  time: string | null;
  comment: string;
}
