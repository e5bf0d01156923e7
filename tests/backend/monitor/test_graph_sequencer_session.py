"""The monitor's side of an S7-Graph FB, on a session, against the instance DB layout of
``nasaq/lang/graph/SEMANTICS.md`` §1: the block status reports each step (inactive, active,
disturbed, its time) and each transition's TT from the DB the sampled call used, and the Control
Sequencer's commands reach the DB's mailbox one per FB call, validated with their MON6xx codes.

The FB here is written in STL with exactly that layout and a mailbox that only records what it
takes, so what is tested is the monitor, not the Graph lowering (``test_graph_monitor_run.py``
runs a real ``.graph`` FB)."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from pydantic import ValidationError

sys.path.insert(0, str(Path(__file__).resolve().parent))
from graph_session import Cpu

from nasaq.lang.stl import SourceFile
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.protocol import CLIENT_MESSAGE

SEQUENCER = """\
FUNCTION_BLOCK FB 1
VAR_INPUT
  INIT_SQ : BOOL;
END_VAR
VAR
  G7_MODE : INT := 1;
  G7_CMD : INT;
  G7_CMD_STEP : INT;
  Idle : STRUCT
    X : BOOL;
    LA : BOOL;
    VA : BOOL;
    SNO : INT := 1;
    T : TIME;
    U : TIME;
  END_STRUCT;
  Fill : STRUCT
    X : BOOL;
    LA : BOOL;
    VA : BOOL;
    SNO : INT := 7;
    T : TIME;
    U : TIME;
  END_STRUCT;
  Trans1 : STRUCT
    TT : BOOL;
    TNO : INT := 3;
  END_STRUCT;
  Taken : INT;
  TakenStep : INT;
END_VAR
BEGIN
NETWORK
TITLE = the mailbox: take the command, a mode command selects the mode
      L     #G7_CMD;
      T     #Taken;
      L     #G7_CMD_STEP;
      T     #TakenStep;
      L     0;
      T     #G7_CMD;
      L     #Taken;
      L     4;
      >I    ;
      JC    done;
      L     #Taken;
      L     0;
      >I    ;
      JCN   done;
      L     #Taken;
      T     #G7_MODE;
done: A     I 0.0;
      =     #Idle.X;
      A     I 0.1;
      =     #Idle.LA;
      A     I 0.2;
      =     #Fill.X;
      A     I 0.3;
      =     #Fill.VA;
      A     I 0.4;
      =     #Trans1.TT;
      L     MD 20;
      T     #Fill.T;
      L     MD 24;
      T     #Fill.U;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB 2
VAR
  count : INT;
END_VAR
BEGIN
NETWORK
TITLE =
      L     #count;
      T     MW 30;
END_FUNCTION_BLOCK

DATA_BLOCK DB 1
FB 1
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB 3
FB 1
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB 2
FB 2
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB 5
STRUCT
  level : INT;
END_STRUCT;
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE =
      CALL FB 1 , DB 1 (INIT_SQ := FALSE);
      CALL FB 2 , DB 2;
      A     M 0.0;
      JCN   end;
      CALL FB 1 , DB 3 (INIT_SQ := FALSE);
