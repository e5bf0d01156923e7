"""Reads the steps of one STL network as a LAD rung, or stops at the first reason it cannot.

The reading follows the status word, not a grammar of text: a first check loads the RLO, ``A``
adds an element in series, ``O x`` ORs one contact with *everything so far* (the S7 status
tables clear the OR bit, so ``A a; A b; O c; A d`` is ((a AND b) OR c) AND d, as our CPU runs
it), a bare ``O`` parks the AND group so far (AND before OR: ``A a; A b; O; A c; A d`` is
(a AND b) OR (c AND d)), brackets nest. ``= x`` followed by ``A x`` is a midline; a box's flow
out is reloaded the same way (``A BR`` after an EN/ENO box, ``A T 1`` after a timer box, ``A m``
after SR/RS), so after a box the chain goes on in series. The shapes ``to_stl`` writes are in
``STL_PATTERNS.md``: temporaries ``#_lad_tN`` carry the common logic into output branches, a
flow past a parallel with side effects, and Boolean inputs of calls.

The chain state is ``from_stl_chain.Chain``; box patterns are ``from_stl_box_reading``.
"""

from __future__ import annotations

from typing import NoReturn

from nasaq.lang.lad.from_stl_box_reading import (
    BoxReading,
    FinalBoxError,
    PinDirections,
    edge_box,
)
from nasaq.lang.lad.from_stl_boxes import TIMERS
from nasaq.lang.lad.from_stl_chain import Chain, is_temp
from nasaq.lang.lad.from_stl_cursor import COUNTER, RLO_USERS, STATUS_BITS
from nasaq.lang.lad.from_stl_reasons import RefusalError, not_convertible
from nasaq.lang.lad.from_stl_steps import Step
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    Midline,
    OpenDb,
    Output,
    Return,
    Series,
    StatusContact,
)
from nasaq.lang.lad.to_stl_boxes import needs_whole_flow
from nasaq.lang.limits import MAX_LAD_NESTING

__all__ = ["FinalBoxError", "PinDirections", "RungReader", "is_temp"]


