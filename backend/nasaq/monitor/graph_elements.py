"""S7-Graph element status: the power flow of an online Graph FB's conditions and what its
action rows did, for the chart and the step view.

The Graph lowering gives every generated instruction its chart element (``SEMANTICS.md`` §5),
so the LAD element status (``element_status``) applies as it is to the conditions, keyed by
origin instead of network: ``T3/e2`` (transition 3's condition), ``S2/C/e1`` (interlock),
``S2/V/e1`` (supervision), ``PRE1/e2``/``POST1/e1`` (permanent networks, coils and boxes too),
all with ``network = 0``. An action row ``S2/A1`` reports its operand as the row left it:

- ``value``: an N/S/R/D/L bit after its write, an arithmetic action's target after its ``T``,
  a timer's remaining time or a counter's count (as LAD's timer/counter coils), read after the
  row's last operation; CALL, ON and OFF have no operand value (null);
- ``out``: for a bit row the RLO at its write: whether the row drove its bit (a coil's power
  flow); null otherwise.

A row whose code did not run (its step inactive) is absent; a row that ran but jumped over its
operation (an event that did not come) shows its operand as it was (read at the row's first
instruction) with ``out`` null, as S7-Graph's step view shows the operands of an active step.
With Skip Step, a transition condition is evaluated twice in a call (``lower_machinery``); the
status shows the later evaluation when both ran.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from nasaq.ir import CounterRef, TimerRef
from nasaq.lang.graph.model import Action, GraphBlock
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.graph.text_limits import refuse_oversized
from nasaq.lang.lad.model import Network, Series
from nasaq.lang.stl import SourceFile
from nasaq.lang.stl.compiler import decode
from nasaq.monitor.block_info import BlockInfo, parse_block_name
from nasaq.monitor.element_status import ElementStatusBuilder, Rows, _state, _Walk
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.lad_blocks import Key
from nasaq.monitor.protocol import ElementStatus
from nasaq.monitor.status import RLO, Reader, reader_of

if TYPE_CHECKING:
    from nasaq.ir import Program
    from nasaq.monitor.status import Recorder

_WRITES = frozenset({"=", "S", "R", "T", "CU", "CD", "SE", "SS"})
_BIT_ROWS = frozenset({"N", "S", "R", "D", "L"})
_NO_VALUE = frozenset({"CALL", "ON", "OFF"})


def graph_blocks(sources: list[SourceFile], program: Program) -> dict[Key, GraphBlock]:
    """Each FB of ``program`` compiled from a ``.graph`` source, as that source draws it."""
    found: dict[Key, GraphBlock] = {}
    for source in sources:
        if not source.name.lower().endswith(".graph"):
            continue
        text, _ = refuse_oversized(source.name, decode(source.text))  # as the compiler reads it
        parsed = parse_graph(text, source.name)
        for block in parsed.blocks:
            try:
                key = parse_block_name(block.name, program)
            except MonitorError:
                continue  # not in the program (it did not compile)
            compiled = program.get(*key)
            if compiled is not None and compiled.file == source.name:
                found[key] = block
    return found


class _Row:
    """One action row and the instructions it owns, in code order."""

    __slots__ = ("action", "id", "indices", "write")

    def __init__(self, id: str, action: Action, indices: list[int], code: list[Any]) -> None:
        self.id = id
        self.action = action
        self.indices = indices
        writes = [k for k in indices if code[k].op in _WRITES]
        self.write = writes[-1] if writes and action.qualifier not in _NO_VALUE else None


class GraphElementStatusBuilder(ElementStatusBuilder):
    """The element status of one Graph FB, worked out once when the block is opened."""

    def __init__(self, block: GraphBlock, info: BlockInfo) -> None:
        self.info = info
        self.code = info.block.code
        owned: dict[tuple[int, str], list[int]] = {}
        for index, instruction in enumerate(self.code):
            origin = instruction.origin
            if origin is not None and origin.element is not None:
                owned.setdefault((0, origin.element), []).append(index)
        self.items = []
        self.rows: list[_Row] = []
        for sequencer in block.sequencers:
            for step in sequencer.steps:
                self._condition(owned, step.interlock, f"S{step.number}/C/")
                self._condition(owned, step.supervision, f"S{step.number}/V/")
                for k, action in enumerate(step.actions, start=1):
                    row = f"S{step.number}/A{k}"
                    self.rows.append(_Row(row, action, owned.get((0, row), []), self.code))
            for transition in sequencer.transitions:
                self._condition(owned, transition.condition, f"T{transition.number}/")
        self._networks(owned, block.pre, "PRE")
        self._networks(owned, block.post, "POST")

    def _condition(
        self, owned: dict[tuple[int, str], list[int]], series: Series | None, prefix: str
    ) -> None:
        if series is not None:
            walk = _Walk(0, owned, prefix)
            walk.series(series)
            self.items += walk.items

    def _networks(
        self, owned: dict[tuple[int, str], list[int]], networks: list[Network], kind: str
    ) -> None:
        for number, network in enumerate(networks, start=1):
            if network.stl is not None:
                continue
            walk = _Walk(0, owned, f"{kind}{number}/")
            walk.series(network.logic)
            for output in network.outputs:
                walk.series(output.conditions)
                walk.add(output.target)
            self.items += walk.items

    def attach(self, recorder: Recorder) -> None:
        """Adds LAD's readers, and for each row its operand's value at its write (a timer's
        time, a counter's count) and at its first instruction (a row that skips its write)."""
        super().attach(recorder)
        timers, counters = recorder.timers, recorder.counters
        for row in self.rows:
            if row.write is None:
                continue
            address = self.code[row.write].operand
            reader: Reader | None
            if isinstance(address, TimerRef):
                reader = _state(timers.remaining_ms, timers.status, address.number)
                recorder.attach(row.write, reader)
            elif isinstance(address, CounterRef):
                reader = _state(counters.load, counters.status, address.number)
                recorder.attach(row.write, reader)
            else:
                reader = reader_of(address, self.info, recorder.memory, timers, counters)
            if reader is not None and row.indices[0] != row.write:
                recorder.attach(row.indices[0], reader)

    def status(self, rows: Rows, extra: dict[int, Any]) -> list[ElementStatus]:
        found = super().status(rows, extra)
        for row in self.rows:
            if not any(k in rows for k in row.indices):
                continue
            found.append(_row_status(row, rows, extra))
        return found


def _row_status(row: _Row, rows: Rows, extra: dict[int, Any]) -> ElementStatus:
    write = row.write
    if write is None:
        return ElementStatus(network=0, id=row.id)
    bit = row.action.qualifier in _BIT_ROWS and ":=" not in row.action.operand
    out: bool | None = None
    value: Any = None
    if write in rows:
        regs, value = rows[write]
        state = extra.get(write)
        out = bool(regs[RLO]) if bit else None
    else:  # jumped over: the operand as it was before the row
        state = extra.get(row.indices[0]) if row.indices[0] in rows else None
    if isinstance(state, tuple):
        value = state[0]
    elif state is not None:
        value = state
    if bit and value is not None:
        value = bool(value)
    return ElementStatus(network=0, id=row.id, value=value, out=out)
