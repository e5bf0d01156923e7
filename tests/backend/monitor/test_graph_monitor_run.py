"""A real ``.graph`` FB in a session: its block status says language ``graph`` and reports the
chart (steps active/inactive/disturbed with their times, each transition's TT) scan by scan, and
the Control Sequencer's commands drive the compiled sequencer: MAN, a step switched on and off by
hand, TAP with T_PUSH, acknowledging a supervision error, INIT and OFF."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from graph_session import Cpu

from nasaq.lang.stl import SourceFile
from nasaq.monitor.protocol import GraphStatus

MIXER = """\
FUNCTION_BLOCK FB 1
TITLE = Mixer
BEGIN
SEQUENCER Mixer
INITIAL_STEP Idle (1)
END_STEP

TRANSITION Go (1) FROM Idle TO Fill
CONDITION Contact(I 0.0) END_CONDITION
END_TRANSITION

STEP Fill (2)
INTERLOCK Contact(I 0.5) END_INTERLOCK
SUPERVISION Contact(I 0.6) END_SUPERVISION
ACTIONS
  N Q 4.0;
END_ACTIONS
END_STEP

TRANSITION Full (2) FROM Fill TO Mix
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION

STEP Mix (3)
ACTIONS
  N Q 4.1;
END_ACTIONS
END_STEP

TRANSITION Done (3) FROM Mix JUMP Idle
CONDITION Contact(I 0.2) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""
OB1 = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE =
      CALL FB 1 , DB 1;
END_ORGANIZATION_BLOCK

DATA_BLOCK DB 1
FB 1
BEGIN
END_DATA_BLOCK
"""


class Mixer(Cpu):
    def __init__(self) -> None:
        super().__init__([SourceFile("mixer.graph", MIXER), SourceFile("ob1.awl", OB1)])

    def chart(self) -> tuple[GraphStatus, dict[str, str], dict[str, bool]]:
        status = self.status("FB1")
        assert status.language == "graph"
        graph = status.graph
        assert graph is not None
        steps = {step.name: step.state for step in graph.steps}
        return graph, steps, {t.name: t.tt for t in graph.transitions}


@pytest.fixture(scope="module")
def session() -> Iterator[Mixer]:
    found = Mixer()
    yield found
    found.session.close()


@pytest.fixture
def mixer(session: Mixer) -> Mixer:
    """The mixer as after a cold start: AUTO, the initial step active, the interlock fine (the
    next call starts the sequencer again when G7_STARTED is 0, SEMANTICS.md §2 phase 1)."""
    session.run(session.session.sequencers.clear)
    inputs = {f"I0.{bit}": bit == 5 for bit in range(8)}
    session.write(inputs | {"DB1.G7_MODE": 1, "DB1.G7_CMD": 0, "DB1.G7_STARTED": False})
    session.scans(2)
    return session


def test_the_chart_follows_the_sequencer_scan_by_scan(mixer: Mixer) -> None:
    graph, steps, tt = mixer.chart()
    assert (graph.db, graph.mode) == ("DB1", "AUTO")
    assert [(s.number, s.name) for s in graph.steps] == [
        (1, "Idle"),
        (2, "Fill"),
        (3, "Mix"),
    ]
    assert steps == {"Idle": "active", "Fill": "inactive", "Mix": "inactive"}
    assert tt == {"Go": False, "Full": False, "Done": False}
    mixer.write({"I0.0": True})
    mixer.scans(1)
    _, steps, _ = mixer.chart()
    assert steps["Fill"] == "active"
    assert mixer.read("Q4.0") is True
    mixer.write({"I0.5": False})  # the interlock breaks: Fill is disturbed, its N action stops
    _, steps, _ = mixer.chart()
    fill = next(s for s in mixer.chart()[0].steps if s.name == "Fill")
    assert (steps["Fill"], fill.interlock_error) == ("disturbed", True)
    assert fill.t_ms >= 10
    assert fill.u_ms < fill.t_ms


def test_a_transition_reports_its_condition_in_the_call_it_was_evaluated(
    mixer: Mixer,
) -> None:
    mixer.write({"I0.0": True})
    mixer.scans(1)
    mixer.write({"I0.0": False, "I0.1": True})
    # Opening the block samples the next scan: the call in which Full fires.
    _graph, steps, tt = mixer.chart()
    assert (tt, steps["Mix"]) == ({"Go": False, "Full": True, "Done": False}, "active")
    # In the next call Fill is no longer active: Full is not evaluated, its TT is false.
    assert mixer.chart()[2] == {"Go": False, "Full": False, "Done": False}


def test_man_mode_switches_steps_by_hand(mixer: Mixer) -> None:
    mixer.control("DB1", "man")
    mixer.control("DB1", "step_on", 3)  # queued: taken at the call after MAN
    mixer.scans(2)
    graph, steps, _ = mixer.chart()
    assert graph.mode == "MAN"
    assert steps == {"Idle": "active", "Fill": "inactive", "Mix": "active"}
    assert mixer.read("Q4.1") is True
    mixer.write({"I0.0": True})  # MAN: no transition switches
    mixer.scans(3)
    assert mixer.chart()[1]["Fill"] == "inactive"
    mixer.control("DB1", "step_off", 1)
    mixer.scans(1)
    assert mixer.chart()[1] == {"Idle": "inactive", "Fill": "inactive", "Mix": "active"}


def test_tap_switches_one_transition_per_push(mixer: Mixer) -> None:
    mixer.control("DB1", "tap")
    mixer.write({"I0.0": True, "I0.1": True})
    mixer.scans(3)
    assert mixer.chart()[1]["Idle"] == "active"  # the condition alone does not switch in TAP
    mixer.control("DB1", "push")
    mixer.scans(3)
    assert mixer.chart()[1] == {"Idle": "inactive", "Fill": "active", "Mix": "inactive"}


def test_a_supervision_error_is_acknowledged(mixer: Mixer) -> None:
    mixer.write({"I0.0": True})
    mixer.scans(1)
    mixer.write({"I0.0": False, "I0.6": True})
    mixer.scans(2)
    mixer.write({"I0.6": False, "I0.1": True})
    mixer.scans(2)
    fill = next(s for s in mixer.chart()[0].steps if s.name == "Fill")
    assert (fill.state, fill.supervision_error) == ("disturbed", True)  # blocks Full
    mixer.control("DB1", "ack")
    mixer.scans(2)
    assert mixer.chart()[1] == {"Idle": "inactive", "Fill": "inactive", "Mix": "active"}


def test_init_and_off(mixer: Mixer) -> None:
    mixer.write({"I0.0": True})
    mixer.scans(2)
    mixer.control("DB1", "off")
    mixer.scans(1)
    assert set(mixer.chart()[1].values()) == {"inactive"}
    mixer.write({"I0.0": False})
    mixer.control("DB1", "init")
    mixer.scans(1)
    assert mixer.chart()[1] == {"Idle": "active", "Fill": "inactive", "Mix": "inactive"}
