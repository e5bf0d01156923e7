"""LAD/FBD element status: what each element of a rung read, wrote and let through, as TIA
Portal draws the power flow of an online block.

It is read from the rows the block status records (``status.Recorder``: the registers after
each instruction of one sampled execution), knowing which element each instruction belongs to
(``ir.Origin.element``, set by the LAD lowering) and what the element is (the network model
parsed from the block's source at download). Each value comes from the instruction that makes
it, in the shapes of ``nasaq/lang/lad/STL_PATTERNS.md``:

- a contact's bit is STA after its ``A``/``O`` (the signal state it scanned; for a status
  contact the condition of the status word);
- NOT, an edge, a midline: the RLO after their last instruction; an edge's memory bit after it;
- a coil: the RLO at its ``=``/``S``/``R``/timer or counter operation (they keep the RLO), a jump
  or RET the RLO before it (JC/JCN/BEC set the RLO to 1), from the rail 1;
- a compare box: the RLO after its compare operation, its inputs ACCU1 after each load;
- an EN/ENO box: EN is BR after its ``JNB`` (which copies the RLO there), ENO BR at its ``_00n:``
  label, or after ``SAVE`` when EN is the rail; inputs ACCU1 after their loads, OUT after ``T``;
- a timer, counter or flip-flop box: each Boolean pin the RLO at the operation it drives, Q the
  RLO after ``A T n`` (``A C n``, ``A m``), or the timer's (counter's, bit's) state after the
  box when Q is not used; the time or count as the watch shows it, read after the box;
- POS/NEG: the watched bit (STA), the edge result (RLO after FP/FN);
- a call: EN and ENO as for an EN/ENO box, the actual parameters read after the call.

An element none of whose instructions ran is absent (not processed); a box pin whose
instructions did not run (EN was 0) is absent from its pins. A parallel has no value of its
own: it is present when anything in it ran, and the client ORs its branches.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from nasaq.ir import Constant, CounterRef, TimerRef
from nasaq.lang.lad.boxes import BoxSpec, box_spec
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    LadBlock,
    Midline,
    OpenDb,
    Parallel,
    Return,
    Series,
    StatusContact,
)
from nasaq.monitor.block_info import BlockInfo
from nasaq.monitor.protocol import ElementStatus, Value
from nasaq.monitor.status import A1, BR, RLO, STA, Reader, reader_of
from nasaq.monitor.values import decode

if TYPE_CHECKING:
    from nasaq.monitor.status import Recorder

Rows = dict[int, tuple[tuple[Any, ...], Value]]
_TIMER_OPS = frozenset({"SP", "SE", "SD", "SS", "SF"})
_WIDTHS = {"INT": 0xFFFF, "WORD": 0xFFFF, "S5TIME": 0xFFFF}


@dataclass(slots=True)
class _Item:
    """One element of the block's rungs and the instructions it owns, in code order."""

    network: int
    node: Element | Final
    indices: list[int]
    inside: list[_Item] = field(default_factory=list)  # a parallel's elements, nested ones too
    prefix: str = ""  # an S7-Graph condition's origin before the element id ("T3/")


