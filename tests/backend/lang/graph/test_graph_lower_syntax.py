"""The syntax tree the lowering builds for its STL (``lower_syntax``, without the STL parser)
is the tree the STL parser makes of the same text: same items, operands, values and lines."""

from __future__ import annotations

from dataclasses import fields, is_dataclass
from typing import Any

import pytest
from graph_lower_support import SCENARIOS

from nasaq.lang.graph.compile import lower_file
from nasaq.lang.stl import ast
from nasaq.lang.stl.parse import parse_source

EXAMPLES = sorted(SCENARIOS.glob("*.graph"))


def shape(node: Any) -> Any:
    """A node without columns: what it is, its contents and, for a statement, its line."""
    if isinstance(node, list):
        return [shape(item) for item in node]
    if is_dataclass(node) and not isinstance(node, type):
        parts: list[Any] = [type(node).__name__]
        for item in fields(node):
            value = getattr(node, item.name)
            if item.name == "loc":
                if isinstance(node, ast.InstrNode | ast.LabelNode | ast.NetworkNode):
                    parts.append(value.line)
                continue
            if item.name == "end":
                continue
            parts.append((item.name, shape(value)))
        return tuple(parts)
    return node


def test_there_are_examples() -> None:
    assert len(EXAMPLES) >= 15


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_the_tree_is_the_parsers(path: Any) -> None:
    lowered = lower_file(path.name, path.read_text(encoding="utf-8"))
    assert lowered.parsed is not None
    if not lowered.stl:  # an example of a mistake: nothing to compile
        assert any(d.severity == "error" for d in lowered.diagnostics)
        return
    parsed = parse_source(path.name, lowered.stl)
    assert not parsed.diagnostics
    assert not lowered.parsed.diagnostics
    ours, theirs = lowered.parsed.source.blocks, parsed.source.blocks
    assert len(ours) == len(theirs) >= 1
    for mine, reference in zip(ours, theirs, strict=True):
        assert shape(mine.code) == shape(reference.code)
        assert shape(mine.head) == shape(reference.head)
        assert (mine.keyword, mine.ident, mine.ident_quoted) == (
            reference.keyword,
            reference.ident,
            reference.ident_quoted,
        )


TWO_BLOCKS = """FUNCTION_BLOCK "Press"
TITLE = first
VAR_TEMP
  scratch : INT;
END_VAR
BEGIN
PERMANENT_PRE
NETWORK
TITLE = lamp
RUNG Contact(I 2.1)
  PARALLEL BRANCH Contact(M 0.1) END_BRANCH BRANCH ContactNC(DB1.DBX 0.1) END_BRANCH END_PARALLEL
  Coil(Q 2.1)
END_RUNG
END_PERMANENT_PRE
SEQUENCER One
INITIAL_STEP Start (1)
ACTIONS
  CALL FC 3;
  S1 CALL FB 2, DB 2;
  CALL "Motor";
  N #scratch := 5;
END_ACTIONS
END_STEP
TRANSITION T1 (1) FROM Start TO Start
CONDITION Contact(Start.X) Contact(MW1.V1) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB 7
BEGIN
SEQUENCER Two
INITIAL_STEP A (1)
INTERLOCK Contact(I 0.0) END_INTERLOCK
SUPERVISION Box(CMP>D, IN1 := A.T, IN2 := T#5S) END_SUPERVISION
ACTIONS
  L1 N M 1.0;
END_ACTIONS
END_STEP
TRANSITION Go (1) FROM A STOP
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""


def test_two_blocks_calls_and_user_temporaries() -> None:
    lowered = lower_file("two.graph", TWO_BLOCKS)
    assert lowered.parsed is not None
    assert not [d for d in lowered.diagnostics if d.severity == "error"], lowered.diagnostics
    parsed = parse_source("two.graph", lowered.stl)
    assert not parsed.diagnostics
    ours, theirs = lowered.parsed.source.blocks, parsed.source.blocks
    assert [b.ident for b in ours] == ["Press", "FB 7"]
    assert shape(ours) == shape(theirs)
