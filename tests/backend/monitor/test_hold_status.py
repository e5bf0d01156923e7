"""At a hold, an SCL block's line values are the values at the hold: the same as its Locals."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import CALC_SCL, LiveServer, Monitor, line_of, running_server, source

BODY = line_of(CALC_SCL, "total := total + i;")
RUNS = line_of(CALC_SCL, "runs := runs + 1;")


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


@pytest.fixture
def calc(live: LiveServer) -> Iterator[Monitor]:
    session_id = live.create([source("calc.scl", CALC_SCL)])["id"]
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        yield client
    live.delete(session_id)


def _line(m: Monitor, line: int) -> dict[str, Any] | None:
    block = m.block
    if block is None:
        return None
    found = [row["values"] for row in block["lines"] if row["line"] == line]
    return found[0] if found else None


def _disagreements(m: Monitor) -> list[str]:
    """Every line value of the open block that is not what the hold's Locals show."""
    assert m.hold is not None
    assert m.block is not None
    shown = {v["name"]: v["value"] for v in m.hold["locals"]}
    return [
        f"line {row['line']}: {name} = {value!r}, Locals: {shown.get(name)!r}"
        for row in m.block["lines"]
        for name, value in row["values"].items()
        if shown.get(name) != value
    ]


def test_line_values_at_a_hold_are_the_locals_not_the_last_scan(calc: Monitor) -> None:
    calc.ok("open_block", block="FB2")
    calc.ok("run")
    # A whole scan leaves the loop's last values: total = 1 + 2 + 3 + 4.
    calc.until(lambda m: _line(m, BODY) == {"total": 10, "i": 4}, "the status of a whole scan")

    calc.ok("set_breakpoint", location={"file": "calc.scl", "line": BODY}, condition="i = 3")
    calc.until_held()
    assert (calc.local("i"), calc.local("total")) == (3, 3)
    calc.until(lambda m: _line(m, BODY) == {"total": 3, "i": 3}, "the line values at the hold")
    assert _disagreements(calc) == []
    runs = calc.local("runs")
    # A line not yet run in this scan shows the value now, too.
    assert _line(calc, RUNS) == {"runs": runs}

    # A value modified at the hold is what the line shows, as the Locals do.
    calc.ok("modify", target="#total", value=7)
    calc.until(lambda m: m.local("total") == 7, "the modified local")
    calc.until(lambda m: (_line(m, BODY) or {}).get("total") == 7, "the modified line value")
    assert _disagreements(calc) == []

    calc.ok("clear_breakpoint")
    calc.step("statement")  # the FOR's step: i := i + 1, after total := 7 + 3
    calc.until(lambda m: (_line(m, BODY) or {}).get("total") == 10, "the line after a step")
    assert (calc.local("i"), calc.local("total")) == (3, 10)
    assert _disagreements(calc) == []
    calc.ok("continue")
    calc.until_mode("RUN")
