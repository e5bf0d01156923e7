"""The .graph format: printing a model and reading it back gives the same model, the printed text
is canonical (stable), and the printer writes each step followed by the transitions leaving it."""

from __future__ import annotations

from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st
from lad_strategies import elements, networks

from nasaq.lang.graph.model import (
    Action,
    GraphBlock,
    Sequencer,
    Settings,
    Step,
    Transition,
)
from nasaq.lang.graph.text import number_block, parse_graph, print_graph
from nasaq.lang.lad.model import Box, Contact, Network, Output, Parallel, Series

FIXTURES = Path(__file__).parent / "fixtures" / "ok"
COURSE = Path(__file__).parents[3] / "scenarios" / "graph"  # tests/scenarios/graph: G1-G20


def round_trip(blocks: list[GraphBlock]) -> list[GraphBlock]:
    parsed = parse_graph(print_graph(blocks), "round.graph")
    assert parsed.diagnostics == []
    return parsed.blocks


# ---- a model with every part ------------------------------------------------------------------

ROWS = [
    Action(qualifier="N", operand="Q 0.0"),
    Action(qualifier="S", operand='"Belt_A"', comment="starts belt A"),
    Action(qualifier="R", operand="#done", interlock=True),
    Action(event="S1", qualifier="N", operand="DB5.DBX 2.1", interlock=True),
    Action(qualifier="D", operand="Q 0.1", time="T#5S"),
    Action(qualifier="L", operand="M 1.0", time="#wait", interlock=True),
    Action(qualifier="CALL", operand="FB 2, DB 2"),
    Action(event="S0", qualifier="CALL", operand='"Motor"', interlock=True),
    Action(qualifier="ON", operand="S3"),
    Action(event="V1", qualifier="OFF", operand="S_ALL"),
    Action(event="L1", qualifier="ON", operand="Fill"),
    Action(qualifier="CS", operand="C 1", time="C#26"),
    Action(event="A1", qualifier="CU", operand="C 1"),
    Action(event="R1", qualifier="CD", operand="C 1", interlock=True),
    Action(event="V0", qualifier="CR", operand="C 2"),
    Action(qualifier="TL", operand="T 0", time="S5T#8S"),
    Action(event="L0", qualifier="TD", operand="T 1", time="MW 4", interlock=True),
    Action(qualifier="TR", operand="T 1"),
    Action(event="S1", qualifier="N", operand="#count := #count + 1", id="count_up"),
    Action(qualifier="N", operand='#E := SIN(MD 0) * "Gain"', interlock=True),
]


def every_part_block() -> GraphBlock:
    compare = Box(name="CMP>D", inputs={"IN1": "Fill.T", "IN2": "T#10S"})
    either = Parallel(
        branches=[
            Series(elements=[Contact(operand='"Start"')]),
            Series(elements=[Contact(operand="S3.X", negated=True, id="held")]),
        ]
    )
    fill = Step(
        number=2,
        name="Fill",
        comment="fills the tank\nuntil the level is reached",
        interlock=Series(elements=[Contact(operand="I 0.5"), either]),
        supervision=Series(elements=[compare]),
        actions=ROWS,
    )
    first = Sequencer(
        name="Tank",
        comment="the tank",
        steps=[
            Step(number=1, name="Idle", initial=True),
            fill,
            Step(number=3, name="Mix", interlock=Series()),
            Step(number=4, name="Drain"),
            Step(number=5, name="Lamp"),
        ],
        transitions=[
            Transition(number=1, name="T_start", source=["Idle"], target=["Fill"]),
            Transition(
                number=2,
                name="T_full",
                source=["Fill"],
                target=["Mix", "Lamp"],
                condition=Series(elements=[Contact(operand='"Full"')]),
                comment="both at once",
            ),
            Transition(
                number=3,
                name="T_done",
                source=["Mix", "Lamp"],
                target=["Drain"],
                condition=Series(),
            ),
            Transition(number=4, name="T_back", source=["Drain"], target=["Idle"], jump=True),
        ],
    )
    second = Sequencer(
        name="Alarm",
        steps=[Step(number=10, name="Quiet", initial=True), Step(number=11, name="Ring")],
        transitions=[
            Transition(number=10, name="T_ring", source=["Quiet"], target=["Ring"]),
            Transition(number=11, name="T_end", source=["Ring"], target=[]),
        ],
    )
    rung = Network(
        title="Emergency",
        logic=Series(elements=[Contact(operand='"Emergency"')]),
        outputs=[Output(target=Box(name="MOVE", inputs={"IN": "0"}, outputs={"OUT": "MW 2"}))],
    )
    return GraphBlock(
        name="FB 7",
        title="A tank",
        comment="first line\nsecond line",
        settings=Settings(
            parameters="USER_DEFINED",
            skip_steps=True,
            acknowledge_required=False,
            interlock_blocks=True,
        ),
        declarations="VAR\n  count : INT;\n  wait : TIME := T#2S;\nEND_VAR",
        pre=[rung],
        sequencers=[first, second],
        post=[rung.model_copy(update={"title": ""})],
    )


