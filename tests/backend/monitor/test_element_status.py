"""LAD/FBD element status is exact: evaluating each rung's power flow from the statuses alone
(contacts AND in series, the branches of a parallel ORed from the flow into it, every other
element's ``out``) gives the coil values the CPU wrote in the same scan, for every element kind
and box family, in many input combinations; what did not run is absent."""

from __future__ import annotations

import json
import random
import time
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import pytest

from nasaq.lang.lad.boxes import box_spec
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
    Network,
    OpenDb,
    Parallel,
    Return,
    Series,
    StatusContact,
)
from nasaq.lang.lad.text import parse_lad
from nasaq.lang.stl import SourceFile
from nasaq.monitor import targets
from nasaq.monitor.protocol import BlockStatus, ElementStatus
from nasaq.monitor.session import ClientView, Session

OB1 = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = contacts, a parallel acting on the flow, NOT, midlines, an edge, set and reset coils
RUNG
  Contact(I 0.0)
  PARALLEL
    BRANCH ContactNC(I 0.1) Not END_BRANCH
    BRANCH Contact(I 0.2) Contact(I 0.3) END_BRANCH
    BRANCH
      PARALLEL
        BRANCH Contact(I 0.4) END_BRANCH
        BRANCH Midline(M 1.0) END_BRANCH
      END_PARALLEL
    END_BRANCH
  END_PARALLEL
  Midline(M 1.1)
  OUTPUTS
    BRANCH Coil(Q 0.0) END_BRANCH
    BRANCH Edge(P, M 1.2) Coil(Q 0.1) END_BRANCH
    BRANCH ContactNC(I 0.5) SetCoil(M 2.0) END_BRANCH
    BRANCH Contact(I 0.6) ResetCoil(M 2.0) END_BRANCH
  END_OUTPUTS
END_RUNG
NETWORK
TITLE = math, then status contacts on its result
RUNG
  Contact(I 1.0)
  Box(SUB_I, IN1 := IW 2, IN2 := IW 4, OUT => MW 10)
  PARALLEL
    BRANCH Status(<0) END_BRANCH
    BRANCH StatusNC(==0) StatusNC(OV) END_BRANCH
  END_PARALLEL
  Coil(Q 1.0)