class ElementStatusBuilder:
    """The element status of one LAD/FBD block, worked out once when the block is opened."""

    def __init__(self, block: LadBlock, info: BlockInfo) -> None:
        self.info = info
        self.code = info.block.code
        owned: dict[tuple[int, str], list[int]] = {}
        for index, instruction in enumerate(self.code):
            origin = instruction.origin
            if origin is not None and origin.element is not None and origin.network is not None:
                owned.setdefault((origin.network, origin.element), []).append(index)
        self.items: list[_Item] = []
        for number, network in enumerate(block.networks, start=1):
            if network.stl is not None:
                continue
            walk = _Walk(number, owned)
            walk.series(network.logic)
            for output in network.outputs:
                walk.series(output.conditions)
                walk.add(output.target)
            self.items += walk.items

    def attach(self, recorder: Recorder) -> None:
        """Adds the readers the statuses need beyond the registers: a timer's or counter's
        value and state after its box or coil, a call's parameters after the call."""
        timers, counters = recorder.timers, recorder.counters
        for item in self.items:
            node = item.node
            if not item.indices:
                continue
            last = item.indices[-1]
            address = self.code[last].operand if isinstance(node, Coil) else None
            if isinstance(node, Box):
                spec = box_spec(node.name)
                if spec is None:
                    call = next((k for k in item.indices if self.code[k].call), None)
                    if call is not None:
                        recorder.attach(call, self._call_reader(call, recorder))
                    continue
                if spec.family in ("timer", "counter"):
                    address = next(
                        (
                            self.code[k].operand
                            for k in item.indices
                            if isinstance(self.code[k].operand, TimerRef | CounterRef)
                        ),
                        None,
                    )
            if isinstance(address, TimerRef):
                recorder.attach(last, _state(timers.remaining_ms, timers.status, address.number))
            elif isinstance(address, CounterRef):
                recorder.attach(last, _state(counters.load, counters.status, address.number))

    def _call_reader(self, index: int, recorder: Recorder) -> Reader:
        call = self.code[index].call
        assert call is not None
        readers: list[tuple[str, Reader | None, Value]] = []
        for arg in call.args:
            fixed = arg.value.value if isinstance(arg.value, Constant) else None
            found = reader_of(
                arg.value, self.info, recorder.memory, recorder.timers, recorder.counters
            )
            readers.append((arg.name, found, fixed))

        def parameters(frame: bytearray, params: list[Any], regs: tuple[Any, ...]) -> Any:
            return {
                name: read(frame, params, regs) if read else fixed for name, read, fixed in readers
            }

        return parameters

    def status(self, rows: Rows, extra: dict[int, Any]) -> list[ElementStatus]:
        """The statuses of the elements that ran, in network and reading order."""
        found: dict[int, ElementStatus] = {}
        for position in range(len(self.items) - 1, -1, -1):  # a parallel after its elements
            item = self.items[position]
            if not any(k in rows for k in item.indices) and not (
                isinstance(item.node, Parallel) and any(id(i) in found for i in item.inside)
            ):
                continue
            made = _Reading(self.code, item, rows, extra).status()
            if made is not None:
                found[id(item)] = made
        return [found[id(item)] for item in self.items if id(item) in found]


class _Walk:
    """The elements of one network in reading order (``text_ids``), with their instructions."""

    def __init__(
        self, network: int, owned: dict[tuple[int, str], list[int]], prefix: str = ""
    ) -> None:
        self.network = network
        self.owned = owned
        self.prefix = prefix  # the ids are ``<prefix><element id>`` (S7-Graph: ``T3/e2``)
        self.items: list[_Item] = []

    def series(self, series: Series) -> list[_Item]:
        added: list[_Item] = []
        for element in series.elements:
            added += self.add(element)
        return added

    def add(self, node: Element | Final) -> list[_Item]:
        key = (self.network, self.prefix + node.id)
        item = _Item(self.network, node, self.owned.get(key, []), prefix=self.prefix)
        self.items.append(item)
        added = [item]
        if isinstance(node, Parallel):
            for branch in node.branches:
                item.inside += self.series(branch)
            added += item.inside
        elif isinstance(node, Box):
            for value in node.inputs.values():
                if isinstance(value, Series):
                    added += self.series(value)
        return added


