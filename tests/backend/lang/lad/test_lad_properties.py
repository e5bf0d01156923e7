"""Properties of random LAD networks (``lad_strategies``): the STL, FBD and text views give the
same network back, and the network, its STL on the CPU and its FBD compute the same outputs.

The oracle is a Python reading of the tree with LAD's own semantics: a parallel's branches all
start from the flow into it, every element is evaluated in reading order (no short circuit), a
midline and an edge write their memory as they are passed. The FBD oracle evaluates the FBD
graph on its own, so neither view is checked against itself.

Settings are ``derandomize=True``: CI runs the same examples every time (no failure that appears
once and never again, no example database to carry); the example counts keep the file at a few
seconds, and widening the search is a matter of raising ``max_examples`` locally.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hypothesis import assume, given, settings
from hypothesis import strategies as st
from lad_strategies import (
    BITS,
    COILS,
    EDGE_MEMORIES,
    MIDLINES,
    RESULTS,
    WORDS,
    blocks,
    networks,
)

from nasaq.cpu import Cpu
from nasaq.headless.addresses import encode_value, parse_address, signed
from nasaq.ir import Direct
from nasaq.lang.lad.fbd import (
    FbdAssign,
    FbdBox,
    FbdBranch,
    FbdEdge,
    FbdLogic,
    FbdMidline,
    FbdNetwork,
    FbdNode,
    FbdNot,
    FbdOperand,
    from_fbd,
    to_fbd,
)
from nasaq.lang.lad.from_stl import lift_block
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Invert,
    LadBlock,
    Midline,
    Network,
    Parallel,
    Series,
)
from nasaq.lang.lad.text import number_network, parse_lad, print_lad
from nasaq.lang.lad.to_stl import block_to_stl
from nasaq.lang.stl import SourceFile, compile_sources

State = dict[str, int]
QUICK = settings(max_examples=150, deadline=None, derandomize=True)

BIT_NAMES = (*BITS, *MIDLINES, *EDGE_MEMORIES, *COILS)


def _no_ids(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _no_ids(v) for k, v in value.items() if k != "id"}
    if isinstance(value, list):
        return [_no_ids(v) for v in value]
    return value


def shape(network: Network) -> Network:
    """The network with its ids renumbered and title/comment dropped: what must come back."""
    data = _no_ids(network.model_dump(exclude={"title", "comment"}))
    return number_network(Network.model_validate(data))


def one_block(network: Network) -> LadBlock:
    return LadBlock(kind="OB", name="OB 1", networks=[network])


# -- structure ---------------------------------------------------------------------------------


@QUICK
@given(networks(status=True))
def test_lad_to_stl_to_lad_gives_the_same_network(network: Network) -> None:
    text, problems = block_to_stl(one_block(network))
    assert problems == [], problems
    lifted = lift_block(text, "random.awl")
    assert lifted.diagnostics == [], (lifted.diagnostics, text)
    [back] = lifted.blocks[0].networks
    assert isinstance(back, Network), text
    assert shape(back) == shape(network), text


@QUICK
@given(networks(status=True))
def test_lad_to_fbd_to_lad_gives_the_same_network(network: Network) -> None:
    back = from_fbd(to_fbd(network))
    assert isinstance(back, Network), back
    assert shape(back) == shape(network)


@QUICK
@given(blocks(status=True), st.sampled_from(["LAD", "FBD"]))
def test_text_round_trip(block: LadBlock, language: str) -> None:
    block = block.model_copy(
        update={"language": language, "networks": [number_network(n) for n in block.networks]}
    )
    parsed, problems = parse_lad(print_lad([block]), "random.lad")
    assert problems == []
    assert parsed == [block]


# -- the oracles -------------------------------------------------------------------------------


def _compare(name: str, first: int, second: int) -> bool:
    op = name.removeprefix("CMP").removesuffix("I")
    return {
        "==": first == second,
        "<>": first != second,
        ">": first > second,
        "<": first < second,
        ">=": first >= second,
        "<=": first <= second,
    }[op]


def _word(state: Mapping[str, int], operand: str) -> int:
    return state[operand] if operand in state else int(operand)


def _box_value(box: Box | FbdBox, state: State) -> bool:
    first, second = box.inputs["IN1"], box.inputs["IN2"]
    assert isinstance(first, str)
    assert isinstance(second, str)
    return _compare(box.name, _word(state, first), _word(state, second))


def _en_box(box: Box | FbdBox, enabled: bool, state: State) -> bool:
    """MOVE / ADD_I: writes OUT when enabled; ENO is EN (the words are too small to overflow)."""
    if enabled:
        if box.name == "MOVE":
            value = _word(state, str(box.inputs["IN"]))
        else:
            value = _word(state, str(box.inputs["IN1"])) + _word(state, str(box.inputs["IN2"]))
        state[box.outputs["OUT"]] = value
    return enabled


def _edge(edge: str, memory: str, flow: bool, state: State) -> bool:
    before = bool(state[memory])
    state[memory] = int(flow)
    return flow and not before if edge == "P" else before and not flow


def _coil(kind: str, operand: str, flow: bool, state: State) -> None:
    if kind == "=":
        state[operand] = int(flow)
    elif flow:
        state[operand] = int(kind == "S")


def lad_series(series: Series, flow: bool, state: State) -> bool:
    for element in series.elements:
        flow = lad_element(element, flow, state)
    return flow


def lad_element(element: Element, flow: bool, state: State) -> bool:
    if isinstance(element, Contact):
        return flow and bool(state[element.operand]) != element.negated
    if isinstance(element, Box):
        if element.name in ("MOVE", "ADD_I"):
            return _en_box(element, flow, state)
        return _box_value(element, state) and flow
    if isinstance(element, Parallel):
        branches = [lad_series(branch, flow, state) for branch in element.branches]
        return any(branches)
    if isinstance(element, Invert):
        return not flow
    if isinstance(element, EdgeContact):
        return _edge(element.edge, element.memory, flow, state)
    assert isinstance(element, Midline), element
    state[element.operand] = int(flow)
    return flow


def run_lad(network: Network, state: State) -> State:
    state = dict(state)
    common = lad_series(network.logic, True, state)
    for output in network.outputs:
        flow = lad_series(output.conditions, common, state)
        assert isinstance(output.target, Coil)
        _coil(output.target.coil, output.target.operand, flow, state)
    return state


class FbdRun:
    """One evaluation of an FBD graph: every box once, inputs top-down, an AND box's value kept
    for the taps of its wire (``FbdBranch.source``)."""

    def __init__(self, state: State, common: bool = True) -> None:
        self.state = state
        self.common = common
        self.wires: dict[str, bool] = {}

    def node(self, node: FbdNode) -> bool:
        state = self.state
        if isinstance(node, FbdOperand):
            return bool(state[node.operand]) != node.negated
        if isinstance(node, FbdBranch):
            return self.wires[node.source] if node.source else self.common
        if isinstance(node, FbdLogic):
            if node.flow is not None:
                self.node(node.flow)
            values = [self.node(item) for item in node.inputs]
            if node.op == "AND":
                self.wires[node.id] = all(values)
                return all(values)
            if node.op == "OR":
                return any(values)
            return sum(values) % 2 == 1
        if isinstance(node, FbdNot):
            return not self.node(node.input)
        if isinstance(node, FbdEdge):
            return _edge(node.edge, node.memory, self.node(node.input), state)
        if isinstance(node, FbdMidline):
            value = self.node(node.input)
            state[node.operand] = int(value)
            return value
        assert isinstance(node, FbdBox), node
        if node.en is not None:
            return _en_box(node, self.node(node.en), state)
        return _box_value(node, state)


def run_fbd(fbd: FbdNetwork, state: State) -> State:
    run = FbdRun(dict(state))
    run.common = run.node(fbd.logic)
    for output in fbd.outputs:
        assert isinstance(output, FbdAssign)
        _coil(output.coil, output.operand, run.node(output.input), run.state)
    return run.state


def _where(name: str) -> Direct:
    found = parse_address(name.replace(" ", ""))
    assert isinstance(found, Direct)
    return found


def bracket_depth(stl: str) -> int:
    """The deepest nesting of ``A(`` ... ``)`` in the STL (the CPU allows 7 levels)."""
    depth = deepest = 0
    for line in stl.splitlines():
        words = line.split()
        if words and words[0].endswith(":"):  # a jump label
            words = words[1:]
        op = words[0] if words else ""
        if op.endswith("("):
            depth += 1
            deepest = max(deepest, depth)
        elif op == ")":
            depth -= 1
    return deepest


def run_cpu(network: Network, state: State) -> State:
    """One scan of the network's STL on the CPU, started from ``state``. Networks nested
    deeper than the CPU's 7 bracket levels are not drawn (STL240 is tested on its own)."""
    text, problems = block_to_stl(one_block(network))
    assert problems == []
    assume(bracket_depth(text) <= 7)
    result = compile_sources([SourceFile("random.awl", text)])
    assert [d for d in result.diagnostics if d.severity == "error"] == [], text
    cpu = Cpu(result.program)
    cpu.start()
    for name, value in state.items():
        address = _where(name)
        if address.area.name == "I":
            cpu.set_input(address, encode_value(address, value))
        else:
            cpu.write(address, encode_value(address, value))
    cpu.run(1)
    assert cpu.mode == "RUN", (cpu.stop_reason, text)
    return {name: signed(cpu.read(_where(name)), _where(name).width) for name in state}


def _read_back(state: State) -> State:
    words = (*WORDS, *RESULTS)
    return {name: abs(value) if name not in words else value for name, value in state.items()}


states = st.fixed_dictionaries(
    {
        **{name: st.integers(0, 1) for name in BIT_NAMES},
        **{name: st.integers(-2, 2) for name in (*WORDS, *RESULTS)},
    }
)


@settings(max_examples=150, deadline=None, derandomize=True)
@given(networks(), states)
def test_lad_stl_and_fbd_compute_the_same_outputs(network: Network, state: State) -> None:
    expected = run_lad(network, state)
    assert _read_back(run_cpu(network, state)) == expected, block_to_stl(one_block(network))[0]
    fbd = to_fbd(network)
    assert run_fbd(fbd, state) == expected
    back = from_fbd(fbd)
    assert isinstance(back, Network)
    assert _read_back(run_cpu(back, state)) == expected