def test_every_part_survives_print_and_parse() -> None:
    block = number_block(every_part_block())
    assert round_trip([block]) == [block]


def test_numbering_gives_actions_and_condition_elements_their_reading_ids() -> None:
    [block] = round_trip([every_part_block()])
    fill = block.sequencers[0].steps[1]
    assert [row.id for row in fill.actions][:3] == ["a1", "a2", "a3"]
    assert fill.actions[18].id == "count_up"
    assert fill.interlock is not None
    contact, either = fill.interlock.elements
    assert (contact.id, either.id) == ("e1", "e2")
    assert isinstance(either, Parallel)
    assert [branch.elements[0].id for branch in either.branches] == ["e3", "held"]


def test_the_printer_leaves_out_default_settings_and_generated_ids() -> None:
    block = number_block(every_part_block())
    text = print_graph([block])
    assert "@a1" not in text
    assert "@count_up;" in text
    assert "@held" in text
    assert "SETTINGS" in text
    plain = block.model_copy(update={"settings": Settings()})
    assert "SETTINGS" not in print_graph([plain])


def test_every_fixture_and_course_source_prints_canonically_and_reads_back() -> None:
    paths = sorted(FIXTURES.glob("*.graph")) + sorted(COURSE.glob("*.graph"))
    assert len(paths) >= 3 + 20
    for path in paths:
        parsed = parse_graph(path.read_text("utf-8"), path.name)
        assert parsed.diagnostics == [], path.name
        printed = print_graph(parsed.blocks)
        again = parse_graph(printed, path.name)
        assert again.diagnostics == []
        assert again.blocks == parsed.blocks, path.name
        assert print_graph(again.blocks) == printed


def test_each_step_is_followed_by_the_transitions_leaving_it() -> None:
    steps = [Step(number=n, name=f"S_{n}") for n in (1, 2, 3)]
    transitions = [
        Transition(number=1, name="A", source=["S_1"], target=["S_2"]),
        Transition(number=2, name="B", source=["S_1"], target=["S_3"]),
        Transition(number=3, name="C", source=["S_2"], target=["S_1"]),
        Transition(number=4, name="D", source=["S_3"], target=["S_1"]),
    ]
    block = GraphBlock(
        name="FB 1", sequencers=[Sequencer(name="Q", steps=steps, transitions=transitions)]
    )
    heads = [
        line.split(" (")[0]
        for line in print_graph([block]).splitlines()
        if line.startswith(("STEP", "TRANSITION"))
    ]
    assert heads == [
        "STEP S_1",
        "TRANSITION A",
        "TRANSITION B",
        "STEP S_2",
        "TRANSITION C",
        "STEP S_3",
        "TRANSITION D",
    ]


def test_transitions_out_of_chart_order_keep_their_priority_order() -> None:
    """The model's transition order is the evaluation order (priority): the printer never
    reorders transitions, it only chooses where to put them between the steps."""
    steps = [Step(number=n, name=f"S_{n}") for n in (1, 2, 3)]
    transitions = [
        Transition(number=1, name="Late", source=["S_2", "S_1"], target=["S_3"]),
        Transition(number=2, name="Early", source=["S_1"], target=["S_2"]),
        Transition(number=3, name="Lost", source=["Nowhere"], target=["S_1"]),
    ]
    block = GraphBlock(
        name="FB 1", sequencers=[Sequencer(name="Q", steps=steps, transitions=transitions)]
    )
    assert round_trip([block]) == [block]


# ---- random models ----------------------------------------------------------------------------

