"""LAD/FBD boxes → STL: the catalogued boxes (``boxes.py``) and calls of FC/FB/SFC/SFB.

Each box is lowered where it sits in a rung: ``started`` says whether power flow logic precedes
it (its EN/first Boolean input), ``in_chain`` whether its ENO/Q flows on to more elements (else
it ends the rung and its ENO is used only when it has an operand). The shapes are those of
``STL_PATTERNS.md``.
"""

from __future__ import annotations

from typing import Protocol

from nasaq.lang.lad.boxes import BoxSpec, box_spec, call_target
from nasaq.lang.lad.model import Box, EdgeContact, Element, Invert, Midline, Parallel, Series


class Lowering(Protocol):
    """What a box needs from the network being lowered (``to_stl.NetworkLowering``)."""

    @property
    def labels(self) -> _Labels: ...

    def emit(self, op: str, operand: str = "", label: str | None = None) -> None: ...

    def temp(self) -> str: ...

    def report(self, code: str, element: str, **params: object) -> None: ...

    def bool_input(self, value: str | Series, started: bool) -> bool: ...

    def chain(self, elements: list[Element], started: bool) -> bool: ...


class _Labels(Protocol):
    def label(self) -> str: ...


def needs_whole_flow(element: Element) -> bool:
    """Whether an element acts on the whole power flow into it (it writes memory, runs code or
    inverts the flow): inside a parallel after other elements it must see that flow too. The
    one definition the lowering, the FBD view (``fbd``) and the lifter (LAD327) share."""
    if isinstance(element, EdgeContact | Midline | Invert):
        return True
    if isinstance(element, Box):
        spec = box_spec(element.name)
        return spec is None or spec.family != "compare"
    if isinstance(element, Parallel):
        return any(
            needs_whole_flow(item) for branch in element.branches for item in branch.elements
        )
    return False


def lower_box(low: Lowering, box: Box, started: bool, in_chain: bool) -> bool:
    """Emits the box; returns whether a chain (the box's ENO/Q) is running after it."""
    spec = box_spec(box.name)
    if spec is None:
        if call_target(box.name) is None:
            low.report("LAD201", box.id, name=box.name)
            return started
        return _call(low, box, started, in_chain)
    if not _pins_ok(low, box, spec):
        return started
    if spec.family == "compare":
        return _compare(low, box, spec, started)
    if spec.en_eno:
        return _en_eno(low, box, spec, started, in_chain)
    if spec.family == "timer":
        return _timer(low, box, spec, started, in_chain)
    if spec.family == "counter":
        return _counter(low, box, spec, started, in_chain)
    if spec.family == "flipflop":
        return _flipflop(low, box, spec, started, in_chain)
    return _edge(low, box, spec, started, in_chain)


def _pins_ok(low: Lowering, box: Box, spec: BoxSpec) -> bool:
    ok = True
    for name, value in box.inputs.items():
        pin = spec.pin(name)
        if pin is None or pin.direction != "in":
            low.report("LAD202", box.id, name=spec.name, pin=name)
            ok = False
        elif isinstance(value, Series) and pin.type != "BOOL":
            low.report("LAD204", box.id, name=spec.name, pin=name)
            ok = False
    for name in box.outputs:
        pin = spec.pin(name)
        if pin is None or pin.direction != "out":
            low.report("LAD202", box.id, name=spec.name, pin=name)
            ok = False
    required = [pin.name for pin in spec.inputs if pin.type != "BOOL"]
    if spec.en_eno:
        required.append("OUT")
    if spec.family == "counter":
        required = ["PV"] if "S" in box.inputs else []
    if spec.family == "edge":
        required = ["M_BIT"]
    for name in required:
        if name not in box.inputs and name not in box.outputs:
            low.report("LAD203", box.id, name=spec.name, pin=name)
            ok = False
    if spec.family == "edge" and isinstance(box.inputs.get("M_BIT"), Series):
        low.report("LAD204", box.id, name=spec.name, pin="M_BIT")
        ok = False
    if spec.address is not None and not box.instance:
        low.report("LAD208", box.id, name=spec.name, what=spec.address)
        ok = False
    return ok


def _operand(box: Box, pin: str) -> str:
    value = box.inputs.get(pin, "")
    return value if isinstance(value, str) else ""


def _flow_in(low: Lowering, box: Box, pin: str | None, started: bool) -> bool:
    """The flow into the box, with an explicit operand/logic on its flow pin ANDed onto it."""
    if pin is not None and pin in box.inputs:
        started = low.bool_input(box.inputs[pin], started)
    return started


def _flow_out(low: Lowering, box: Box, pin: str, in_chain: bool) -> bool:
    """After the RLO holds the box's ENO/Q: its operand, then the chain goes on with it."""
    operand = box.outputs.get(pin)
    if operand:
        low.emit("=", operand)
        if in_chain:
            low.emit("A", operand)
    return in_chain


def _compare(low: Lowering, box: Box, spec: BoxSpec, started: bool) -> bool:
    if started:
        low.emit("A(")
    low.emit("L", _operand(box, "IN1"))
    low.emit("L", _operand(box, "IN2"))
    low.emit(spec.op)
    if started:
        low.emit(")")
    return True


