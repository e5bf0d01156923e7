"""SEMANTICS §2 phase 5, the arithmetic action ``N A := B op C``: executed in every call while
the step is active, or once at its event (``S1 N #count := #count + 1`` counts activations),
on the FB's own variables and on global words alike."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, chain, make

VARS = "VAR\n  count : INT;\n  left : INT;\nEND_VAR"


@pytest.mark.parametrize("kind", KINDS)
def test_an_event_assignment_counts_activations(kind: str) -> None:
    ex = make(kind, chain("S1 N #count := #count + 1", declarations=VARS))
    ex.call()
    for _ in range(3):
        ex.call({"I 0.0": 1, "I 0.1": 0})
        ex.call({"I 0.0": 0})
        ex.call({"I 0.1": 1})
    assert ex.var("count") == 3


@pytest.mark.parametrize("kind", KINDS)
def test_a_plain_assignment_runs_every_call_while_active(kind: str) -> None:
    ex = make(kind, chain("N MW 10 := MW 10 + 2"))
    ex.call()
    ex.call({"I 0.0": 1})
    ex.call()
    ex.call()
    assert ex.word("MW 10") == 6
    ex.call({"I 0.0": 0, "I 0.1": 1})  # left: the assignment does not run
    ex.call()
    assert ex.word("MW 10") == 6


@pytest.mark.parametrize("kind", KINDS)
def test_assignments_subtract_multiply_and_copy(kind: str) -> None:
    actions = (
        "S1 N MW 12 := MW 14 * 3",
        "S1 N MW 16 := MW 14 - 10",
        "S0 N #left := MW 14",
    )
    ex = make(kind, chain(*actions, declarations=VARS))
    ex.call({"MW 14": 7})
    ex.call({"I 0.0": 1})
    assert (ex.word("MW 12"), ex.word("MW 16")) == (21, -3)
    ex.call({"I 0.0": 0, "I 0.1": 1, "MW 14": 5})
    assert ex.var("left") == 5