END_RUNG
NETWORK
TITLE = compare, MOVE with its own EN operand, conversion, word logic, shift
RUNG
  Box(CMP>I, IN1 := IW 2, IN2 := IW 4)
  Box(MOVE, EN := I 1.1, IN := IW 2, OUT => MW 12)
  Box(I_DI, IN := IW 4, OUT => MD 14)
  Box(WAND_W, IN1 := IW 2, IN2 := W#16#00FF, OUT => MW 18)
  Box(SHL_W, IN := IW 4, N := 3, OUT => MW 20)
  Coil(Q 1.1)
END_RUNG
NETWORK
TITLE = a MOVE ending the rung: its pins are absent when EN is 0
RUNG Contact(I 1.2) Box(MOVE, IN := IW 4, OUT => MW 22) END_RUNG
NETWORK
TITLE = a timer box with R, BI and BCD
RUNG
  Contact(I 1.3)
  Box(S_PULSE, INSTANCE T 1, TV := S5T#50MS, R := I 1.4, BI => MW 24, BCD => MW 26)
  Coil(Q 2.0)
END_RUNG
NETWORK
TITLE = an up/down counter, its CD fed by logic
RUNG
  Contact(I 1.5)
  Box(S_CUD, INSTANCE C 1, CD := RUNG Contact(I 1.6) ContactNC(I 1.7) END_RUNG, S := I 2.0,
      PV := C#5, R := I 2.1, CV => MW 28)
  Coil(Q 2.1)
END_RUNG
NETWORK
TITLE = RS from its own R operand, then POS
RUNG
  Box(RS, INSTANCE M 3.0, R := I 2.2, S1 := I 2.3)
  Box(POS, INSTANCE I 2.4, M_BIT := M 3.1)
  Coil(Q 2.2)
END_RUNG
NETWORK
TITLE = NEG, then SR
RUNG
  Contact(I 2.5)
  Box(NEG, INSTANCE I 2.6, M_BIT := M 3.2)
  Box(SR, INSTANCE M 3.3, R1 := I 2.7)
  Coil(Q 2.3)
END_RUNG
NETWORK
TITLE = boxes whose Q is not used: the state after the box
RUNG
  Contact(I 3.0)
  OUTPUTS
    BRANCH Box(S_ODT, INSTANCE T 2, TV := S5T#30MS) END_BRANCH
    BRANCH Contact(I 3.1) Box(S_CU, INSTANCE C 2) END_BRANCH
  END_OUTPUTS
END_RUNG
NETWORK
TITLE = timer and counter coils, SAVE
RUNG
  Contact(I 3.2)
  OUTPUTS
    BRANCH SE(T 3, S5T#40MS) END_BRANCH
    BRANCH Contact(I 3.3) CU(C 3) END_BRANCH
    BRANCH ContactNC(I 3.3) CD(C 3) END_BRANCH
    BRANCH Contact(I 3.4) SC(C 3, C#7) END_BRANCH
    BRANCH Save END_BRANCH
  END_OUTPUTS
END_RUNG
NETWORK
TITLE = a call with a Boolean pin fed by logic
RUNG
  Contact(I 3.5)
  Box(FC 1, x := RUNG Contact(I 3.6) ContactNC(I 3.7) END_RUNG, y => MW 30)
  Coil(Q 3.0)
END_RUNG
NETWORK
TITLE = a call of a block drawn in FBD
RUNG
  Box(FC 2, a := I 4.0, b := I 4.1)
END_RUNG
NETWORK
RUNG Open(DB 1) END_RUNG
NETWORK
RUNG Contact(I 4.2) Jump(SKIP) END_RUNG
NETWORK
RUNG Contact(I 4.3) Coil(Q 3.1) END_RUNG
NETWORK
LABEL SKIP
RUNG Contact(I 4.4) JumpN(LAST) END_RUNG
NETWORK
RUNG Contact(I 4.5) Coil(Q 3.2) END_RUNG
NETWORK
LABEL LAST
RUNG Contact(I 4.6) Return END_RUNG
NETWORK
RUNG Contact(I 4.7) Coil(Q 3.3) END_RUNG
END_ORGANIZATION_BLOCK
"""

FC2 = """\
FUNCTION FC 2 : VOID
LANGUAGE FBD
VAR_INPUT
  a : BOOL;
  b : BOOL;
END_VAR
BEGIN
NETWORK
RUNG
  PARALLEL
    BRANCH Contact(#a) END_BRANCH
    BRANCH ContactNC(#b) END_BRANCH
  END_PARALLEL
  Coil(Q 5.0)
END_RUNG
END_FUNCTION
"""

STL = """\
DATA_BLOCK DB 1
  STRUCT
    x : INT;
  END_STRUCT;
BEGIN
END_DATA_BLOCK

FUNCTION FC 1 : VOID
VAR_INPUT
  x : BOOL;
END_VAR
VAR_OUTPUT
  y : INT;
END_VAR
BEGIN
NETWORK
      L     MW    40
      +     1
      T     MW    40
      T     #y
      A     #x
      SAVE
END_FUNCTION
"""

BITS = [f"I {byte}.{bit}" for byte in (0, 1, 2, 3, 4) for bit in range(8)]
WORDS = ["IW 2", "IW 4"]


@dataclass
class Sampled:
    """One sampled scan: the block status and the memory the CPU left after it."""

    status: BlockStatus
    memory: dict[str, Any]


class Plant:
    """A session in its own thread; each ``sample`` sets inputs and runs one sampled scan."""

    def __init__(self, sources: list[SourceFile]) -> None:
        self.session = Session("element-status", sources)
        self.session.clients[1] = ClientView()
        self.session.start()
        self.run(self.session.do_run)

    def run(self, action: Any) -> Any:
        return self.session.submit(action).result(timeout=5)

    def sample(
        self,
        inputs: dict[str, Any],
        read: list[str],
        block: str = "OB1",
        networks: list[int] | None = None,
    ) -> Sampled:
        session = self.session

        def prepare() -> tuple[int, Any]:
            for address, value in inputs.items():
                session.do_set_input(address.replace(" ", ""), value)
            session.do_open_block(1, block, networks)  # the next scan is sampled
            session.do_run_scans(1)
            return session.cpu.scans, session.view(1).open_block

        scans, key = self.run(prepare)
        deadline = time.monotonic() + 5
        while True:
            snapshot = session.snapshot
            status = snapshot.blocks.get(key) if snapshot else None
            if status is not None and status.scan > scans and session.cpu.scans > scans:
                break
            assert time.monotonic() < deadline, "no sampled scan"
            time.sleep(0.002)

        def memory() -> dict[str, Any]:
            program = session.program
            return {
                text: targets.read(targets.resolve(text, program), session.cpu) for text in read
            }

        return Sampled(status, self.run(memory))

    def close(self) -> None:
        self.session.close()


@pytest.fixture(scope="module")
def plant() -> Iterator[Plant]:
    found = Plant(
        [
            SourceFile("main.lad", OB1),
            SourceFile("fc2.lad", FC2),
            SourceFile("blocks.awl", STL),
        ]
    )
    yield found
    found.close()


def _block(text: str, name: str) -> LadBlock:
    [block], problems = parse_lad(text, name)
    assert problems == []
    return block


def _operands(block: LadBlock) -> list[str]:
    """Every coil, midline and box output operand of the block: what the CPU wrote."""
    found: list[str] = []

    def walk(node: Element | Final) -> None:
        if (isinstance(node, Coil) and node.coil in ("=", "S", "R")) or isinstance(node, Midline):
            found.append(node.operand)
        elif isinstance(node, Box):
            found.extend(node.outputs.values())
            for value in node.inputs.values():
                if isinstance(value, Series):
                    for element in value.elements:
                        walk(element)
        elif isinstance(node, Parallel):
            for branch in node.branches:
                for element in branch.elements:
                    walk(element)

    for network in block.networks:
        for element in network.logic.elements:
            walk(element)
        for output in network.outputs:
            for element in output.conditions.elements:
                walk(element)
            walk(output.target)
    return sorted(set(found))


class Rung:
    """Evaluates one network's power flow from its element statuses and checks each element
    against the flow into it and against the memory the CPU wrote."""

    def __init__(
        self, statuses: dict[str, ElementStatus], memory: dict[str, Any], written: dict[str, Any]
    ) -> None:
        self.statuses = statuses
        self.memory = memory
        self.written = written  # operand -> the value the last element that wrote it reported

    def state(self, node: Element | Final) -> ElementStatus:
        assert node.id in self.statuses, f"{node.id} ({node.kind}) did not report"
        return self.statuses[node.id]

    def series(self, series: Series, flow: bool) -> bool:
        for element in series.elements:
            flow = self.element(element, flow)
        return flow

    def element(self, node: Element, flow: bool) -> bool:
        if isinstance(node, Parallel):
            self.state(node)
            branches = [self.series(branch, flow) for branch in node.branches]  # check them all
            return any(branches)
        state = self.state(node)
        if isinstance(node, Contact | StatusContact):
            assert state.out is None, state
            assert isinstance(state.value, bool), state
            return flow and state.value != node.negated
        if isinstance(node, Invert):
            assert state.out is (not flow), state
            return not flow
        if isinstance(node, Midline):
            assert state.value is flow, state
            assert state.out is flow, state
            self.written[node.operand] = flow
            return flow
        if isinstance(node, EdgeContact):
            assert state.value is flow, state  # the memory keeps the flow for the next scan
            assert flow or state.out is False, state
            return bool(state.out)
        assert isinstance(node, Box)
        return self.box(node, flow)

    def box(self, node: Box, flow: bool) -> bool:
        state = self.state(node)
        spec = box_spec(node.name)
        for pin, value in node.inputs.items():
            if isinstance(value, Series) and (spec is None or pin != spec.flow_pin):
                self.series(value, True)  # pin logic starts at the rail
        if spec is not None and spec.family in ("compare", "edge"):
            if spec.family == "compare":
                left, right = state.pins["IN1"], state.pins["IN2"]
                assert isinstance(left, int)
                assert isinstance(right, int)
                assert state.out is _compare(spec.op, left, right), state
            else:
                assert isinstance(state.value, bool), state
            return flow and bool(state.out)
        flow_pin = "EN" if spec is None else spec.flow_pin
        assert flow_pin is not None
        if flow_pin not in node.inputs:  # an operand on the flow pin is ANDed with the flow
            assert state.pins[flow_pin] is flow, (node.id, state)
        if spec is None or spec.en_eno:
            enabled = state.pins["EN"]
            assert state.pins["ENO"] is state.out
            if not enabled:
                assert state.out is False, state
                assert set(state.pins) == {"EN", "ENO"}, state  # the body did not run
            else:
                for pin, operand in node.outputs.items():
                    self.written[operand] = _bits(state.pins[pin], operand)
        else:
            assert state.pins["Q"] is state.out, state
            if spec.family == "flipflop":
                assert state.value is state.out, state
            else:
                assert isinstance(state.value, int), state
        return bool(state.out)

    def target(self, node: Final, flow: bool) -> bool | None:
        """Checks the rung's end; for a jump or RET whether it is taken."""
        if isinstance(node, Box):
            self.box(node, flow)
            return None
        state = self.state(node)
        if isinstance(node, OpenDb):
            return None
        assert state.out is flow, (node.id, state)
        if isinstance(node, Coil):
            if node.coil == "=":
                assert state.value is flow, state
                self.written[node.operand] = flow
            elif node.coil in ("S", "R"):
                if flow:
                    assert state.value is (node.coil == "S"), state
                self.written[node.operand] = state.value
            elif node.coil in ("SE", "CU", "CD", "SC"):
                assert isinstance(state.value, int), state
            return None
        if isinstance(node, Jump):
            return flow is not node.negated
        assert isinstance(node, Return)
        return flow


def _bits(value: Any, operand: str) -> Any:
    """A pin's value as the watch shows its operand (``MW`` a WORD, ``MD`` a DWORD)."""
    if isinstance(value, bool) or not isinstance(value, int):
        return value
    return value & (0xFFFF if operand.startswith("MW") else 0xFFFFFFFF)


def _compare(op: str, left: int, right: int) -> bool:
    relation = op[:-1]
    return {
        "==": left == right,
        "<>": left != right,
        ">": left > right,
        "<": left < right,
        ">=": left >= right,
        "<=": left <= right,
    }[relation]


def check(block: LadBlock, sampled: Sampled) -> list[int]:
    """Checks every network of ``block`` against the sample; the networks that ran."""
    statuses: dict[int, dict[str, ElementStatus]] = {}
    for status in sampled.status.elements:
        statuses.setdefault(status.network, {})[status.id] = status
    ran: list[int] = []
    skip_to: str | None = None
    returned = False
    written: dict[str, Any] = {}
    for number, network in enumerate(block.networks, start=1):
        if skip_to is not None and network.label == skip_to:
            skip_to = None
        if skip_to is not None or returned:
            assert number not in statuses, f"network {number} was jumped over: {statuses[number]}"
            continue
        ran.append(number)
        rung = Rung(statuses.get(number, {}), sampled.memory, written)
        taken = _network(rung, network)
        if taken and isinstance(network.outputs[-1].target, Jump):
            skip_to = network.outputs[-1].target.label
        elif taken and isinstance(network.outputs[-1].target, Return):
            returned = True
    # What the last element writing each operand reported is what the CPU left there.
    assert {operand: sampled.memory[operand] for operand in written} == written
    return ran


def _network(rung: Rung, network: Network) -> bool | None:
    common = rung.series(network.logic, True)
    taken = None
    for output in network.outputs:
        flow = rung.series(output.conditions, common)
        taken = rung.target(output.target, flow)
    return taken


def _every_id(network: Network) -> set[str]:
    ids: set[str] = set()

    def walk(node: Element | Final) -> None:
        ids.add(node.id)
        if isinstance(node, Parallel):
            for branch in node.branches:
                for element in branch.elements:
                    walk(element)
        if isinstance(node, Box):
            for value in node.inputs.values():
                if isinstance(value, Series):
                    for element in value.elements:
                        walk(element)

    for element in network.logic.elements:
        walk(element)
    for output in network.outputs:
        for element in output.conditions.elements:
            walk(element)
        walk(output.target)
    return ids


def test_the_flow_from_the_statuses_gives_what_the_cpu_wrote(plant: Plant) -> None:
    block = _block(OB1, "main.lad")
    read = _operands(block)
    rng = random.Random(7)
    seen_networks: set[int] = set()
    jumped = returned = disabled = 0
    for sample in range(80):
        inputs: dict[str, Any] = {bit: rng.random() < 0.5 for bit in BITS}
        inputs["IW 2"] = rng.choice([-3, 0, 5, 7, 200, 32767])
        inputs["IW 4"] = rng.choice([-32768, -5, 0, 5, 9, 1000])
        if sample < 4:  # the first scans: everything runs
            inputs["I 4.2"], inputs["I 4.4"], inputs["I 4.6"] = False, True, False
        sampled = plant.sample(inputs, read)
        assert sampled.status.language == "lad"
        ran = check(block, sampled)
        seen_networks |= set(ran)
        for number in ran:  # every element of a network that ran reports
            reported = {s.id for s in sampled.status.elements if s.network == number}
            assert reported == _every_id(block.networks[number - 1]), number
        jumped += 15 not in ran
        returned += 19 not in ran
        disabled += not inputs["I 1.2"]
    assert seen_networks == set(range(1, len(block.networks) + 1))
    # The input combinations reached every case.
    assert jumped > 0
    assert returned > 0
    assert disabled > 0


def test_a_block_drawn_in_fbd_reports_its_elements(plant: Plant) -> None:
    block = _block(FC2, "fc2.lad")
    for a in (False, True):
        for b in (False, True):
            sampled = plant.sample({"I 4.0": a, "I 4.1": b}, ["Q 5.0"], block="FC2")
            assert sampled.status.language == "fbd"
            assert check(block, sampled) == [1]
            assert sampled.memory["Q 5.0"] is (a or not b)


def test_only_the_networks_on_screen_are_recorded(plant: Plant) -> None:
    sampled = plant.sample({"I 1.0": True}, [], networks=[2, 5])
    assert {s.network for s in sampled.status.elements} == {2, 5}
    session = plant.session
    info = session.info(session.view(1).open_block or next(iter(session.lad)))
    assert {info.networks[row.index] for row in sampled.status.instructions} == {2, 5}
    everything = plant.sample({}, [])
    assert {s.network for s in everything.status.elements} >= {1, 2, 3, 5}


def test_two_clients_see_their_own_networks(plant: Plant) -> None:
    """The recorder records what any client shows; each client's frames carry its own."""
    session = plant.session
    frames: dict[int, list[str]] = {1: [], 2: []}
    session.emit = lambda client, text: frames[client].append(text)
    session.clients[2] = ClientView()
    try:

        def open_both() -> None:
            session.do_open_block(1, "OB1", [1])
            session.do_open_block(2, "OB1", [3, 4])
            session.view(1).state.block_scan = session.view(2).state.block_scan = None
            session.do_run_scans(1)

        plant.run(open_both)
        deadline = time.monotonic() + 5
        while not all('"elements"' in "".join(texts) for texts in frames.values()):
            assert time.monotonic() < deadline, frames
            time.sleep(0.005)
    finally:
        session.emit = None
        plant.run(lambda: session.clients.pop(2, None))
    for client, wanted in ((1, {1}), (2, {3, 4})):
        blocks = [json.loads(text)["block"] for text in frames[client]]
        shown = [b for b in blocks if b is not None]
        assert shown, client
        assert {e["network"] for e in shown[-1]["elements"]} == wanted


def test_networks_on_screen_jumped_over_show_nothing_not_the_previous_scan(plant: Plant) -> None:
    """Network 15 runs unless network 14 jumps over it: then the block ran, but nothing on
    screen did, and the status says so (an empty status, not the previous sample's)."""
    ran = plant.sample({"I 4.2": False, "I 4.3": True}, [], networks=[15])
    assert [(s.network, s.id) for s in ran.status.elements] == [(15, "e1"), (15, "e2")]
    jumped = plant.sample({"I 4.2": True}, [], networks=[15])
    assert jumped.status.scan > ran.status.scan
    assert jumped.status.elements == []
    assert jumped.status.instructions == []