class RungReader(BoxReading):
    """Reads ``steps`` (one network) into ``logic`` and ``outputs``; raises ``RefusalError``."""

    def __init__(self, steps: list[Step], directions: PinDirections | None = None) -> None:
        super().__init__(steps, directions)
        self.saved: set[str] = set()  # temporaries that only carried the flow past pin logic
        self.in_pins = 0
        self.assigned: dict[str, set[str]] = {}
        self.label: str | None = None
        self.branch_temp = ""  # the temporary that carries the common logic to the outputs
        self.depth = 0  # brackets open around the chain being read

    # ---- network ----------------------------------------------------------------------------

    def read(self) -> tuple[str | None, list[Element], list[Output]]:
        first = self.steps[0]
        if first.labels:
            if len(first.labels) > 1:
                raise RefusalError(not_convertible("LAD304", first.line, first.labels[1]))
            self.label = first.labels[0]
            if self.is_nop(first):
                if len(self.steps) == 1:  # ``M001: NOP 0``: a jump target, an empty rung
                    return self.label, [], []
                self.i = 1
        start = self.peek()
        assert start is not None
        if start.op in ("JU", "BEU", "OPN"):
            return self.label, [], [Output(target=self.from_rail(self.take()))]
        if start.op in RLO_USERS:
            self.refuse("LAD309", start)
        if start.op == "T":
            self.refuse("LAD308", start)
        self.prelude()
        branches = [self.branch(first=True)]
        while (step := self.peek()) is not None:
            if self.is_branch_reload(branches[0][0], step):
                self.take()
                branches.append(self.branch(first=False))
                continue
            self.after_rung(step, branches[-1][1])
        logic, outputs = self.assemble(branches)
        return self.label, logic, outputs

    def is_branch_reload(self, elements: list[Element], step: Step) -> bool:
        """``A #t`` after the targets, where ``= #t`` kept the common logic: a new output."""
        if step.op != "A" or not is_temp(step.operand) or step.labels:
            return False
        if self.branch_temp:
            return step.operand == self.branch_temp
        if any(isinstance(e, Midline) and e.operand == step.operand for e in elements):
            self.branch_temp = step.operand or ""
            return True
        return False

    def prelude(self) -> None:
        """Boolean inputs of a call from the rail computed first: ``<chain>; = #t`` ... CALL."""
        start = self.i
        found: dict[str, Series] = {}
        while True:
            save = self.i
            try:
                elements, store = self.pin_chain()
            except RefusalError:
                self.i = save
                break
            after = self.peek()
            if after is not None and after.op == "A" and after.operand == store.operand:
                self.i = save
                break
            found[store.operand or ""] = Series(elements=elements)
        step = self.peek()
        if found and step is not None and step.op == "CALL":
            self.pin_logic.update(found)
        else:
            self.i = start

    def pin_chain(self) -> tuple[list[Element], Step]:
        """``<logic>; = #t`` (``SET; = #t`` for the rail): a Boolean pin in a temporary."""
        step, nxt = self.peek(), self.peek(1)
        rail = step is not None and step.op == "SET" and nxt is not None and nxt.op == "="
        if rail and nxt is not None and is_temp(nxt.operand) and not nxt.labels:
            self.i += 2
            return [], nxt
        self.in_pins += 1
        try:
            elements, final = self.chain(nested=False)
        finally:
            self.in_pins -= 1
        store = self.peek()
        if final is not None or store is None or store.op != "=" or not elements:
            self.refuse("LAD325", store or step)
        if not is_temp(store.operand) or store.labels:
            self.refuse("LAD325", store)
        self.take()
        return elements, store

    def from_rail(self, step: Step) -> Final:
        if self.peek() is not None:
            nxt = self.peek()
            assert nxt is not None
            self.refuse(
                "LAD314" if step.op != "OPN" else "LAD326", nxt if step.op != "OPN" else step
            )
        if step.operand is None and step.op != "BEU":
            self.refuse("LAD317", step)
        if step.op == "JU":
            return Jump(label=step.operand or "")
        if step.op == "BEU":
            return Return()
        return OpenDb(block=step.operand or "")

    def after_rung(self, step: Step, finals: list[Final]) -> NoReturn:
        """Something follows the rung's outputs: say what."""
        if finals and isinstance(finals[-1], Jump | Return):
            self.refuse("LAD314", step)
        if finals and isinstance(finals[-1], Box) and not step.labels:
            self.refuse("LAD306", step)
        self.refuse(self.classify(step), step)

    def branch(self, first: bool) -> tuple[list[Element], list[Final]]:
        """One chain and the targets that end it (a later branch: after its ``A #t``)."""
        start = self.peek()
        reload = self.steps[self.i - 1] if not first else None
        if reload is not None:
            # The output's conditions start from the common logic in ``#t``: read ``A #t`` as
            # the chain's start (a parallel, a box or an edge there acts on that flow) and drop
            # it afterwards
            self.i -= 1
            elements, final = self.chain(nested=False)
            if not elements or elements[0] != Contact(operand=reload.operand or ""):
                self.refuse("LAD306", reload)
            elements = elements[1:]
        else:
            elements, final = self.chain(nested=False)
        if final is not None:
            return elements, [final]
        finals = self.targets()
        if not finals:
            step = self.peek()
            if step is None:
                self.refuse("LAD312", self.steps[-1])
            self.refuse(self.classify(step), step)
        if first and not elements and start is not None and start.op != "SET":
            self.refuse("LAD309", start)
        return elements, finals

    def assemble(
        self, branches: list[tuple[list[Element], list[Final]]]
    ) -> tuple[list[Element], list[Output]]:
        cleaned = [(self.unsaved(elements), finals) for elements, finals in branches]
        elements, finals = cleaned[0]
        if len(cleaned) == 1:
            return elements, [Output(target=final) for final in finals]
        temp = self.branch_temp
        at = max(i for i, e in enumerate(elements) if isinstance(e, Midline) and e.operand == temp)
        outputs: list[Output] = []
        for number, (conditions, targets) in enumerate(cleaned):
            own = elements[at + 1 :] if number == 0 else conditions
            if len(targets) > 1 and own and not all(isinstance(e, Contact) for e in own):
                self.refuse("LAD306", self.steps[-1])
            outputs.extend(Output(conditions=Series(elements=own), target=t) for t in targets)
        return elements[:at], outputs

    def unsaved(self, elements: list[Element]) -> list[Element]:
        return [e for e in elements if not (isinstance(e, Midline) and e.operand in self.saved)]

    # ---- chains -----------------------------------------------------------------------------

    def chain(self, nested: bool) -> tuple[list[Element], Final | None]:
        """A chain up to its targets (or its ``)``), boxes in series included; a box that ends
        the rung (ENO unused) comes back as the final element."""
        c = Chain()
        while (step := self.peek()) is not None:
            self.no_label(step)
            op = step.op
            if op in ("A", "AN", "O", "ON"):
                self.check(c, self.take())
            elif op in ("X", "XN", "X(", "XN("):
                self.refuse("LAD305", step)
            elif op in ("A(", "AN(", "O(", "ON("):
                self.bracket(c, self.take())
            elif op == ")":
                if not nested:
                    self.refuse("LAD311", step)
                self.take()
                result = c.elements()
                if not result:
                    self.refuse("LAD324", step)
                return result, None
            elif op in ("NOT", "FP", "FN"):
                self.flow_element(c, self.take())
            elif op == "SET" and c.empty() and not c.done and not c.rail and self.rail_target():
                self.take()
                c.rail = True
            elif op == "=" and self.midline(c, step):
                continue
            elif op == "L" and c.empty() and c.reload is None and not c.rail:
                final = self.accu_start(c)
                if final is not None:
                    return c.elements(), final
            elif op == "CALL" and c.empty() and c.reload is None:
                final = self.en_box(c, None)
                if final is not None:
                    return c.elements(), final
            elif op == "CALL":
                self.refuse("LAD321", step)
            elif op == "JNB" and not c.empty():
                if c.groups:
                    self.refuse("LAD320", step)
                final = self.en_box(c, self.take())
                if final is not None:
                    return c.elements(), final
            elif (c.rail or not c.empty()) and not self.in_slot:
                try:
                    if not self.try_box(c):
                        break
                except FinalBoxError as final:
                    return c.elements(), final.box
            else:
                break
        if nested:
            step = self.peek()
            if step is not None and step.op in ("=", "S", "R"):
                self.refuse("LAD313", step)
            if step is None:
                self.refuse("LAD311", self.steps[-1])
            self.refuse(self.classify(step), step)
        if c.groups and not c.current:
            self.refuse("LAD312", self.peek() or self.steps[-1])
        return c.elements(), None

    def rail_target(self) -> bool:
        nxt = self.peek(1)
        targets = ("=", "S", "R", "L", "CU", "CD", "JCN", "JC", "SAVE")
        return nxt is not None and nxt.op in targets and not nxt.labels

    def contact(self, step: Step) -> Element:
        negated = step.op in ("AN", "ON")
        operand = step.operand
        if step.kind == "indirect":
            self.refuse("LAD316", step)
        if operand is None or step.kind in ("literal", "none"):
            self.refuse("LAD317", step)
        if step.kind == "status":
            return StatusContact(bit=operand, negated=negated)
        if step.kind == "bare" and operand.upper() in STATUS_BITS:
            return StatusContact(bit=operand.upper(), negated=negated)
        return Contact(operand=operand, negated=negated)

    def check(self, c: Chain, step: Step) -> None:
        if step.operand is None:
            if step.op != "O":
                self.refuse("LAD317", step)
            if not c.current:
                self.refuse("LAD310", step)
            c.groups.append(c.current)
            c.current = []
            c.bare_o = step
            return
        element = self.contact(step)
        self.add(c, step.op in ("O", "ON"), [element])

    def add(self, c: Chain, ored: bool, elements: list[Element]) -> None:
        if not ored or c.empty():
            c.current.extend(elements)
            return
        so_far = [*c.groups, c.current] if c.current else c.groups  # ``O; O x``: nothing new
        c.current = [c.parallel([*so_far, elements])]
        c.groups = []

    def bracket(self, c: Chain, step: Step) -> None:
        self.depth += 1
        if self.depth > MAX_LAD_NESTING:  # the lift recurses per level (STEP 7 allows 7)
            self.refuse("LAD151", step)
        try:
            inner, _ = self.chain(nested=True)
        finally:
            self.depth -= 1
        op = step.op
        if op == "A(":
            box = edge_box(inner)
            # NOT, an edge, a midline or a box after other checks, also inside a nested
            # parallel: in the bracket it sees only the bracket's flow, in LAD the whole flow
            if box is None and not c.empty() and any(needs_whole_flow(e) for e in inner):
                self.refuse("LAD327", step)
            self.add(c, False, [box] if box is not None else inner)
        elif op == "AN(":
            if not c.empty():
                self.refuse("LAD319", step)
            c.current = [*inner, Invert()]
        else:
            branch = [*inner, Invert()] if op == "ON(" else inner
            self.add(c, True, branch)

    def flow_element(self, c: Chain, step: Step) -> None:
        if c.groups:
            self.refuse("LAD320", step)
        if not c.current:
            self.refuse("LAD309", step)
        if step.op == "NOT":
            c.current.append(Invert())
            return
        if step.kind == "indirect":
            self.refuse("LAD316", step)
        if step.operand is None or step.kind not in ("address", "symbol", "bare"):
            self.refuse("LAD317", step)
        c.current.append(EdgeContact(edge="P" if step.op == "FP" else "N", memory=step.operand))

    def midline(self, c: Chain, step: Step) -> bool:
        """``= x; A x`` (a midline) or ``= #t`` + Boolean pin logic + ``A #t``."""
        nxt = self.peek(1)
        operand = step.operand
        if operand is None or c.empty():
            return False
        if nxt is not None and nxt.op == "A" and nxt.operand == operand and not nxt.labels:
            self.take()
            self.take()
            self.note(step, "=")
            c.restart(Midline(operand=operand), Contact(operand=operand), nxt)
            return True
        if not is_temp(operand) or self.in_pins:
            return False
        save = self.i
        try:
            self.take()
            self.pins(operand)
        except RefusalError:
            self.i = save
            return nxt is not None and nxt.op in ("A(", "O(") and self.flow_past_parallel(c, step)
        self.saved.add(operand)
        c.restart(Midline(operand=operand), Contact(operand=operand), self.steps[self.i - 1])
        return True

    def flow_past_parallel(self, c: Chain, step: Step) -> bool:
        """``= #t`` then a parallel whose every branch starts with ``A #t``."""
        self.take()
        operand = step.operand or ""
        c.restart(Midline(operand=operand), Contact(operand=operand), step, reloaded=False)
        c.unloaded = step
        return True

    def pins(self, temp: str) -> None:
        """Boolean inputs of a call computed into temporaries, then the flow reloaded."""
        while True:
            step = self.peek()
            if step is None:
                self.refuse("LAD312", self.steps[-1])
            if step.op == "A" and step.operand == temp:
                self.take()
                return
            elements, store = self.pin_chain()
            self.pin_logic[store.operand or ""] = Series(elements=elements)

    def note(self, step: Step, kind: str) -> None:
        """Refuses =, S and R mixed on one operand (LAD307)."""
        operand = step.operand or ""
        kinds = self.assigned.setdefault(operand, set())
        if (kind == "=" and kinds & {"S", "R"}) or (kind in ("S", "R") and "=" in kinds):
            self.refuse("LAD307", step)
        kinds.add(kind)

    # ---- targets ----------------------------------------------------------------------------

    def targets(self) -> list[Final]:
        finals: list[Final] = []
        while (step := self.peek()) is not None:
            self.no_label(step)
            op = step.op
            if op in ("=", "S", "R"):
                self.coil_operand(step)
                if op == "S" and COUNTER.fullmatch(step.operand or ""):
                    self.refuse("LAD323", step)
                self.note(self.take(), op)
                finals.append(Coil(coil=op, operand=step.operand or ""))
            elif op == "L":
                nxt = self.peek(1)
                if nxt is None or not (nxt.op in TIMERS or nxt.op == "S"):
                    self.refuse("LAD303", step)
                self.coil_operand(nxt)
                self.take()
                self.take()
                kind = "SC" if nxt.op == "S" else nxt.op
                finals.append(Coil(coil=kind, operand=nxt.operand or "", value=step.operand))
            elif op in TIMERS:
                self.refuse("LAD323", step)
            elif op in ("CU", "CD"):
                self.coil_operand(step)
                self.take()
                finals.append(Coil(coil=op, operand=step.operand or ""))
            elif op == "SAVE":
                self.take()
                finals.append(Coil(coil="SAVE"))
            elif op in ("JC", "JCN"):
                self.coil_operand(step)
                self.take()
                finals.append(Jump(label=step.operand or "", negated=op == "JCN"))
                break
            elif op == "BEC":
                self.take()
                finals.append(Return())
                break
            elif op == "JU" and finals:
                self.refuse("LAD315", step)
            else:
                break
        return finals
