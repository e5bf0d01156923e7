"""grammars/graph.lark is the reference of the .graph format: every alternative of its rules and
every terminal of its own is exercised by a valid example (and every LAD rule it imports is used
at least once), it reads every valid example the recursive-descent reader reads, to the same
structure, and it rejects the syntax errors the reader reports."""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest
from grammar_coverage import Recorder, describe
from lark import Lark, Token, Tree
from lark.exceptions import LarkError

from nasaq.lang.graph.model import GraphBlock
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.graph.text_words import QUALIFIERS

GRAMMAR = Path(__file__).resolve().parents[4] / "grammars" / "graph.lark"
FIXTURES = Path(__file__).parent / "fixtures" / "ok"

# Every alternative of the format's own rules: both block-name forms, all settings, both step
# kinds, every part of a step and a transition, each form of an action row and of a link, and
# permanent networks that use every LAD rule (each final element, OUTPUTS, boxes with every
# kind of pin, parallels, an STL network, network titles, comments and labels).
COVERAGE = """\
FUNCTION_BLOCK FB 3
TITLE = coverage
COMMENT = one
SETTINGS
  PARAMETERS := USER_DEFINED;
  SKIP_STEPS := TRUE;
  ACKNOWLEDGE := FALSE;
  INTERLOCK_BLOCKS := TRUE;
END_SETTINGS
VAR
  n : INT;
END_VAR
BEGIN
PERMANENT_PRE
NETWORK
TITLE = every element
COMMENT = and a label
LABEL P001
RUNG
  Contact(I 0.0) ContactNC(I 0.1) Status(OV) StatusNC(BR) Not Edge(P, M 1.0) Midline(M 2.0)
  PARALLEL BRANCH Contact(I 0.2) END_BRANCH BRANCH END_BRANCH END_PARALLEL
  Box(FB 5, INSTANCE DB 5, EN_RUN := RUNG Contact(I 0.3) END_RUNG, SPEED := MW 4, DONE => #d)
  OUTPUTS
    BRANCH Coil(Q 0.0) END_BRANCH
    BRANCH Contact(I 0.4) @c SetCoil(Q 0.1) END_BRANCH
    BRANCH ResetCoil(Q 0.2) END_BRANCH
    BRANCH SD(T 1, S5T#2S) END_BRANCH
    BRANCH SC(C 1, C#10) END_BRANCH
    BRANCH Save END_BRANCH
    BRANCH Jump(P001) END_BRANCH
    BRANCH JumpN(P001) END_BRANCH
    BRANCH Return END_BRANCH
    BRANCH Open(DB 10) END_BRANCH
    BRANCH Box(SR, S := I 0.0, R := I 0.1) END_BRANCH
  END_OUTPUTS
END_RUNG
NETWORK
RUNG Contact(I 1.0) Coil(Q 1.0) END_RUNG
NETWORK
TITLE = an STL network
STL REASON LAD305
      L     MW 10
      T     MW 12
END_STL
END_PERMANENT_PRE
SEQUENCER Main
COMMENT = the sequencer
INITIAL_STEP Idle (1)
COMMENT = a step
INTERLOCK Contact(I 0.5) END_INTERLOCK
SUPERVISION Box(CMP>D, IN1 := Idle.T, IN2 := T#10S) END_SUPERVISION
ACTIONS
  N Q 0.0;
  S1 NC Q 0.1;
  N C Q 0.2 @fast;
  D Q 0.3, T#5S;
  S1 N #n := #n + 1;
  CALL FB 2, DB 2;
  S0 CS C 1, C#3 @preset;
  V1 RC Q 0.4 @off;
  N #n := 0 @zero;
  L1 N C #n := #n - 1 @down;
END_ACTIONS
END_STEP
STEP Empty_parts (4)
INTERLOCK END_INTERLOCK
SUPERVISION END_SUPERVISION
ACTIONS END_ACTIONS
END_STEP
TRANSITION Go (1) FROM Idle TO (Work, Lamp)
COMMENT = a transition
CONDITION Contact(I 0.6) END_CONDITION
END_TRANSITION
STEP Work (2) END_STEP
STEP Lamp (3) END_STEP
TRANSITION Back (2) FROM (Work, Lamp) JUMP Idle
END_TRANSITION
TRANSITION Out (3) FROM Lamp STOP
CONDITION END_CONDITION
END_TRANSITION
TRANSITION One (4) FROM Work TO (Lamp)
END_TRANSITION
END_SEQUENCER
SEQUENCER Second
END_SEQUENCER
PERMANENT_POST
END_PERMANENT_POST
END_FUNCTION_BLOCK

FUNCTION_BLOCK "Plain"
BEGIN
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB 4
SETTINGS
END_SETTINGS
BEGIN
PERMANENT_PRE
END_PERMANENT_PRE
SEQUENCER Only_comment
COMMENT = nothing else
END_SEQUENCER
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB 5
VAR_TEMP
  t : INT;
END_VAR
BEGIN
PERMANENT_PRE
END_PERMANENT_PRE
PERMANENT_POST
NETWORK
STL
      NOP   0
END_STL
END_PERMANENT_POST
END_FUNCTION_BLOCK
"""


