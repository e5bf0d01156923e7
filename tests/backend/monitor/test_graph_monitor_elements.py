"""The element status of a real ``.graph`` FB in a session, as the Graph editor draws it online:
each condition element of a transition (``T3/e2``), an interlock (``S2/C/e1``), a supervision
(``S2/V/e1``) and the permanent networks (``PRE1/e1``, ``POST1/e2``) with LAD's value/out
semantics, and each action row (``S2/A1``) with its operand's value, all with network 0. An
element whose code did not run (a transition whose step is not active) is absent."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from graph_session import Cpu

from nasaq.lang.stl import SourceFile
from nasaq.monitor.protocol import ElementStatus

SCENARIOS = Path(__file__).resolve().parents[2] / "scenarios" / "graph"
G17 = ["g17_conveyors.graph", "g17_conveyors.awl", "g17_conveyors.sdf"]

STATION = """\
FUNCTION_BLOCK FB 2
TITLE = Station
VAR
  count : INT;
END_VAR
BEGIN
PERMANENT_PRE
NETWORK
RUNG Contact(I 1.0) Coil(M 10.0) END_RUNG
END_PERMANENT_PRE
SEQUENCER Station
INITIAL_STEP Idle (1)
END_STEP

TRANSITION Go (1) FROM Idle TO Work
CONDITION Contact(I 1.1) END_CONDITION
END_TRANSITION

STEP Work (2)
INTERLOCK Contact(I 1.2) END_INTERLOCK
SUPERVISION Contact(I 1.3) ContactNC(I 1.5) END_SUPERVISION
ACTIONS
  NC Q 5.0;
  D Q 5.1, T#50MS;
  S1 CU C 3;
  N #count := #count + 2;
  S1 ON S3;
END_ACTIONS
END_STEP

STEP Spare (3)
END_STEP

TRANSITION Rest (3) FROM Spare JUMP Idle
CONDITION Contact(I 1.6) END_CONDITION
END_TRANSITION

TRANSITION Done (2) FROM Work JUMP Idle
CONDITION Contact(I 1.4) END_CONDITION
END_TRANSITION
END_SEQUENCER
PERMANENT_POST
NETWORK
RUNG Contact(Work.X) Coil(M 10.1) END_RUNG
END_PERMANENT_POST
END_FUNCTION_BLOCK
"""
OB1 = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE =
      CALL FB 2 , DB 2;
END_ORGANIZATION_BLOCK

DATA_BLOCK DB 2
FB 2
BEGIN
END_DATA_BLOCK
"""


def _by_id(elements: list[ElementStatus]) -> dict[str, ElementStatus]:
    assert all(e.network == 0 for e in elements), elements
    found = {e.id: e for e in elements}
    assert len(found) == len(elements), "an element reported twice"
    return found


@pytest.fixture(scope="module")
def conveyors() -> Iterator[Cpu]:
    cpu = Cpu([SourceFile(name, (SCENARIOS / name).read_text()) for name in G17])
    yield cpu
    cpu.session.close()


@pytest.fixture(scope="module")
def station() -> Iterator[Cpu]:
    cpu = Cpu([SourceFile("station.graph", STATION), SourceFile("ob1.awl", OB1)])
    yield cpu
    cpu.session.close()


def test_transition_conditions_of_the_active_step_with_their_values(
    conveyors: Cpu,
) -> None:
    conveyors.control("IDB_Conveyors", "man")  # MAN: the conditions are evaluated, none fires
    conveyors.write({"I0.0": True, "I0.1": False, "I0.2": False})
    status = conveyors.status("Conveyors")
    assert status.language == "graph"
    shown = _by_id(status.elements)
    # Idle's three transitions ran (Emergency / Start AND NOT Emergency / Stop AND NOT Emergency)
    assert {k for k in shown if k.startswith("T")} == {
        "T1/e1",
        "T2/e1",
        "T2/e2",
        "T3/e1",
        "T3/e2",
    }
    assert shown["T1/e1"].value is False  # Emergency
    assert shown["T2/e1"].value is True  # Start: the contact's bit, the client draws the flow
    assert shown["T2/e1"].out is None
    assert shown["T2/e2"].value is False  # NC Emergency: its bit, not the flow through it
    assert shown["T3/e1"].value is False
    graph = status.graph
    assert graph is not None
    assert {t.number: t.tt for t in graph.transitions}[2] is True

    conveyors.write({"I0.2": True})
    shown = _by_id(conveyors.status("Conveyors").elements)
    assert shown["T1/e1"].value is True
    assert shown["T2/e2"].value is True
    conveyors.write({"I0.0": False, "I0.2": False})
    conveyors.control("IDB_Conveyors", "auto")
    conveyors.scans(2)