end:  NOP   0;
END_ORGANIZATION_BLOCK
"""
SYMBOLS = """\
"Conveyor","DB 1","FB 1","the sequencer's instance"
"Plain","DB 5","DB 5","a shared DB"
"""


@pytest.fixture(scope="module")
def cpu() -> Iterator[Cpu]:
    found = Cpu([SourceFile("seq.awl", SEQUENCER), SourceFile("symbols.sdf", SYMBOLS)])
    yield found
    found.session.close()


def _error(cpu: Cpu, db: str, op: str, step: int | None = None) -> MonitorError:
    with pytest.raises(MonitorError) as caught:
        cpu.control(db, op, step)
    return caught.value


def test_the_block_status_of_a_graph_fb_shows_each_step_and_transition(
    cpu: Cpu,
) -> None:
    cpu.write({"I0.0": True, "I0.1": True, "I0.2": True, "I0.3": False, "I0.4": True})
    cpu.write({"MD20": 2500, "MD24": 1000})
    status = cpu.status()
    assert status.graph is not None
    graph = status.graph
    assert (graph.db, graph.at, graph.mode) == ("DB1", 0, "AUTO")
    steps = {step.name: step for step in graph.steps}
    assert [step.number for step in graph.steps] == [1, 7]
    assert steps["Idle"].state == "disturbed"  # active with an interlock error (LA)
    assert steps["Idle"].interlock_error
    assert not steps["Idle"].supervision_error
    assert steps["Fill"].state == "active"
    assert (steps["Fill"].t_ms, steps["Fill"].u_ms) == (2500, 1000)
    assert [(t.number, t.name, t.tt) for t in graph.transitions] == [(3, "Trans1", True)]

    cpu.write({"I0.0": False, "I0.3": True, "I0.4": False})
    graph2 = cpu.status().graph
    assert graph2 is not None
    states = {step.name: (step.state, step.supervision_error) for step in graph2.steps}
    assert states == {"Idle": ("inactive", False), "Fill": ("disturbed", True)}
    assert not graph2.transitions[0].tt


def test_the_status_reads_the_instance_the_sampled_call_used(cpu: Cpu) -> None:
    cpu.write({"I0.0": True, "I0.1": False, "M0.0": True})  # the second call, with DB 3, runs last
    cpu.scans(1)
    cpu.write({"DB3.G7_MODE": 4})
    graph = cpu.status().graph
    assert graph is not None
    assert (graph.db, graph.mode) == ("DB3", "TOP")
    cpu.write({"M0.0": False})
    graph = cpu.status().graph
    assert graph is not None
    assert graph.db == "DB1"


def test_other_blocks_have_no_graph_status(cpu: Cpu) -> None:
    assert cpu.status("FB2").graph is None
    assert cpu.status("OB1").graph is None


def test_a_mode_command_reaches_the_fb_at_its_next_call(cpu: Cpu) -> None:
    answer = cpu.control('"Conveyor"', "man")
    assert answer == {"db": "DB1", "fb": "FB1", "command": 2, "waiting": 0}
    assert cpu.read("DB1.G7_CMD") == 2  # in the mailbox until the FB's next call
    cpu.scans(1)
    assert (cpu.read("DB1.Taken"), cpu.read("DB1.G7_CMD"), cpu.read("DB1.G7_MODE")) == (
        2,
        0,
        2,
    )
    cpu.control("DB1", "auto")
    cpu.scans(1)
    assert cpu.read("DB1.G7_MODE") == 1


def test_commands_sent_together_are_handed_over_one_per_call_in_order(cpu: Cpu) -> None:
    assert cpu.control("DB 1", "man")["waiting"] == 0
    # step_on is accepted although the FB is still in AUTO: MAN is on its way.
    assert cpu.control("DB1", "step_on", 7)["waiting"] == 1
    assert cpu.control("DB1", "ack")["waiting"] == 2
    taken: list[tuple[int, int]] = []
    for _ in range(3):
        cpu.scans(1)
        taken.append((cpu.read("DB1.Taken"), cpu.read("DB1.TakenStep")))
    assert taken == [(2, 0), (6, 7), (5, 0)]
    cpu.control("DB1", "auto")
    cpu.scans(1)


@pytest.mark.parametrize(
    ("op", "code"),
    [
        ("tap", 3),
        ("top", 4),
        ("push", 8),
        ("init", 9),
        ("off", 10),
        ("interlock_on", 11),
        ("interlock_off", 12),
        ("supervision_on", 13),
        ("supervision_off", 14),
    ],
)
def test_each_operation_writes_its_mailbox_code(cpu: Cpu, op: str, code: int) -> None:
    assert cpu.control("DB1", op)["command"] == code
    assert cpu.read("DB1.G7_CMD") == code
    cpu.scans(1)
    assert cpu.read("DB1.Taken") == code
    cpu.write({"DB1.G7_MODE": 1})


def test_bad_commands_have_their_codes(cpu: Cpu) -> None:
    assert _error(cpu, "DB9", "auto").code == "MON617"
    assert _error(cpu, '"Nothing"', "auto").code == "MON617"
    assert _error(cpu, "DB2", "auto").code == "MON618"  # an instance DB of an FB without mailbox
    assert _error(cpu, '"Plain"', "auto").code == "MON618"  # a shared DB
    cpu.control("DB1", "man")
    unknown = _error(cpu, "DB1", "step_on", 2)
    assert unknown.code == "MON619"
    assert unknown.params["steps"] == "S1, S7"
    assert _error(cpu, "DB1", "step_off").code == "MON620"
    cpu.control("DB1", "auto")
    manual = _error(cpu, "DB1", "step_on", 1)
    assert (manual.code, manual.params["mode"]) == ("MON621", "AUTO")
    cpu.scans(2)


def test_a_command_needs_run_and_an_fb_that_is_called(cpu: Cpu) -> None:
    cpu.write({"M0.0": False})
    # DB 3's FB is not called: one command waits in its mailbox, 16 more in the queue.
    assert [cpu.control("DB3", "push")["waiting"] for _ in range(17)] == list(range(17))
    assert _error(cpu, "DB3", "push").code == "MON623"
    cpu.write({"M0.0": True})
    cpu.scans(16)
    assert cpu.read("DB3.G7_CMD") == 0  # the 16th taken, the 17th goes in before the next scan
    cpu.scans(1)
    assert cpu.read("DB3.G7_CMD") == 0
    assert cpu.control("DB3", "auto")["waiting"] == 0  # the queue is empty again
    cpu.scans(1)  # the FB took them all, one per call
    cpu.write({"M0.0": False})
    cpu.run(cpu.session.do_stop)
    assert _error(cpu, "DB1", "auto").code == "MON622"
    cpu.run(cpu.session.do_run)
    cpu.run(lambda: cpu.session.do_set_time("pause", None))


def test_unknown_operations_and_bad_steps_are_refused_by_the_protocol() -> None:
    for bad in (
        {"type": "graph_control", "db": "DB1", "op": "jump"},
        {"type": "graph_control", "db": "", "op": "auto"},
        {"type": "graph_control", "db": "DB1", "op": "step_on", "step": 0},
    ):
        with pytest.raises(ValidationError, match="graph_control"):
            CLIENT_MESSAGE.validate_python(bad)
