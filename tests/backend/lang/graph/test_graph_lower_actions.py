"""Action rows the lowering writes: the instruction an arithmetic row gets from its types, and
the GRA3xx problems of rows it cannot lower (reported on the row, the rest of the FB lowered)."""

from __future__ import annotations

import pytest

from nasaq.lang.graph.lower import lower_block
from nasaq.lang.graph.model import Action, GraphBlock, Sequencer, Step
from nasaq.lang.graph.source import ParsedGraph

DECLARATIONS = """VAR
  count : INT;
  total : DINT;
  wait : TIME;
  level : REAL;
  mask : WORD;
END_VAR"""


def lowered(*actions: Action) -> tuple[list[list[str]], list[str]]:
    """The instruction lines (words, labels dropped) of the rows of step S2 (element S2/A<k>)
    and the codes of the problems."""
    steps = [Step(number=1, name="Idle", initial=True), Step(number=2, name="Work")]
    steps[1] = steps[1].model_copy(update={"actions": list(actions)})
    block = GraphBlock(
        name="FB 1",
        declarations=DECLARATIONS,
        sequencers=[Sequencer(name="Main", steps=steps)],
    )
    parsed = ParsedGraph("seq.graph", [block], [], [{"BLOCK": 1, "S2": 9, "S2/A1": 10}])
    result = lower_block(block, parsed, 0)
    lines = result.text.split("\n")
    rows = [
        [w for w in line.split() if not w.endswith(":")]
        for line, element in zip(lines, result.elements, strict=False)
        if element is not None and element.startswith("S2/A")
    ]
    for problem in result.diagnostics:
        assert problem.span is not None
        assert problem.span.file == "seq.graph"
    return rows, [d.code for d in result.diagnostics]


def arithmetic(text: str) -> list[list[str]]:
    rows, problems = lowered(Action(qualifier="N", operand=text))
    assert not problems
    return rows


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("count := count + 1", [["L", "#count"], ["L", "1"], ["+I"], ["T", "#count"]]),
        (
            "#total := #total - 1",
            [["L", "#total"], ["L", "L#1"], ["-D"], ["T", "#total"]],
        ),
        ("wait := Work.T", [["L", "#Work.T"], ["T", "#wait"]]),
        ("#level := SIN(MD 0)", [["L", "MD", "0"], ["SIN"], ["T", "#level"]]),
        (
            "level := level * 2",
            [["L", "#level"], ["L", "2.0"], ["*R"], ["T", "#level"]],
        ),
        (
            "mask := MW 0 AND W#16#FFF0",
            [["L", "MW", "0"], ["L", "W#16#FFF0"], ["AW"], ["T", "#mask"]],
        ),
        ("mask := mask SHL 2", [["L", "2"], ["L", "#mask"], ["SLW"], ["T", "#mask"]]),
        ("total := INT_TO_DINT(count)", [["L", "#count"], ["ITD"], ["T", "#total"]]),
        (
            "MD 4 := MD 4 MOD L#7",
            [["L", "MD", "4"], ["L", "L#7"], ["MOD"], ["T", "MD", "4"]],
        ),
    ],
)
def test_the_type_picks_the_instruction(text: str, expected: list[list[str]]) -> None:
    assert arithmetic(text) == expected


@pytest.mark.parametrize(
    ("action", "code"),
    [
        (Action(qualifier="N", operand="count := FOO(count)"), "GRA302"),
        (Action(qualifier="N", operand='"Sym" := "Other" + 1'), "GRA303"),
        (Action(qualifier="N", operand="level := level AND 3"), "GRA304"),
        (Action(qualifier="D", operand="Q 0.0"), "GRA305"),
        (Action(event="S1", qualifier="CS", operand="C 1"), "GRA305"),
        (Action(event="S1", qualifier="ON", operand="S9"), "GRA306"),
        (Action(event="S1", qualifier="CU", operand="MW 2"), "GRA307"),
        (Action(event="S1", qualifier="TL", operand="Q 1.0", time="S5T#2S"), "GRA307"),
    ],
)
def test_rows_that_cannot_be_lowered(action: Action, code: str) -> None:
    rows, problems = lowered(Action(qualifier="N", operand="Q 4.0"), action)
    assert problems == [code]
    assert ["=", "Q", "4.0"] in rows  # the other rows are still there


def test_a_timer_and_a_counter_get_a_rising_rlo_once() -> None:
    rows, problems = lowered(
        Action(event="S1", qualifier="TL", operand="T 3", time="S5T#8S"),
        Action(event="S1", qualifier="CS", operand="C 2", time="C#26"),
        Action(event="S1", qualifier="CU", operand="C 2"),
    )
    assert not problems
    body = [row for row in rows if row[0] not in ("A", "JCN")]
    assert body == [
        ["CLR"], ["SE", "T", "3"], ["SET"], ["L", "S5T#8S"], ["SE", "T", "3"],
        ["CLR"], ["S", "C", "2"], ["SET"], ["L", "C#26"], ["S", "C", "2"],
        ["CLR"], ["CU", "C", "2"], ["SET"], ["CU", "C", "2"],
    ]  # fmt: skip