def test_action_rows_and_a_compare_box_of_the_next_transition(conveyors: Cpu) -> None:
    conveyors.write({"I0.0": True})
    conveyors.scans(2)
    conveyors.write({"I0.0": False})
    assert conveyors.read("IDB_Conveyors.B_on.X") == 1
    shown = _by_id(conveyors.status("Conveyors").elements)
    # step 2 (B_on) is active: its S "Belt_B" row wrote Q 0.1; Idle's transitions did not run
    assert shown["S2/A1"].value is True
    assert shown["S2/A1"].out is True
    assert "T2/e1" not in shown
    assert not any(k.startswith("S6/") for k in shown)  # Emergency is not active
    compare = shown["T5/e1"]  # B_on.T >= T#5S, not yet
    assert compare.out is False
    assert compare.pins["IN2"] == 5000
    assert isinstance(compare.pins["IN1"], int)
    assert 0 <= compare.pins["IN1"] < 5000
    assert shown["T4/e1"].value is False  # the emergency branch of B_on

    conveyors.write({"I0.2": True})  # emergency: the Emergency step resets both belts
    conveyors.scans(2)
    shown = _by_id(conveyors.status("Conveyors").elements)
    assert (shown["S6/A1"].value, shown["S6/A1"].out) == (False, True)
    assert (shown["S6/A2"].value, shown["S6/A2"].out) == (False, True)
    assert shown["T10/e1"].value is True  # NC Emergency: the bit is 1, so no flow
    conveyors.write({"I0.2": False})
    conveyors.scans(3)
    assert conveyors.read("IDB_Conveyors.Idle.X") == 1


def test_interlock_supervision_permanent_networks_and_action_kinds(
    station: Cpu,
) -> None:
    station.write({"I1.0": True, "I1.1": False})
    shown = _by_id(station.status("FB2").elements)
    assert shown["PRE1/e1"].value is True  # the contact
    assert (shown["PRE1/e2"].value, shown["PRE1/e2"].out) == (
        True,
        True,
    )  # the coil M 10.0
    assert shown["POST1/e1"].value is False  # Work.X
    assert shown["POST1/e2"].out is False
    assert shown["T1/e1"].value is False
    assert not any(k.startswith("S2/") for k in shown)  # Work not active: nothing of it ran

    station.write({"I1.1": True, "I1.2": True, "I1.3": False, "I1.5": True})
    station.scans(2)
    station.write({"I1.1": False})
    assert station.read("DB2.Work.X") == 1
    shown = _by_id(station.status("FB2").elements)
    assert shown["S2/C/e1"].value is True  # the interlock is satisfied
    assert shown["S2/V/e1"].value is False  # the supervision: I 1.3 AND NOT I 1.5
    assert shown["S2/V/e2"].value is True
    assert (shown["S2/A1"].value, shown["S2/A1"].out) == (True, True)  # NC Q 5.0
    assert shown["POST1/e1"].value is True
    assert shown["S2/A3"].value == 1  # S1 CU C 3: the count after the one count up
    assert isinstance(shown["S2/A4"].value, int)  # #count := #count + 2, its new value
    assert shown["S2/A4"].value == station.read("DB2.count")
    assert shown["S2/A4"].out is None
    assert shown["S2/A5"].value is None  # S1 ON S3 has no operand value
    station.scans(10)  # more than 50 ms: the D row's bit comes
    shown = _by_id(station.status("FB2").elements)
    assert (shown["S2/A2"].value, shown["S2/A2"].out) == (True, True)

    station.write({"I1.2": False})  # interlock error: the C row's bit goes, the step is disturbed
    status = station.status("FB2")
    shown = _by_id(status.elements)
    assert shown["S2/C/e1"].value is False
    assert (shown["S2/A1"].value, shown["S2/A1"].out) == (False, False)
    assert status.graph is not None
    assert {s.number: s.state for s in status.graph.steps}[2] == "disturbed"
