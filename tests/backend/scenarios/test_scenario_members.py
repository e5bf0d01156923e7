"""Scenarios read and write DB variables by name (``DB1.Motor.on``, ``"Seq".count``): what a
Graph sequencer's tests need (active steps, step times, the Control Sequencer mailbox), shown
here on an STL FB with STAT members so the names resolve through the compiled DB layout."""

from pathlib import Path

import pytest

from nasaq.scenarios.model import ScenarioError, load_scenario
from nasaq.scenarios.runner import run_scenario

FB = """\
FUNCTION_BLOCK FB 1
VERSION : 0.1
VAR_INPUT
  start : BOOL;
END_VAR
VAR_OUTPUT
  running : BOOL;
END_VAR
VAR
  count : INT := 3;
  total : DINT;
  elapsed : TIME;
  level : REAL;
  cmd : INT;
  state : STRUCT
    X : BOOL;
    T : TIME;
  END_STRUCT;
END_VAR
BEGIN
NETWORK
TITLE = the start input sets the state and copies it out
      A     #start;
      =     #state.X;
      =     #running;
NETWORK
TITLE = while started, count scans and add 10 ms per scan to the time
      A     #start;
      JCN   done;
      L     #count;
      +     1;
      T     #count;
      L     #elapsed;
      L     L#10;
      +D;
      T     #elapsed;
      T     #state.T;
done: NOP 0;
NETWORK
TITLE = a command word is taken and cleared, as a mailbox
      L     #cmd;
      L     7;
      ==I;
      JCN   keep;
      L     L#100000;
      T     #total;
      L     0;
      T     #cmd;
keep: NOP 0;
END_FUNCTION_BLOCK

ORGANIZATION_BLOCK OB 1
VERSION : 0.1
BEGIN
NETWORK
TITLE = call the FB
      CALL FB 1, DB 1 (
           start   := I 0.0,
           running := Q 4.0);
END_ORGANIZATION_BLOCK
"""

SYMBOLS = '"Seq_data","DB 1","FB 1","the instance DB"\n'


def _scenario(tmp_path: Path, steps: str) -> Path:
    (tmp_path / "fb.awl").write_text(FB, encoding="utf-8")
    (tmp_path / "symbols.sdf").write_text(SYMBOLS, encoding="utf-8")
    path = tmp_path / "members.yaml"
    path.write_text(
        f"name: members\nsources: [fb.awl, symbols.sdf]\nsteps:\n{steps}",
        encoding="utf-8",
    )
    return path


def _problems(path: Path) -> list[str]:
    result = run_scenario(path)
    problems = [result.error, *result.diagnostics] if result.error else []
    return problems + [failure.describe() for failure in result.failures]


def test_members_are_read_by_name_with_their_types(tmp_path: Path) -> None:
    path = _scenario(
        tmp_path,
        """\
  - expect: {DB1.count: 3, DB1.state.X: 0, DB1.elapsed: T#0MS, '"Seq_data".running': FALSE}
  - set: {I0.0: 1}
  - run: 4
  - expect:
      DB1.count: 7
      DB1.state.x: 1
      db1.STATE.T: T#40MS
      DB1.elapsed: 40
      '"Seq_data".running': 1
      seq_data.count: 7
      DB1.DBX2.0: 1
      DB1.state.T: {min: T#30MS, max: 40}
      DB1.level: {real: 0.0, tolerance: 0}
""",
    )
    assert _problems(path) == []


def test_members_are_written_by_name(tmp_path: Path) -> None:
    path = _scenario(
        tmp_path,
        """\
  - set: {DB1.count: -5, DB1.level: 2.5, '"Seq_data".elapsed': T#1S}
  - expect: {DB1.count: -5, DB1.level: 2.5, DB1.elapsed: T#1S, DB1.DBW4: -5}
  - note: a mailbox written by the scenario is taken by the next call and cleared
  - set: {DB1.cmd: 7}
  - run: 1
  - expect: {DB1.cmd: 0, DB1.total: 100000}
""",
    )
    assert _problems(path) == []


def test_a_wrong_value_is_a_failure_naming_the_member_and_both_values(
    tmp_path: Path,
) -> None:
    path = _scenario(
        tmp_path,
        """\
  - set: {I0.0: 1}
  - run: 2
  - expect: {DB1.count: 4, DB1.state.X: 0, DB1.state.T: {min: T#1S}}
""",
    )
    result = run_scenario(path)
    assert result.error is None
    found = {f.address: (f.expected, f.actual, f.step) for f in result.failures}
    assert found == {
        "DB1.count": ("4", "5", 3),
        "DB1.state.X": ("0", "1", 3),
        "DB1.state.T": ("1000 ms..", "20 ms", 3),
    }


@pytest.mark.parametrize(
    ("steps", "wanted"),
    [
        ("  - run: 1\n  - expect: {DB1.S9.X: 1}\n", "step 2: DB1.S9.X:"),
        ("  - set: {DB1.cuont: 1}\n", "step 1: DB1.cuont:"),
        ("  - expect: {'\"Nope\".count': 1}\n", 'step 1: "Nope".count:'),
        ("  - expect: {Nope.count: 1}\n", "step 1: Nope.count:"),
        ("  - expect: {DB7.count: 1}\n", "step 1: DB7.count:"),
        ("  - set: {DB1.count: 70000}\n", "step 1: DB1.count:"),
        ("  - expect: {DB1.state: 1}\n", "step 1: DB1.state:"),
    ],
)
def test_an_unknown_member_or_bad_value_is_a_scenario_error_with_the_step(
    tmp_path: Path, steps: str, wanted: str
) -> None:
    result = run_scenario(_scenario(tmp_path, steps))
    assert result.error is not None
    assert wanted in result.error
    assert "(MON60" in result.error  # the monitor's stable code: MON603 unknown, MON606 value


def test_the_unknown_member_error_lists_what_the_db_has(tmp_path: Path) -> None:
    result = run_scenario(_scenario(tmp_path, "  - expect: {DB1.cuont: 1}\n"))
    assert result.error is not None
    assert "count" in result.error
    assert "MON603" in result.error


def test_a_member_key_is_only_shape_checked_before_compiling(tmp_path: Path) -> None:
    good = tmp_path / "good.yaml"
    good.write_text(
        "name: x\nsources: [a.awl]\nsteps:\n  - expect: {DB1.S5.X: 1, '\"IDB\".AUTO_ON': 0}\n",
        encoding="utf-8",
    )
    assert load_scenario(good).steps[0].expect == {"DB1.S5.X": 1, '"IDB".AUTO_ON': 0}
    plant = tmp_path / "plant.yaml"
    plant.write_text("name: x\nsources: [a.awl]\nsteps:\n  - set: {plant.level: 1}\n")
    with pytest.raises(ScenarioError, match=r"plant\.level"):
        load_scenario(plant)
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: x\nsources: [a.awl]\nsteps:\n  - set: {Q9: 1}\n", encoding="utf-8")
    with pytest.raises(ScenarioError, match="Q9"):
        load_scenario(bad)