@cache
def reference() -> Lark:
    return Lark.open(str(GRAMMAR), parser="lalr", lexer="contextual")


def valid_texts() -> list[str]:
    return ["", COVERAGE, *(path.read_text("utf-8") for path in sorted(FIXTURES.glob("*.graph")))]


def _read(name: str, text: str, lark: Lark) -> SimpleNamespace:
    lark.parse(text)
    return SimpleNamespace(diagnostics=[])


def test_every_alternative_and_terminal_of_the_grammar_is_exercised() -> None:
    recorder = Recorder(Lark.open(str(GRAMMAR), parser="lalr", lexer="contextual"), _read)
    for number, text in enumerate(valid_texts()):
        assert recorder.parse(f"valid{number}.graph", text) == []
    own = {shape for shape in recorder.missing_alternatives() if "lad__" not in shape[0]}
    assert not own, "grammar alternatives never exercised:\n" + describe(own)
    never = {name for name in recorder.missing_terminals() if not name.startswith("LAD__")}
    assert not never, f"terminals never shifted: {sorted(never)}"
    imported = {str(rule.origin.name) for rule in recorder.lark.rules}
    used = {str(rule.origin.name) for rule in recorder.rules}
    unused = {name for name in imported - used if name.startswith("lad__")}
    assert not unused, f"LAD rules never used: {sorted(unused)}"


# ---- both readers agree ---------------------------------------------------------------------


def _tokens(tree: Tree[Any], kind: str) -> list[str]:
    return [
        str(child) for child in tree.children if isinstance(child, Token) and child.type == kind
    ]


def _subtrees(tree: Tree[Any], name: str) -> list[Tree[Any]]:
    return [child for child in tree.children if isinstance(child, Tree) and child.data == name]


def _squeeze(text: str) -> str:
    return re.sub(r"\s+", "", text)


def _row(tree: Tree[Any]) -> tuple[Any, ...]:
    operands = [
        str(child)
        for child in tree.children
        if isinstance(child, Token) and child.type in ("ASSIGNMENT", "ACTION_OPERAND")
    ]
    written = _tokens(tree, "QUALIFIER")[0].upper()
    glued = written not in QUALIFIERS  # NC, CSC, TDC ...: the C suffix written onto it
    base = written[:-1] if glued else written
    interlock = glued or bool(_tokens(tree, "C_SUFFIX"))
    if base == "CALL":
        operand, time = ", ".join(o.strip() for o in operands), None
    else:
        operand, time = operands[0], (operands[1] if len(operands) > 1 else None)
    events = [event.upper() for event in _tokens(tree, "EVENT")]
    ids = [given[1:] for given in _tokens(tree, "ACTION_ID")]
    return (
        events[0] if events else None,
        base,
        interlock,
        _squeeze(operand),
        None if time is None else time.strip(),
        ids[0] if ids else None,
    )


def _steps(tree: Tree[Any]) -> list[str]:
    return _tokens(tree, "NAME")


def tree_summary(tree: Tree[Any]) -> list[Any]:
    blocks = []
    for block in tree.find_data("block"):
        sequencers = []
        for sequencer in block.find_data("sequencer"):
            steps = []
            for step in _subtrees(sequencer, "step"):
                rows = [
                    _row(row)
                    for actions in _subtrees(step, "actions")
                    for row in _subtrees(actions, "action")
                ]
                parts = {
                    part.data: len(part.children) - 2
                    for part in step.children
                    if isinstance(part, Tree) and part.data in ("interlock", "supervision")
                }
                steps.append(
                    (
                        _tokens(step, "NAME")[0],
                        int(_tokens(step, "NUMBER")[0]),
                        bool(_tokens(step, "INITIAL_STEP")),
                        rows,
                        parts,
                    )
                )
            transitions = []
            for link in _subtrees(sequencer, "transition"):
                [source] = _subtrees(link, "steps")
                goes = _subtrees(link, "goes_to") + _subtrees(link, "jumps_to")
                target = _steps(_subtrees(goes[0], "steps")[0]) if goes else []
                conditions = [len(c.children) - 2 for c in _subtrees(link, "condition")]
                transitions.append(
                    (
                        _tokens(link, "NAME")[0],
                        int(_tokens(link, "NUMBER")[0]),
                        _steps(source),
                        target,
                        bool(_subtrees(link, "jumps_to")),
                        conditions[0] if conditions else None,
                    )
                )
            sequencers.append((_tokens(sequencer, "NAME")[0], steps, transitions))
        pre = [len(_subtrees(p, "network")) for p in _subtrees(block, "permanent_pre")]
        post = [len(_subtrees(p, "network")) for p in _subtrees(block, "permanent_post")]
        blocks.append((_tokens(block, "FB_NAME")[0], sequencers, sum(pre), sum(post)))
    return blocks


