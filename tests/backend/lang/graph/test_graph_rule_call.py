"""SEMANTICS §2 phase 5, CALL: a block called in every call while the step is active, or once
at an event (``S0 CALL`` when the step is left)."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, chain, make
from graph_reference import Call, Memory

FCS = """\
FUNCTION FC 1 : VOID
BEGIN
NETWORK
TITLE = counts its calls in MW 20
      L     MW 20
      L     1
      +I
      T     MW 20
END_FUNCTION

FUNCTION FC 2 : VOID
BEGIN
NETWORK
TITLE = counts its calls in MW 22
      L     MW 22
      L     1
      +I
      T     MW 22
END_FUNCTION
"""


def _count(word: str) -> Call:
    def run(memory: Memory) -> None:
        memory.put(word, memory.get(word) + 1)

    return run


CALLS = {"FC 1": _count("MW 20"), "FC 2": _count("MW 22")}


@pytest.mark.parametrize("kind", KINDS)
def test_call_runs_every_call_while_active_and_s0_call_once(kind: str) -> None:
    ex = make(kind, chain("CALL FC 1", "S0 CALL FC 2"), calls=CALLS, extra=FCS)
    ex.call()
    ex.call({"I 0.0": 1})
    ex.call()
    ex.call()
    assert (ex.word("MW 20"), ex.word("MW 22")) == (3, 0)
    ex.call({"I 0.0": 0, "I 0.1": 1})
    ex.call()
    assert (ex.word("MW 20"), ex.word("MW 22")) == (3, 1)