OPERANDS = ["Q 0.0", '"Belt_A"', "#x", "DB5.DBX 2.1", "M 10.1", "S3", "S_ALL", "C 1", "T 0"]
TIMES = ["T#5S", "S5T#8S", "C#26", "MW 2", "#t"]
COMMENTS = ["", "a comment", 'with "quotes", commas; and // slashes']
EVENT_CHOICES = [None, "S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1"]
QUALIFIER_CHOICES = ["N", "S", "R", "D", "L", "ON", "OFF", "CS", "CU", "CD", "CR", "TL", "TD"]


@st.composite
def actions(draw: st.DrawFn) -> Action:
    """Any row the format can hold: a CALL or an assignment carries no time after a comma (its
    operand may hold commas itself)."""
    kind = draw(st.sampled_from(["plain", "call", "assignment"]))
    event = draw(st.sampled_from(EVENT_CHOICES))
    interlock = draw(st.booleans())
    comment = draw(st.sampled_from(COMMENTS))
    if kind == "call":
        operand = draw(st.sampled_from(["FC 1", "FB 2, DB 2", '"Motor"']))
        return Action(
            event=event, qualifier="CALL", interlock=interlock, operand=operand, comment=comment
        )
    if kind == "assignment":
        operand = draw(st.sampled_from(["#a := #a + 1", '#e := SIN(MD 0) * "k"', "MW 2 := 0"]))
        return Action(event=event, qualifier="N", interlock=interlock, operand=operand)
    return Action(
        event=event,
        qualifier=draw(st.sampled_from(QUALIFIER_CHOICES)),
        interlock=interlock,
        operand=draw(st.sampled_from(OPERANDS)),
        time=draw(st.one_of(st.none(), st.sampled_from(TIMES))),
        comment=comment,
    )


# Built once: a strategy built anew for every draw makes Hypothesis slow.
CONDITIONS = st.one_of(
    st.none(),
    st.just(Series()),
    st.lists(elements(), min_size=1, max_size=2).map(lambda found: Series(elements=found)),
)
ACTIONS = actions()
NETWORKS = st.lists(networks(), max_size=1)


@st.composite
def sequencers(draw: st.DrawFn, prefix: str, first: int) -> Sequencer:
    count = draw(st.integers(1, 4))
    names = [f"{prefix}{n}" for n in range(count)]
    steps = [
        Step(
            number=first + n,
            name=names[n],
            initial=draw(st.booleans()),
            comment=draw(st.sampled_from(["", "one", "two\nlines"])),
            interlock=draw(CONDITIONS),
            supervision=draw(CONDITIONS),
            actions=draw(st.lists(ACTIONS, max_size=3)),
        )
        for n in range(count)
    ]
    links = st.lists(st.sampled_from(names), min_size=1, max_size=2, unique=True)
    transitions = []
    for n in range(draw(st.integers(0, 4))):
        target = draw(st.one_of(st.just([]), links))
        transitions.append(
            Transition(
                number=first + n,
                name=f"T{prefix}{n}",
                source=draw(links),
                target=target,
                jump=bool(target) and draw(st.booleans()),
                condition=draw(CONDITIONS),
                comment=draw(st.sampled_from(["", "why"])),
            )
        )
    return Sequencer(name=f"Seq{prefix}", steps=steps, transitions=transitions)


@st.composite
def blocks(draw: st.DrawFn) -> GraphBlock:
    return GraphBlock(
        name=draw(st.sampled_from(["FB 1", '"Drill"'])),
        title=draw(st.sampled_from(["", "A title"])),
        settings=Settings(
            parameters=draw(st.sampled_from(["MINIMUM", "STANDARD", "MAXIMUM", "USER_DEFINED"])),
            skip_steps=draw(st.booleans()),
        ),
        declarations=draw(st.sampled_from(["", "VAR\n  x : INT;\nEND_VAR"])),
        pre=draw(NETWORKS),
        sequencers=[draw(sequencers("A", 1)), *draw(st.lists(sequencers("B", 50), max_size=1))],
        post=draw(NETWORKS),
    )


@settings(max_examples=15, deadline=None)
@given(st.lists(blocks(), min_size=1, max_size=2))
def test_random_models_survive_print_and_parse(drawn: list[GraphBlock]) -> None:
    numbered = [number_block(block) for block in drawn]
    assert round_trip(numbered) == numbered
    assert print_graph(round_trip(numbered)) == print_graph(numbered)
