"""Box patterns of the lifter: compares, EN/ENO boxes, calls, timers, counters, SR/RS, POS/NEG.

``BoxReading`` recognises the shapes of ``STL_PATTERNS.md`` ("Boxes") after the flow so far and
either puts the box in series (its output reloaded: ``A BR``, ``A T n``, ``A C n``, ``A m``) or
ends the rung with it (``FinalBoxError``). Timer, counter and flip-flop patterns are tried with
backtracking: when no box slot follows, the instruction is a coil after all.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping

from nasaq.lang.lad.from_stl_boxes import BINARY, COMPARES, SHIFTS, TIMERS, UNARY
from nasaq.lang.lad.from_stl_chain import Chain
from nasaq.lang.lad.from_stl_cursor import ACCU_OPS, COUNTER, StepCursor
from nasaq.lang.lad.from_stl_reasons import RefusalError, not_convertible
from nasaq.lang.lad.from_stl_steps import Step
from nasaq.lang.lad.model import (
    Box,
    Contact,
    EdgeContact,
    Element,
    Final,
    Series,
    StatusContact,
)

PinDirections = Callable[[str], Mapping[str, str] | None]
"""Block name as a CALL names it → pin → ``in``/``out``/``in_out`` (None: unknown block)."""


class FinalBoxError(Exception):
    """A timer/counter/flip-flop box that ends the rung (its Q unused)."""

    def __init__(self, box: Box) -> None:
        super().__init__(box.name)
        self.box = box


class BoxReading(StepCursor, ABC):
    """The box half of the rung reader; the chain half (``chain``) comes from the subclass."""

    def __init__(self, steps: list[Step], directions: PinDirections | None) -> None:
        super().__init__(steps)
        self.directions = directions
        self.pin_logic: dict[str, Series] = {}  # temporaries holding a call's Boolean pins
        self.in_slot = 0  # reading a box's Boolean pin: no box inside it

    @abstractmethod
    def chain(self, nested: bool) -> tuple[list[Element], Final | None]:
        """A chain up to its targets (or its ``)``); a box ending the rung comes back too."""

    def accu_start(self, c: Chain) -> Final | None:
        """``L`` where a chain starts: a comparison (a check), or an EN/ENO box from the rail."""
        a, b, op = self.peek(), self.peek(1), self.peek(2)
        if (
            a is not None
            and b is not None
            and op is not None
            and b.op == "L"
            and op.op in COMPARES
            and not b.labels
            and not op.labels
        ):
            self.i += 3
            inputs: dict[str, str | Series] = {"IN1": self.value(a), "IN2": self.value(b)}
            c.current.append(Box(name=f"CMP{op.op}", inputs=inputs))
            return None
        return self.en_box(c, None)

    def en_box(self, c: Chain, jnb: Step | None) -> Final | None:
        """An EN/ENO box: body, ENO tail, then ``A BR`` (ENO flows on) or ``NOP 0``/nothing."""
        body_start = self.peek()
        if body_start is None:
            self.refuse("LAD325", jnb)
        box = self.call_box() if body_start.op == "CALL" else self.accu_box()
        tail = self.peek()
        if tail is not None and tail.op in ("AN", "SET") and not tail.labels:
            self.eno_tail(tail)
        end = self.peek()
        if jnb is not None:
            if end is None or jnb.operand not in end.labels:
                self.refuse("LAD325", end or jnb)
            if len(end.labels) > 1:
                raise RefusalError(not_convertible("LAD304", end.line, end.labels[1]))
        elif end is not None and end.labels:
            raise RefusalError(not_convertible("LAD304", end.line, end.labels[0]))
        if end is not None and end.op == "A" and end.operand == "BR" and end.kind == "bare":
            c.restart(box, StatusContact(bit="BR"), self.take())
            return None
        if self.is_nop(end):
            self.take()
        elif end is not None and jnb is not None:
            self.refuse("LAD325", end)
        return box

    def eno_tail(self, first: Step) -> None:
        """``AN OV; SAVE; CLR`` or ``SET; SAVE; CLR`` after a box body."""
        if first.op == "AN" and first.operand != "OV":
            return
        expected = ["SAVE", "CLR"]
        for offset, op in enumerate(expected, start=1):
            step = self.peek(offset)
            if step is None or step.op != op or step.labels:
                self.refuse("LAD325", step or first)
        self.i += 3

    def accu_box(self) -> Box:
        loads: list[Step] = []
        while (step := self.peek()) is not None and step.op == "L" and not (loads and step.labels):
            self.value(step)
            loads.append(self.take())
        op_step = self.peek()
        if not loads:
            self.refuse("LAD308" if op_step is not None and op_step.op == "T" else "LAD318")
        if op_step is None:
            self.refuse("LAD322", loads[-1])
        self.no_label(op_step)
        op = op_step.op
        inputs: dict[str, str | Series] = {}
        if op == "T":
            name, needed = "MOVE", 1
        elif op in BINARY:
            name, needed = BINARY[op], 2
        elif op in SHIFTS:
            name, needed = SHIFTS[op], 2 if op_step.operand is None else 1
        elif op in UNARY:
            name, needed = UNARY[op], 1
        elif op in COMPARES:
            self.refuse("LAD308" if len(loads) < 2 else "LAD318", op_step)
        elif op in TIMERS or op == "S":
            self.refuse("LAD309", op_step)
        else:
            self.refuse("LAD322" if op not in ACCU_OPS else "LAD318", op_step)
        if len(loads) < needed:
            self.refuse("LAD308", op_step)
        if len(loads) > needed:
            self.refuse("LAD318", loads[0])
        if name == "MOVE":
            inputs["IN"] = self.value(loads[0])
        elif name in SHIFTS.values() and needed == 1:
            inputs["IN"], inputs["N"] = self.value(loads[0]), op_step.operand or ""
        elif name in SHIFTS.values():
            inputs["IN"], inputs["N"] = self.value(loads[1]), self.value(loads[0])
        elif needed == 2:
            inputs["IN1"], inputs["IN2"] = self.value(loads[0]), self.value(loads[1])
        else:
            inputs["IN"] = self.value(loads[0])
        if name != "MOVE":
            self.take()
        store = self.peek()
        if store is None:
            self.refuse("LAD322", op_step)
        if store.op != "T" or store.labels:
            self.no_label(store)
            self.refuse("LAD318" if store.op in ACCU_OPS else self.classify(store), store)
        self.coil_operand(store)
        self.take()
        after = self.peek()
        if after is not None and after.op == "T" and not after.labels:
            self.refuse("LAD318", after)
        return Box(name=name, inputs=inputs, outputs={"OUT": store.operand or ""})

    def call_box(self) -> Box:
        step = self.take()
        if step.operand is None:
            self.refuse("LAD317", step)
        name = step.operand
        pins = self.directions(name) if self.directions is not None else None
        inputs: dict[str, str | Series] = {}
        outputs: dict[str, str] = {}
        for pin, operand in step.args or ():
            direction = (pins or {}).get(pin) or ("out" if pin.upper() == "RET_VAL" else "in")
            if direction == "out":
                outputs[pin] = operand
            else:
                inputs[pin] = self.pin_logic.get(operand, operand)
        instance = step.extra[0] if step.extra else None
        return Box(name=name, instance=instance, inputs=inputs, outputs=outputs)

    def try_box(self, c: Chain) -> bool:
        """A timer, counter or SR/RS box after the flow so far; False leaves the position."""
        step = self.peek()
        assert step is not None
        save = self.i
        found = False
        try:
            if step.op == "L":
                found = self.timer_box(c)
            elif step.op in ("CU", "CD"):
                found = self.counter_box(c)
            elif step.op in ("S", "R") and step.operand and not COUNTER.fullmatch(step.operand):
                found = self.flip_flop(c)
        except RefusalError:
            found = False
        if not found:
            self.i = save
        return found

    def pin(self, elements: list[Element]) -> str | Series:
        if len(elements) == 1 and isinstance(elements[0], Contact) and not elements[0].negated:
            return elements[0].operand
        return Series(elements=elements)

    def slot_chain(self, op: str, operand: str) -> list[Element] | None:
        """``<chain>; op operand`` (a Boolean pin of a box), or None (position unchanged)."""
        save = self.i
        self.in_slot += 1
        try:
            elements, final = self.chain(nested=False)
        except RefusalError:
            self.i = save
            return None
        finally:
            self.in_slot -= 1
        step = self.peek()
        matches = step is not None and (step.op, step.operand) == (op, operand)
        if final is None and elements and matches and step is not None and not step.labels:
            self.take()
            return elements
        self.i = save
        return None

    def load_store(self, load: str, operand: str) -> str | None:
        """``load operand; T <out>`` (a value pin of a timer/counter box), or None."""
        a, b = self.peek(), self.peek(1)
        if a is None or b is None or a.op != load or a.operand != operand or b.op != "T":
            return None
        if a.labels or b.labels:
            return None
        self.coil_operand(b)
        self.i += 2
        return b.operand

    def reload_or_end(self, c: Chain, box: Box, operand: str) -> bool:
        step = self.peek()
        if step is not None and step.op == "A" and step.operand == operand and not step.labels:
            c.restart(box, Contact(operand=operand), self.take())
            return True
        return False

    def timer_box(self, c: Chain) -> bool:
        load, timer = self.take(), self.peek()
        if timer is None or timer.op not in TIMERS or timer.operand is None or timer.labels:
            return False
        self.take()
        operand = timer.operand
        inputs: dict[str, str | Series] = {"TV": self.value(load)}
        outputs: dict[str, str] = {}
        slots = self.reset_and_values(operand, inputs, outputs, ("BI", "BCD"))
        box = Box(name=TIMERS[timer.op], instance=operand, inputs=inputs, outputs=outputs)
        if self.reload_or_end(c, box, operand):
            return True
        if slots == 0:
            return False
        raise FinalBoxError(box)

    def reset_and_values(
        self,
        operand: str,
        inputs: dict[str, str | Series],
        outputs: dict[str, str],
        value_pins: tuple[str, str],
    ) -> int:
        """The R pin and the two value outputs (``L``, ``LC``) a timer or counter box ends with,
        each a chain or store or an empty ``NOP 0`` slot; how many slots were there."""
        slots = 0
        if self.is_nop(self.peek()):
            self.take()
            slots += 1
        elif (reset := self.slot_chain("R", operand)) is not None:
            inputs["R"] = self.pin(reset)
            slots += 1
        for load_op, pin in zip(("L", "LC"), value_pins, strict=True):
            if self.is_nop(self.peek()):
                self.take()
                slots += 1
            elif (out := self.load_store(load_op, operand)) is not None:
                outputs[pin] = out
                slots += 1
        return slots

    def counter_box(self, c: Chain) -> bool:
        first = self.take()
        operand = first.operand or ""
        name = "S_CU" if first.op == "CU" else "S_CD"
        inputs: dict[str, str | Series] = {}
        outputs: dict[str, str] = {}
        if first.op == "CU" and (down := self.slot_chain("CD", operand)) is not None:
            name = "S_CUD"
            inputs["CD"] = self.pin(down)
        bld = self.peek()
        marked = bld is not None and bld.op == "BLD" and bld.operand == "101"
        if marked:
            self.take()
        slots = 0
        if self.is_nop(self.peek()):
            self.i += 2 if self.is_nop(self.peek(1)) else 1
            slots += 1
        elif (preset := self.preset(operand)) is not None:
            inputs["S"], inputs["PV"] = preset
            slots += 1
        slots += self.reset_and_values(operand, inputs, outputs, ("CV", "CV_BCD"))
        box = Box(name=name, instance=operand, inputs=inputs, outputs=outputs)
        if self.reload_or_end(c, box, operand):
            return True
        if not marked and slots == 0:
            return False
        raise FinalBoxError(box)

    def preset(self, operand: str) -> tuple[str | Series, str] | None:
        """``<S chain>; L <PV>; S C n`` of a counter box, or None (position unchanged)."""
        save = self.i
        self.in_slot += 1
        try:
            elements, final = self.chain(nested=False)
        except RefusalError:
            self.i = save
            return None
        finally:
            self.in_slot -= 1
        load, setter = self.peek(), self.peek(1)
        if (
            final is None
            and elements
            and load is not None
            and setter is not None
            and load.op == "L"
            and setter.op == "S"
            and setter.operand == operand
            and not load.labels
            and not setter.labels
        ):
            self.i += 2
            return self.pin(elements), self.value(load)
        self.i = save
        return None

    def flip_flop(self, c: Chain) -> bool:
        first = self.take()
        operand = first.operand or ""
        other = "R" if first.op == "S" else "S"
        second = self.slot_chain(other, operand)
        if second is None:
            return False
        name, pin = ("SR", "R1") if first.op == "S" else ("RS", "S1")
        box = Box(name=name, instance=operand, inputs={pin: self.pin(second)})
        if self.reload_or_end(c, box, operand):
            return True
        raise FinalBoxError(box)


def edge_box(inner: list[Element]) -> Box | None:
    """``A( A bit; FP m )``: the POS (NEG) box on ``bit`` with its memory ``M_BIT``."""
    if len(inner) != 2:
        return None
    bit, edge = inner
    if isinstance(bit, Contact) and not bit.negated and isinstance(edge, EdgeContact):
        name = "POS" if edge.edge == "P" else "NEG"
        return Box(name=name, instance=bit.operand, inputs={"M_BIT": edge.memory})
    return None