class _Reading:
    """One element's status from its rows."""

    def __init__(self, code: list[Any], item: _Item, rows: Rows, extra: dict[int, Any]) -> None:
        self.code = code
        self.item = item
        self.rows = rows
        self.extra = extra

    # -- the rows -------------------------------------------------------------------------------
    def ran(self) -> Iterator[int]:
        return (k for k in self.item.indices if k in self.rows)

    def regs(self, index: int) -> tuple[Any, ...]:
        return self.rows[index][0]

    def bit(self, index: int | None, register: int) -> bool | None:
        if index is None or index not in self.rows:
            return None
        return bool(self.rows[index][0][register])

    def operand(self, index: int | None) -> Value:
        return None if index is None or index not in self.rows else self.rows[index][1]

    def op(self, index: int) -> str:
        return str(self.code[index].op)

    def first(self, *ops: str) -> int | None:
        return next((k for k in self.item.indices if self.op(k) in ops), None)

    def before(self, index: int) -> bool | None:
        """The RLO the instruction before ``index`` left: what flows into a jump or RET."""
        return self.bit(index - 1, RLO) if index > 0 else None

    def accu(self, index: int | None, pin: str, spec: BoxSpec | None) -> Value:
        """A pin's value in ACCU1 after ``index`` (a load, or the transfer of a result), read as
        the pin's type; a pin of any type (MOVE) as its operand shows it."""
        if index is None or index not in self.rows:
            return None
        found = spec.pin(pin) if spec is not None else None
        kind = found.type if found is not None else "ANY"
        if kind in ("ANY", "BOOL"):
            shown = self.rows[index][1]
            return shown if shown is not None else self.regs(index)[A1] & 0xFFFFFFFF
        return decode(kind, self.regs(index)[A1] & _WIDTHS.get(kind, 0xFFFFFFFF))

    # -- the element ----------------------------------------------------------------------------
    def status(self) -> ElementStatus | None:
        node = self.item.node
        reading: Callable[[], ElementStatus | None]
        if isinstance(node, Contact | StatusContact):
            reading = self.contact
        elif isinstance(node, Invert | EdgeContact | Midline):
            reading = self.flow_element
        elif isinstance(node, Parallel | OpenDb):
            reading = self.plain
        elif isinstance(node, Coil):
            reading = self.coil
        elif isinstance(node, Jump | Return):
            reading = self.jump
        else:
            reading = self.box
        return reading()

    def made(self, value: Value = None, out: bool | None = None, **pins: Value) -> ElementStatus:
        return ElementStatus(
            network=self.item.network,
            id=self.item.prefix + self.item.node.id,
            value=value,
            out=out,
            pins={name: shown for name, shown in pins.items() if shown is not None},
        )

    def contact(self) -> ElementStatus:
        last = max(self.ran())
        return self.made(value=self.bit(last, STA))

    def flow_element(self) -> ElementStatus:
        node = self.item.node
        last = max(self.ran())
        if isinstance(node, Invert):
            return self.made(out=self.bit(last, RLO))
        store = self.first("FP", "FN", "=")
        return self.made(value=_bool(self.operand(store)), out=self.bit(last, RLO))

    def plain(self) -> ElementStatus:
        return self.made()

    def coil(self) -> ElementStatus:
        node = self.item.node
        assert isinstance(node, Coil)
        last = self.item.indices[-1]
        if last not in self.rows:
            return self.made()  # a SET before the coil ran, the coil not (impossible in a rung)
        if node.coil == "SAVE":
            return self.made(out=self.bit(last, RLO))
        extra = self.extra.get(last)
        value = extra[0] if isinstance(extra, tuple) else _bool(self.operand(last))
        return self.made(value=value, out=self.bit(last, RLO))

    def jump(self) -> ElementStatus:
        op = self.first("JC", "JCN", "JU", "BEC", "BEU")
        if op is None or op not in self.rows:
            return self.made()
        from_rail = self.op(op) in ("JU", "BEU") or self.first("SET") is not None
        return self.made(out=True if from_rail else self.before(op))

    # -- boxes ----------------------------------------------------------------------------------
    def box(self) -> ElementStatus | None:
        node = self.item.node
        assert isinstance(node, Box)
        spec = box_spec(node.name)
        if spec is None:
            return self.call()
        if spec.family == "compare":
            return self.compare(spec)
        if spec.en_eno:
            return self.en_eno(spec)
        if spec.family == "edge":
            return self.edge_box()
        return self.stateful(spec)

    def compare(self, spec: BoxSpec) -> ElementStatus:
        loads = [k for k in self.item.indices if self.op(k) == "L"]
        result = next(
            (k for k in self.item.indices if self.op(k) not in ("A(", ")", "L")),
            None,
        )
        pins = {
            name: self.accu(k, name, spec) for name, k in zip(("IN1", "IN2"), loads, strict=False)
        }
        return self.made(out=self.bit(result, RLO), **pins)

    def enable(self) -> tuple[bool | None, bool | None]:
        """(EN, ENO) of an EN/ENO box or a call."""
        jnb = self.first("JNB")
        if jnb is None:
            enable: bool | None = True
            save = self.first("SAVE")
            call = next((k for k in self.item.indices if self.code[k].call), None)
            done = save if save is not None else call
            return enable, True if done is None else self.bit(done, BR)
        labelled = next(
            (k for k in self.item.indices if k > jnb and self.code[k].label is not None), None
        )
        return self.bit(jnb, BR), self.bit(labelled, BR)

    def en_eno(self, spec: BoxSpec) -> ElementStatus:
        enable, eno = self.enable()
        jnb = self.first("JNB")
        body = [k for k in self.item.indices if jnb is None or k > jnb]
        loads = [k for k in body if self.op(k) == "L"]
        if spec.family == "shift":
            names: tuple[str, ...] = ("N", "IN")
        elif spec.pin("IN1") is not None:
            names = ("IN1", "IN2")
        else:
            names = ("IN",)
        pins = {name: self.accu(k, name, spec) for name, k in zip(names, loads, strict=False)}
        transfer = next((k for k in body if self.op(k) == "T"), None)
        pins["OUT"] = self.accu(transfer, "OUT", spec)
        return self.made(out=eno, EN=enable, ENO=eno, **pins)

    def edge_box(self) -> ElementStatus:
        watched = self.first("A")
        edge = self.first("FP", "FN")
        memory = _bool(self.operand(edge))
        return self.made(value=self.bit(watched, STA), out=self.bit(edge, RLO), M_BIT=memory)

    def stateful(self, spec: BoxSpec) -> ElementStatus:
        """A timer, counter or flip-flop box: its pins, its Q, its time, count or bit."""
        if spec.family == "flipflop":
            return self.flipflop(spec)
        pins: dict[str, Value] = {}
        q: bool | None = None
        loaded: str | None = None
        for k in self.item.indices:
            op, operand = self.op(k), self.code[k].operand
            addressed = isinstance(operand, TimerRef | CounterRef)
            if addressed and (op in _TIMER_OPS or op in ("CU", "CD")):
                pins["S" if op in _TIMER_OPS else op] = self.bit(k, RLO)
            elif addressed and op in ("S", "R"):
                pins[op] = self.bit(k, RLO)
            elif addressed and op in ("L", "LC"):
                loaded = op
            elif addressed and op == "A":
                q = self.bit(k, RLO)
            elif op == "L":
                name = "TV" if spec.family == "timer" else "PV"
                pins[name] = self.accu(k, name, spec)
            elif op == "T" and loaded is not None:
                name = _LOADED[spec.family, loaded]
                pins[name] = self.accu(k, name, spec)
                loaded = None
        state = self.extra.get(self.item.indices[-1])  # (time or count, Q) after the box
        value = state[0] if isinstance(state, tuple) else None
        if q is None and isinstance(state, tuple):
            q = bool(state[1])
        pins["Q"] = q
        return self.made(value=value, out=q, **pins)

    def flipflop(self, spec: BoxSpec) -> ElementStatus:
        """SR/RS: the flow pin drives the first S/R on the bit, the other pin the second (or
        NOP 0 stands there); Q is ``A m`` after them, else the bit itself."""
        acts = [k for k in self.item.indices if self.op(k) in ("S", "R")]
        pins: dict[str, Value] = {}
        other = "R1" if spec.name == "SR" else "S1"
        for name, k in zip((spec.flow_pin or "S", other), acts, strict=False):
            pins[name] = self.bit(k, RLO)
        value = _bool(self.operand(acts[-1])) if acts else None
        address = self.code[acts[0]].operand if acts else None
        ends = max(acts[-1], self.first("NOP") or 0) if acts else 0
        reload = next(
            (
                k
                for k in self.item.indices
                if k > ends and self.op(k) == "A" and self.code[k].operand == address
            ),
            None,
        )
        q = self.bit(reload, RLO) if reload is not None else value
        pins["Q"] = q
        return self.made(value=value, out=q, **pins)

    def call(self) -> ElementStatus:
        enable, eno = self.enable()
        call = next((k for k in self.item.indices if self.code[k].call), None)
        parameters = self.extra.get(call) if call is not None and call in self.rows else None
        pins: dict[str, Value] = dict(parameters) if isinstance(parameters, dict) else {}
        return self.made(out=eno, **{**pins, "EN": enable, "ENO": eno})


_LOADED = {
    ("timer", "L"): "BI",
    ("timer", "LC"): "BCD",
    ("counter", "L"): "CV",
    ("counter", "LC"): "CV_BCD",
}


def _state(value: Callable[[int], int], q: Callable[[int], int], number: int) -> Reader:
    """Reads a timer's (remaining ms, Q) or a counter's (count, Q) after an instruction: the
    value the watch shows and the state a box's unused Q has."""

    def read(frame: bytearray, params: list[Any], regs: tuple[Any, ...]) -> tuple[int, int]:
        return value(number), q(number)

    return read


def _bool(value: Value) -> bool | None:
    return None if value is None else bool(value)