def model_summary(blocks: list[GraphBlock]) -> list[Any]:
    def row_summary(number: int, action: Any) -> tuple[Any, ...]:
        given = None if action.id == f"a{number}" else action.id
        return (
            action.event,
            action.qualifier,
            action.interlock,
            _squeeze(action.operand),
            action.time,
            given,
        )

    summary = []
    for block in blocks:
        sequencers = []
        for sequencer in block.sequencers:
            steps = []
            for step in sequencer.steps:
                rows = [row_summary(n, a) for n, a in enumerate(step.actions, start=1)]
                parts = {
                    name: len(part.elements)
                    for name, part in (
                        ("interlock", step.interlock),
                        ("supervision", step.supervision),
                    )
                    if part is not None
                }
                steps.append((step.name, step.number, step.initial, rows, parts))
            transitions = [
                (
                    t.name,
                    t.number,
                    t.source,
                    t.target,
                    t.jump,
                    None if t.condition is None else len(t.condition.elements),
                )
                for t in sequencer.transitions
            ]
            sequencers.append((sequencer.name, steps, transitions))
        summary.append((block.name, sequencers, len(block.pre), len(block.post)))
    return summary


@pytest.mark.parametrize("number", range(len(valid_texts())))
def test_the_grammar_and_the_reader_read_every_valid_example_alike(number: int) -> None:
    text = valid_texts()[number]
    parsed = parse_graph(text, "valid.graph")
    assert parsed.diagnostics == []
    assert tree_summary(reference().parse(text)) == model_summary(parsed.blocks)


# ---- both reject the same syntax errors -----------------------------------------------------

STEP = "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER Main\n{}\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n"
SYNTAX_ERRORS = [
    STEP.format("STEP A (1) ACTIONS X Q 1.0; END_ACTIONS END_STEP"),
    STEP.format("STEP A (1) ACTIONS N Q 1.0 END_ACTIONS END_STEP"),
    STEP.format("STEP A (1) ACTIONS N ; END_ACTIONS END_STEP"),
    STEP.format("STEP A (1) ACTIONS D Q 1.0, T#1S, x; END_ACTIONS END_STEP"),
    STEP.format("STEP A (1) ACTIONS D Q 1.0, ; END_ACTIONS END_STEP"),
    STEP.format("STEP A (1) ACTIONS N Q 1.0 @; END_ACTIONS END_STEP"),
    STEP.format("STEP A ACTIONS N Q 1.0; END_ACTIONS END_STEP"),
    STEP.format("STEP (1) END_STEP"),
    STEP.format("STEP A (1) FOO END_STEP"),
    STEP.format("STEP A (1) ACTIONS N Q 1.0;"),
    STEP.format("TRANSITION T (1) A TO B END_TRANSITION"),
    STEP.format("TRANSITION T (1) FROM A B END_TRANSITION"),
    STEP.format("TRANSITION T (1) FROM (A B) TO B END_TRANSITION"),
    STEP.format("TRANSITION T (1) FROM () TO B END_TRANSITION"),
    STEP.format("TRANSITION T (1) FROM A TO B CONDITION Contact(I 0.0) Coil(Q 0.0) "
                "END_CONDITION END_TRANSITION"),
    STEP.format("TRANSITION T (1) FROM A TO B CONDITION Contact(I 0.0) END_TRANSITION"),
    STEP.format("hello"),
    "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER A\nEND_SEQUENCER\nPERMANENT_PRE\nEND_PERMANENT_PRE\n"
    "END_FUNCTION_BLOCK\n",
    "FUNCTION_BLOCK FC 1\nBEGIN\nEND_FUNCTION_BLOCK\n",
    "FUNCTION_BLOCK FB 1\nSETTINGS\n  PARAMETERS := LARGE;\nEND_SETTINGS\nBEGIN\n"
    "END_FUNCTION_BLOCK\n",
    "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER A\nEND_SEQUENCER\n",
]  # fmt: skip


@pytest.mark.parametrize("text", SYNTAX_ERRORS)
def test_the_grammar_rejects_what_the_reader_reports(text: str) -> None:
    assert parse_graph(text, "bad.graph").diagnostics
    with pytest.raises(LarkError):
        reference().parse(text)