def _en_eno(low: Lowering, box: Box, spec: BoxSpec, started: bool, in_chain: bool) -> bool:
    started = _flow_in(low, box, "EN", started)
    label = low.labels.label() if started else None
    if label:
        low.emit("JNB", label)
    if spec.family == "shift":
        low.emit("L", _operand(box, "N"))
        low.emit("L", _operand(box, "IN"))
    elif spec.pin("IN1"):
        low.emit("L", _operand(box, "IN1"))
        low.emit("L", _operand(box, "IN2"))
    else:
        low.emit("L", _operand(box, "IN"))
    if spec.op:
        low.emit(spec.op)
    low.emit("T", box.outputs["OUT"])
    eno_used = in_chain or bool(box.outputs.get("ENO"))
    if spec.can_fail or eno_used:
        low.emit("AN" if spec.can_fail else "SET", "OV" if spec.can_fail else "")
        low.emit("SAVE")
        low.emit("CLR")
    if label:
        low.emit("A" if eno_used else "NOP", "BR" if eno_used else "0", label=label)
    elif eno_used:
        low.emit("A", "BR")
    return _flow_out(low, box, "ENO", in_chain)


def _rail(low: Lowering, started: bool) -> None:
    if not started:
        low.emit("SET")


def _timer(low: Lowering, box: Box, spec: BoxSpec, started: bool, in_chain: bool) -> bool:
    timer = box.instance or ""
    _rail(low, _flow_in(low, box, "S", started))
    low.emit("L", _operand(box, "TV"))
    low.emit(spec.op, timer)
    _reset_pin(low, box, "R", "R", timer)
    _load_out(low, box, "L", "BI", timer)
    _load_out(low, box, "LC", "BCD", timer)
    return _q(low, box, timer, in_chain)


def _counter(low: Lowering, box: Box, spec: BoxSpec, started: bool, in_chain: bool) -> bool:
    counter = box.instance or ""
    _rail(low, _flow_in(low, box, spec.flow_pin, started))
    low.emit(spec.op, counter)
    if spec.name == "S_CUD":
        _reset_pin(low, box, "CD", "CD", counter)
    low.emit("BLD", "101")
    if "S" in box.inputs:
        low.bool_input(box.inputs["S"], False)
        low.emit("L", _operand(box, "PV"))
        low.emit("S", counter)
    else:
        low.emit("NOP", "0")
        low.emit("NOP", "0")
    _reset_pin(low, box, "R", "R", counter)
    _load_out(low, box, "L", "CV", counter)
    _load_out(low, box, "LC", "CV_BCD", counter)
    return _q(low, box, counter, in_chain)


def _flipflop(low: Lowering, box: Box, spec: BoxSpec, started: bool, in_chain: bool) -> bool:
    bit = box.instance or ""
    _rail(low, _flow_in(low, box, spec.flow_pin, started))
    low.emit(spec.op, bit)
    other = "R1" if spec.name == "SR" else "S1"
    _reset_pin(low, box, other, "R" if spec.name == "SR" else "S", bit)
    return _q(low, box, bit, in_chain)


def _edge(low: Lowering, box: Box, spec: BoxSpec, started: bool, in_chain: bool) -> bool:
    if started:
        low.emit("A(")
    low.emit("A", box.instance or "")
    low.emit(spec.op, _operand(box, "M_BIT"))
    if started:
        low.emit(")")
    return _flow_out(low, box, "Q", in_chain)


def _reset_pin(low: Lowering, box: Box, pin: str, op: str, address: str) -> None:
    """A second Boolean input that acts on the address (``A r; R T 5``), or ``NOP 0``."""
    if pin in box.inputs:
        low.bool_input(box.inputs[pin], False)
        low.emit(op, address)
    else:
        low.emit("NOP", "0")


def _load_out(low: Lowering, box: Box, load: str, pin: str, address: str) -> None:
    operand = box.outputs.get(pin)
    if operand:
        low.emit(load, address)
        low.emit("T", operand)
    else:
        low.emit("NOP", "0")


def _q(low: Lowering, box: Box, address: str, in_chain: bool) -> bool:
    if in_chain or box.outputs.get("Q"):
        low.emit("A", address)
    return _flow_out(low, box, "Q", in_chain)


def _call(low: Lowering, box: Box, started: bool, in_chain: bool) -> bool:
    target = call_target(box.name)
    assert target is not None
    name, needs_instance = target
    if needs_instance and not box.instance:
        low.report("LAD209", box.id, name=name)
        return started
    arguments: list[tuple[str, str]] = []
    logic = {pin: value for pin, value in box.inputs.items() if pin != "EN"}
    kept = None
    if started and any(isinstance(value, Series) for value in logic.values()):
        kept = low.temp()
        low.emit("=", kept)
    for pin, value in logic.items():
        if isinstance(value, Series):
            stored = low.temp()
            if not low.chain(value.elements, False):
                low.emit("SET")
            low.emit("=", stored)
            arguments.append((pin, stored))
        else:
            arguments.append((pin, value))
    arguments += [(pin, operand) for pin, operand in box.outputs.items() if pin != "ENO"]
    if kept:
        low.emit("A", kept)
    started = _flow_in(low, box, "EN", started)
    label = low.labels.label() if started else None
    if label:
        low.emit("JNB", label)
    if box.instance and box.instance.startswith("#"):
        head = box.instance
    elif box.instance:
        head = f"{name} , {box.instance}"
    else:
        head = name
    if arguments:
        low.emit("CALL", f"{head} (")
        for index, (pin, operand) in enumerate(arguments):
            end = ");" if index == len(arguments) - 1 else ","
            low.emit("", f"     {pin:<24} := {operand}{end}")
    else:
        low.emit("CALL", head)
    eno_used = in_chain or bool(box.outputs.get("ENO"))
    if label:
        low.emit("A" if eno_used else "NOP", "BR" if eno_used else "0", label=label)
    elif eno_used:
        low.emit("A", "BR")
    return _flow_out(low, box, "ENO", in_chain)
