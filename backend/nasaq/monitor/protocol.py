"""The monitoring protocol's messages: what a client sends on a session's WebSocket, and what the
server sends back. ``PROTOCOL.md`` beside this module explains them; the front end's TypeScript
types (``frontend/src/api/monitor.ts``) are generated from these models and held to them by a test.

Every client message may carry ``ref``; the server answers it with an ``ack`` (and a result) or an
``error`` with the same ``ref``. Frames carry only what changed since the client's previous frame.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, StrictInt, TypeAdapter

PROTOCOL_VERSION = 1

Value = bool | int | float | str | None
TimeModeName = Literal["virtual", "real", "fast", "pause"]
CpuMode = Literal["RUN", "STOP", "HOLD"]
StepKind = Literal["instruction", "statement", "network", "scan", "transition"]
GraphOp = Literal[
    "auto",
    "man",
    "tap",
    "top",
    "ack",
    "step_on",
    "step_off",
    "push",
    "init",
    "off",
    "interlock_on",
    "interlock_off",
    "supervision_on",
    "supervision_off",
]


class _Message(BaseModel):
    model_config = ConfigDict(extra="forbid")
    ref: StrictInt | None = Field(
        default=None, description="Echoed in the ack or error that answers it"
    )


# -- client -> server: subscriptions ------------------------------------------------------------


class SubscribeCpu(_Message):
    """CPU state in every frame where it changed (mode, scans, clock, cycle statistic)."""

    type: Literal["subscribe_cpu"]
    on: bool = True


class Watch(_Message):
    """Replaces the watch list: addresses (``MW10``, ``DB1.DBW2``, ``T1``), symbols
    (``"Motor"``), DB and instance-DB members (``DB1.level``, ``"Tank".level``, ``DB5.t1.ET``)
    and, while the CPU holds, locals of the held block (``#count``)."""

    type: Literal["watch"]
    entries: list[str] = Field(max_length=10_000)


class OpenBlock(_Message):
    """The block whose status (per STL instruction, per SCL line, per LAD/FBD element) the
    frames carry; None: none. ``networks``: only these networks (1-based) are recorded and
    reported, the ones an editor shows; None: all of them."""

    type: Literal["open_block"]
    block: str | None
    networks: list[Annotated[int, Field(ge=1)]] | None = Field(default=None, max_length=10_000)


class Trend(_Message):
    """Values sampled at the end of every scan, sent as batches of samples. The same entries as
    the session already records (another tab's, or a reloaded page's) start with the samples
    recorded so far: the first frame carries that history."""

    type: Literal["trend"]
    entries: list[str] = Field(max_length=10_000)


class SessionState(_Message):
    """What the session keeps for whoever attaches (a reload, a second tab, another browser):
    the ack lists its breakpoints and the entries of the trend it records."""

    type: Literal["session_state"]


# -- client -> server: commands -----------------------------------------------------------------


class Run(_Message):
    type: Literal["run"]


class Stop(_Message):
    type: Literal["stop"]


class Restart(_Message):
    """Warm restart (OB100), or cold restart (OB102) with ``cold``; the CPU goes to RUN."""

    type: Literal["restart"]
    cold: bool = False


class SetTime(_Message):
    type: Literal["set_time"]
    mode: TimeModeName
    cycle_ms: float | None = Field(default=None, ge=1, le=60_000)


class SetInput(_Message):
    """Drives a peripheral input (``I0.3``, ``IW4``, or an input's symbol)."""

    type: Literal["set_input"]
    address: str
    value: Value


class Modify(_Message):
    """Writes a value once (memory, DB member, or a local of the held block)."""

    type: Literal["modify"]
    target: str
    value: Value


class Force(_Message):
    type: Literal["force"]
    address: str
    value: Value


class Unforce(_Message):
    """Removes the force of ``address``, or every force when it is None."""

    type: Literal["unforce"]
    address: str | None = None


class Location(BaseModel):
    """Where a breakpoint goes: a source line (``file`` + ``line``, STL or SCL), or a block with
    an STL instruction index or a network (1-based), or a block with a line of its source; or
    ``step``, a step number of an S7-Graph FB (``block``, or ``file`` when the file holds one
    Graph FB): the CPU holds when that step is about to become active, however it is."""

    model_config = ConfigDict(extra="forbid")
    file: str | None = None
    block: str | None = None
    line: int | None = Field(default=None, ge=1)
    network: int | None = Field(default=None, ge=1)
    instruction: int | None = Field(default=None, ge=0)
    step: int | None = Field(default=None, ge=1, le=65535)


class SetBreakpoint(_Message):
    """``condition``: ``<operand> <op> <value>`` with op one of = == <> < > <= >=, the operand an
    address, symbol, ``#local``, or a register (RLO, STA, ACCU1, ACCU2, AR1, AR2, OV, OS, BR)."""

    type: Literal["set_breakpoint"]
    location: Location
    condition: str | None = Field(default=None, max_length=200)


class ClearBreakpoint(_Message):
    """Clears breakpoint ``id``, or all of them when it is None."""

    type: Literal["clear_breakpoint"]
    id: int | None = None


class Continue(_Message):
    type: Literal["continue"]


class Step(_Message):
    """From a hold: to the next STL instruction, SCL statement, network, or the next scan's end.
    ``into`` enters called blocks; without it a step stays in the block (or returns to its caller).
    From STOP or pause, ``scan`` runs one scan. ``transition``: from a hold or a running (or
    paused) CPU, runs until a step of any S7-Graph FB is about to become active (one transition
    fires), then holds there."""

    type: Literal["step"]
    by: StepKind
    into: bool = False


class RunScans(_Message):
    """Runs ``count`` scans, then pauses."""

    type: Literal["run_scans"]
    count: int = Field(ge=1, le=1_000_000)


# -- client -> server: the virtual plant (a project's ``.plant`` file) ---------------------------


class PlantOperate(_Message):
    """The operator panel: presses, releases or turns a plant's control. ``value`` is the level
    the PLC input sees (an NC stop button pressed is 0), a word control's value 0..65535."""

    type: Literal["plant_operate"]
    control: str = Field(min_length=1, max_length=64)
    value: StrictInt | bool


class PlantFault(_Message):
    """Injects (``on``) or clears an injectable fault of the plant (a stuck sensor, a jam)."""

    type: Literal["plant_fault"]
    fault: str = Field(min_length=1, max_length=64)
    on: bool = True


class GraphControl(_Message):
    """S7-Graph's Control Sequencer (Debug > Control Sequencer) on the instance DB ``db`` of a
    Graph FB (``DB1`` or its symbol): select a mode (``auto``, ``man``, ``tap``, ``top``),
    acknowledge a supervision error (``ack``), switch step ``step`` on or off in MAN
    (``step_on``, ``step_off``), ``push`` (T_PUSH once), ``init`` or ``off`` the sequencer for
    one call, switch its interlock or supervision check on or off. The FB acts at its next call
    (the instance DB's mailbox, ``nasaq/lang/graph/SEMANTICS.md`` §4)."""

    type: Literal["graph_control"]
    db: str = Field(min_length=1, max_length=64)
    op: GraphOp
    step: int | None = Field(default=None, ge=1, le=65535)


class PlantReset(_Message):
    """Puts the plant back in its initial state: its raised faults cleared, the faults the
    plant file injects from the start injected again."""

    type: Literal["plant_reset"]


ClientMessage = Annotated[
    SubscribeCpu
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
    | GraphControl,
    Field(discriminator="type"),
]
CLIENT_MESSAGE: TypeAdapter[ClientMessage] = TypeAdapter(ClientMessage)


# -- server -> client ---------------------------------------------------------------------------


class Hello(BaseModel):
    type: Literal["hello"] = "hello"
    session: str
    client: int = Field(description="This connection's number (e.g. for the trend CSV export)")
    protocol: int = PROTOCOL_VERSION
    max_frames_per_second: int
    max_watch_entries: int


class Ack(BaseModel):
    type: Literal["ack"] = "ack"
    ref: int | None
    result: dict[str, object] | None = None


class ProtocolError(BaseModel):
    """A message the server could not carry out; ``code`` is from the diagnostics catalogue."""

    type: Literal["error"] = "error"
    ref: int | None
    code: str
    key: str
    message: str
    params: dict[str, object] = Field(default_factory=dict)


class CycleStats(BaseModel):
    """Wall-clock milliseconds the scans took (the program's work, not the cycle wait)."""

    last_ms: float
    min_ms: float
    max_ms: float
    avg_ms: float


class ForcedValue(BaseModel):
    address: str
    value: int


class CpuState(BaseModel):
    mode: CpuMode
    time_mode: TimeModeName
    cycle_ms: float
    scans: int
    time_ms: int
    stop_code: str | None
    stop_reason: str | None
    cycle: CycleStats | None
    forced: list[ForcedValue]


class WatchValue(BaseModel):
    """A watch entry's value; ``forced`` when a force holds it; ``error`` when it has none."""

    value: Value
    forced: bool = False
    error: str | None = None


class InstructionStatus(BaseModel):
    """The registers as STL instruction ``index`` left them (STEP 7's block status columns)."""

    index: int
    line: int | None
    rlo: int
    sta: int
    accu1: int
    accu2: int
    stw: int
    ar1: int
    ar2: int
    operand: Value = None


class LineStatus(BaseModel):
    """An SCL line: the variables its code read or wrote, with their last values."""

    line: int
    values: dict[str, Value]


class ElementStatus(BaseModel):
    """A LAD/FBD element in one sampled execution, as TIA Portal draws its power flow.

    ``value``: the operand as the element read or wrote it (a contact's or status contact's
    bit, a coil's bit after it, a midline's bit, an edge's memory bit, POS/NEG the bit it
    watches; a timer or counter box or coil: its current value as the watch shows it).
    ``out``: the element's Boolean result (contacts: null, the client computes the flow from
    ``value`` and the tree; NOT, an edge, a midline: the power flow out of it; a compare or
    POS/NEG box: its result, which the flow passes in series; an EN/ENO box or a call: its ENO;
    a timer, counter or flip-flop box: its Q; a coil, jump or RET: the power flow into it).
    ``pins``: a box's pins by name, inputs as read and outputs as written (a pin whose
    instructions did not run, as in a box whose EN was 0, is absent). An S7-Graph FB's conditions
    report the same way by origin (``T3/e2``, ``S2/C/e1``, ``S2/V/e1``, ``PRE1/e2``), and its
    action rows as ``S2/A1``: ``value`` the operand as the row left it, ``out`` whether a bit row
    drove its bit (``PROTOCOL.md``, S7-Graph element status)."""

    network: int = Field(description="1-based network; 0 for an S7-Graph FB's elements")
    id: str = Field(
        description="The element id in its network (e1, e2 ... in reading order); in an S7-Graph"
        " FB the origin: T3/e2, S2/C/e1, S2/V/e1, S2/A1, PRE1/e2, POST1/e1"
    )
    value: Value = None
    out: bool | None = None
    pins: dict[str, Value] = Field(default_factory=dict)


class GraphStepStatus(BaseModel):
    """A step of an S7-Graph FB as the chart draws it online: ``disturbed`` is an active step
    with an interlock error (``interlock_error``, LA) or a supervision error not yet
    acknowledged (``supervision_error``, VA). ``t_ms``/``u_ms``: its time active (current or
    last activation), and the same without the time spent disturbed."""

    number: int
    name: str
    state: Literal["inactive", "active", "disturbed"]
    t_ms: int
    u_ms: int
    interlock_error: bool
    supervision_error: bool


class GraphTransitionStatus(BaseModel):
    """A transition: ``tt``, its condition was evaluated true in the FB's last call."""

    number: int
    name: str
    tt: bool


class GraphStatus(BaseModel):
    """The sequencer state of an S7-Graph FB, read from the instance DB its sampled call used
    (``db``) at the end of that scan: the operating mode and every step and transition."""

    db: str = Field(description="The instance read, 'DB1'; a multi-instance: 'DB1' and 'at'")
    at: int = Field(default=0, description="Byte offset of the instance in db (multi-instance)")
    mode: Literal["AUTO", "MAN", "TAP", "TOP"] | None
    steps: list[GraphStepStatus]
    transitions: list[GraphTransitionStatus]


class BlockStatus(BaseModel):
    """One sampled execution of the open block: rows for the instructions that ran, and for a
    LAD/FBD block the status of each element that ran (an element absent did not run); for an
    S7-Graph FB, ``graph`` (null for every other block, and for a Graph FB that did not run)."""

    block: str
    language: Literal["stl", "scl", "lad", "fbd", "graph"]
    scan: int
    instructions: list[InstructionStatus]
    lines: list[LineStatus]
    elements: list[ElementStatus] = Field(default_factory=list)
    graph: GraphStatus | None = None


class PlantFrame(BaseModel):
    """The session's virtual plant as the drawing animates it: ``state`` (levels, positions,
    counts; what a scenario's ``plant.<name>`` expects), every signal's value (sensors and panel
    controls as the PLC inputs get them, actuators as the outputs drive them), the active faults
    and the wiring (signal -> address)."""

    kind: str
    time_ms: int = Field(description="Virtual time the plant has run")
    state: dict[str, bool | int | float | str]
    signals: dict[str, int]
    faults: list[str]
    wiring: dict[str, str]


class Frame(BaseModel):
    type: Literal["frame"] = "frame"
    seq: int
    cpu: CpuState | None = None
    watch: dict[str, WatchValue] | None = None
    block: BlockStatus | None = None
    trend: list[TrendSample] | None = None
    hold: HoldState | None = None
    released: bool = Field(default=False, description="The hold of the previous frame has ended")
    diagnostics: list[DiagnosticEntry] | None = None
    plant: PlantFrame | None = Field(
        default=None, description="The virtual plant, when it changed (null: unchanged or none)"
    )
    plant_removed: bool = Field(
        default=False, description="A download took the plant away (the project has none now)"
    )


class TrendSample(BaseModel):
    scan: int
    time_ms: int
    values: list[Value]


class StackFrame(BaseModel):
    block: str
    instruction: int
    line: int | None
    file: str | None
    network: int | None


class Variable(BaseModel):
    name: str
    type: str
    value: Value


class HoldState(BaseModel):
    """Where the CPU holds mid-scan: the innermost block first in ``call_stack``. At a step
    activation of an S7-Graph FB (a step breakpoint, a single step by transition):
    ``graph_step`` is the number of the step about to become active, ``graph_block`` its FB."""

    reason: Literal["breakpoint", "step"]
    breakpoint: int | None
    location: StackFrame
    registers: dict[str, int]
    locals: list[Variable]
    call_stack: list[StackFrame]
    graph_step: int | None = None
    graph_block: str | None = None


class DiagnosticEntry(BaseModel):
    time_ms: int
    code: str
    message: str = Field(description="English; the UI says `key` with `params` in its language")
    block: str | None
    network: int | None
    line: int | None
    key: str = ""
    params: dict[str, str | int | float | bool | None] = {}

    @classmethod
    def of(cls, entry: object) -> DiagnosticEntry:
        """The protocol's copy of a CPU diagnostic buffer entry (``cpu.cycle.DiagnosticEntry``)."""
        return cls.model_validate(entry, from_attributes=True)


Frame.model_rebuild()

ServerMessage = Annotated[Hello | Ack | ProtocolError | Frame, Field(discriminator="type")]
SERVER_MESSAGE: TypeAdapter[ServerMessage] = TypeAdapter(ServerMessage)
