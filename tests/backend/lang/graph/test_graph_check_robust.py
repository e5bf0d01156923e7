"""The checker never raises, whatever model an editor or a half-read file hands it: random
blocks (names that clash or name nothing, any event × qualifier, odd operands and values,
any condition element) give catalogued diagnostics placed on a part of the block."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from nasaq.diagnostics.catalogue import entry
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.model import (
    Action,
    GraphBlock,
    Sequencer,
    Settings,
    Step,
    Transition,
)
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Invert,
    Network,
    Output,
    Parallel,
    Series,
)

NAMES = st.sampled_from(["Idle", "Run", "run", "S1", "S2", "T1", "INIT_SQ", "G7_x", "", "a b"])
OPERANDS = st.sampled_from(
    ["Q 0.0", "C 1", "T 2", "FC 1", "S_ALL", "S2", "Run", "#a := Run.T", "", "Idle.X", '"x".T']
)
VALUES = st.sampled_from([None, "T#5S", "S5T#1S", "C#3", "26", "", "MW 2"])
LEAVES = st.sampled_from(
    [
        Contact(operand="I 0.0"),
        Contact(operand="Run.T", negated=True),
        Contact(operand="S9.X"),
        Invert(),
        EdgeContact(edge="P", memory="M 0.0"),
        Box(name="CMP>D", inputs={"IN1": "S1.T", "IN2": "T#1S"}),
        Box(name="MOVE", inputs={"IN": "1"}, outputs={"OUT": "MW 0"}),
    ]
)


def _series(depth: int = 2) -> st.SearchStrategy[Series]:
    leaf = LEAVES
    if depth == 0:
        return st.lists(leaf, max_size=3).map(lambda items: Series(elements=items))
    branch = st.lists(_series(depth - 1), min_size=2, max_size=2).map(
        lambda branches: Parallel(branches=branches)
    )
    return st.lists(st.one_of(leaf, branch), max_size=3).map(lambda items: Series(elements=items))


ACTIONS = st.builds(
    Action,
    event=st.sampled_from([None, "S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1"]),
    qualifier=st.sampled_from(
        ["N", "S", "R", "D", "L", "CALL", "ON", "OFF", "CS", "CU", "CD", "CR", "TL", "TD", "TR"]
    ),
    interlock=st.booleans(),
    operand=OPERANDS,
    time=VALUES,
)
STEPS = st.builds(
    Step,
    number=st.integers(1, 4),
    name=NAMES,
    initial=st.booleans(),
    interlock=st.none() | _series(),
    supervision=st.none() | _series(),
    actions=st.lists(ACTIONS, max_size=3),
)
TRANSITIONS = st.builds(
    Transition,
    number=st.integers(1, 4),
    name=NAMES,
    source=st.lists(NAMES, min_size=1, max_size=2),
    target=st.lists(NAMES, max_size=2),
    jump=st.booleans(),
    condition=st.none() | _series(),
)
NETWORKS = st.builds(
    Network,
    logic=_series(1),
    outputs=st.lists(
        st.sampled_from(
            [Output(target=Coil(coil="=", operand="Q 1.0")), Output(target=Coil(coil="SD"))]
        ),
        max_size=2,
    ),
)
BLOCKS = st.builds(
    GraphBlock,
    name=st.just("FB 1"),
    settings=st.builds(
        Settings, parameters=st.sampled_from(["MINIMUM", "STANDARD", "MAXIMUM", "USER_DEFINED"])
    ),
    declarations=st.sampled_from(["", "VAR\n  Run : INT;\nEND_VAR", "VAR\n  broken", "VAR_INPUT"]),
    pre=st.lists(NETWORKS, max_size=2),
    sequencers=st.lists(
        st.builds(
            Sequencer,
            name=st.sampled_from(["A", "B", "A"]),
            steps=st.lists(STEPS, max_size=4),
            transitions=st.lists(TRANSITIONS, max_size=4),
        ),
        max_size=2,
    ),
)


@settings(max_examples=100, deadline=None)
@given(BLOCKS, st.sampled_from([[], [{"BLOCK": 3, "S1": 5, "T1": 7}]]))
def test_random_blocks_give_catalogued_placed_diagnostics(
    block: GraphBlock, places: list[dict[str, int]]
) -> None:
    parsed = ParsedGraph(file="r.graph", blocks=[block], places=places)
    for problem in check_block(parsed, 0):
        assert entry(problem.code).key == problem.key
        assert problem.code.startswith("GRA2")
        assert problem.span is not None
        assert problem.span.file == "r.graph"
        assert problem.span.line is not None
        assert problem.span.line >= 1
        assert problem.span.element
