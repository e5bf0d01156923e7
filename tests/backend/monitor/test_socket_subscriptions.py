"""What a monitoring client subscribes to on a real server: the CPU state, watch tables, block
status (STL and SCL) and trends, checked against what the programs compute."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import (
    CALC_SCL,
    PLANT_PROGRAM,
    LiveServer,
    Monitor,
    line_of,
    plant_sources,
    running_server,
    source,
)


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


@pytest.fixture
def plant(live: LiveServer) -> Iterator[Monitor]:
    """A client on a new session of the plant program (STL, with a symbol table), in STOP."""
    session_id = live.create(plant_sources())["id"]
    with live.monitor(session_id) as client:
        yield client
    live.delete(session_id)


@pytest.fixture
def calc(live: LiveServer) -> Iterator[Monitor]:
    """A client on a new session of the SCL program, in STOP."""
    session_id = live.create([source("calc.scl", CALC_SCL)])["id"]
    with live.monitor(session_id) as client:
        yield client
    live.delete(session_id)


def _row(block: dict[str, Any], index: int) -> dict[str, Any]:
    rows = {row["index"]: row for row in block["instructions"]}
    assert index in rows, f"instruction {index} did not run: {block['instructions']}"
    return rows[index]


def _line(block: dict[str, Any], line: int) -> dict[str, Any]:
    lines = {entry["line"]: entry["values"] for entry in block["lines"]}
    assert line in lines, f"line {line} shows nothing: {block['lines']}"
    values: dict[str, Any] = lines[line]
    return values


# -- the CPU ------------------------------------------------------------------------------------


def test_subscribe_cpu_reports_mode_scans_cycle_and_virtual_time(plant: Monitor) -> None:
    plant.ok("subscribe_cpu")
    first = plant.until(lambda m: m.cpu, "the CPU state")
    assert first["mode"] == "STOP"
    assert first["scans"] == 0
    assert first["cycle"] is None
    assert first["time_mode"] == "virtual"
    assert first["cycle_ms"] == 10

    plant.ok("run")
    seen: list[dict[str, Any]] = []

    def collect(m: Monitor) -> bool:
        if m.cpu is not None and m.state("mode") == "RUN" and (not seen or seen[-1] is not m.cpu):
            seen.append(m.cpu)
        return bool(seen) and seen[-1]["scans"] >= 25

    plant.until(collect, "25 scans")
    scans = [state["scans"] for state in seen]
    assert scans == sorted(scans), scans
    assert len(set(scans)) == len(scans), scans
    for state in seen:
        # Virtual time: exactly one cycle (10 ms) per scan.
        assert state["time_ms"] == state["scans"] * 10, state
        cycle = state["cycle"]
        assert cycle is not None
        assert 0 < cycle["min_ms"] <= cycle["avg_ms"] <= cycle["max_ms"]
        assert cycle["min_ms"] <= cycle["last_ms"] <= cycle["max_ms"]
        assert state["stop_code"] is None

    # Unsubscribed, frames carry no CPU state any more.
    plant.ok("subscribe_cpu", on=False)
    plant.ok("watch", entries=["MW30"])
    count = len(plant.frames)
    plant.until(lambda m: len(m.frames) > count + 3, "more frames")
    # The frame that answers the unsubscribe may still be on its way; later ones have no CPU.
    assert all(frame["cpu"] is None for frame in plant.frames[count + 1 :])


def test_the_cycle_time_given_at_creation_paces_the_virtual_clock(live: LiveServer) -> None:
    session_id = live.create(plant_sources(), cycle_ms=25)["id"]
    try:
        with live.monitor(session_id) as client:
            client.ok("subscribe_cpu")
            client.ok("run")
            state = client.until_scans(4)
            assert state["cycle_ms"] == 25
            assert state["time_ms"] == state["scans"] * 25
    finally:
        live.delete(session_id)


# -- watch --------------------------------------------------------------------------------------

_ENTRIES = [
    "MW30",
    "M1.0",
    "Q0.0",
    "DB1.DBW0",
    '"Counter"',
    "Lamp",
    "DB1.level",
    '"Tank".level',
    "DB1.speed",
    "DB5.count",
    "DB5.inc",
    "XW3",
    "DB1.nope",
    "DB9.DBW0",
]
_UNKNOWN = ["XW3", "DB1.nope", "DB9.DBW0"]


def test_watch_resolves_addresses_symbols_db_and_instance_members(plant: Monitor) -> None:
    ack = plant.ok("watch", entries=_ENTRIES)
    report = {entry["entry"]: entry for entry in ack["entries"]}
    assert list(report) == _ENTRIES
    assert report["MW30"]["type"] == "WORD"
    assert report["M1.0"]["type"] == "BOOL"
    assert report["DB1.DBW0"]["type"] == "WORD"
    assert report["Lamp"]["type"] == "BOOL"
    assert report["DB1.level"]["type"] == "INT"
    assert report['"Tank".level']["type"] == "INT"
    assert report["DB1.speed"]["type"] == "REAL"
    assert report["DB5.count"]["type"] == "INT"
    assert report["DB5.inc"]["type"] == "INT"
    for entry in _UNKNOWN:
        assert report[entry]["code"] == "MON603", report[entry]
        assert "type" not in report[entry]
    assert "DB1 has no variable nope" in report["DB1.nope"]["error"]
    assert "DB9" in report["DB9.DBW0"]["error"]

    plant.ok("run")
    plant.until(lambda m: (m.value("MW30") or 0) >= 5, "MW30 to count 5 scans")
    watch = plant.watch
    # MW30, its symbol and the FB's static counter all count the scans: one snapshot, one value.
    assert watch['"Counter"']["value"] == watch["MW30"]["value"] == watch["DB5.count"]["value"]
    assert watch["M1.0"]["value"] is True  # set by OB100
    assert watch["Q0.0"]["value"] is False
    assert watch["Lamp"]["value"] is False
    assert watch["DB1.DBW0"]["value"] == 5
    assert watch["DB1.level"]["value"] == 5
    assert watch['"Tank".level']["value"] == 5
    assert watch["DB1.speed"]["value"] == 1.5
    assert watch["DB5.inc"]["value"] == 1
    for entry in _ENTRIES:
        assert watch[entry]["forced"] is False
    for entry in _UNKNOWN:
        assert watch[entry]["value"] is None
        assert watch[entry]["error"] == report[entry]["error"]
    assert all(watch[e]["error"] is None for e in _ENTRIES if e not in _UNKNOWN)


def test_a_new_watch_list_replaces_the_old_one(plant: Monitor) -> None:
    plant.ok("watch", entries=["MW30"])
    plant.ok("run")
    plant.until(lambda m: (m.value("MW30") or 0) >= 2, "MW30")
    plant.ok("watch", entries=["DB1.level"])
    count = len(plant.frames)
    plant.until(lambda m: m.watch, "a watch frame")
    plant.drain(0.2)
    assert plant.watch == {"DB1.level": {"value": 5, "forced": False, "error": None}}
    later = [f["watch"] for f in plant.frames[count:] if f["watch"]]
    assert all(set(w) == {"DB1.level"} for w in later), later


def test_locals_are_watched_only_while_the_cpu_holds(plant: Monitor) -> None:
    ack = plant.ok("watch", entries=["#count"])
    assert ack["entries"] == [{"entry": "#count", "type": "local"}]
    plant.ok("run")
    plant.until(lambda m: "#count" in m.watch, "the local in a frame")
    assert plant.watch["#count"]["value"] is None
    assert plant.watch["#count"]["error"]


# -- block status -------------------------------------------------------------------------------


def test_open_block_stl_rows_hold_the_registers_the_program_computes(plant: Monitor) -> None:
    ack = plant.ok("open_block", block="OB1")
    assert ack == {"block": "OB1", "language": "stl", "instructions": 9}
    plant.ok("run")
    block = plant.until(lambda m: m.block if m.block and m.block["scan"] >= 3 else None, "status")
    assert block["block"] == "OB1"
    assert block["language"] == "stl"
    assert block["lines"] == []
    scan = block["scan"]
    assert [row["index"] for row in block["instructions"]] == list(range(9))

    # Network 2: L DB1.DBW0 (5); T MW20; L MW30; + 1; T MW30 (MW30 counts the scans).
    load_level, store, load_counter, add, store_counter = (_row(block, k) for k in range(1, 6))
    assert load_level["line"] == line_of(PLANT_PROGRAM, "L     DB1.DBW    0")
    assert (load_level["operand"], load_level["accu1"]) == (5, 5)
    assert (store["operand"], store["accu1"]) == (5, 5)
    assert load_counter["operand"] == scan - 1
    assert (load_counter["accu1"], load_counter["accu2"]) == (scan - 1, 5)
    assert (add["accu1"], add["accu2"]) == (scan, 5)
    # A positive sum: CC1 = 1, CC0 = 0, OV = 0 in the status word.
    assert (add["stw"] >> 7 & 1, add["stw"] >> 6 & 1, add["stw"] >> 5 & 1) == (1, 0, 0)
    assert store_counter["operand"] == scan
    assert store_counter["line"] == line_of(PLANT_PROGRAM, "T     MW    30")

    # Network 3: A M1.0 (1); AN M1.1 (0); = M1.2.
    check, check_not, assign = (_row(block, k) for k in (6, 7, 8))
    assert (check["operand"], check["rlo"], check["sta"]) == (True, 1, 1)
    assert (check_not["operand"], check_not["rlo"], check_not["sta"]) == (False, 1, 0)
    assert (assign["operand"], assign["rlo"], assign["sta"]) == (True, 1, 1)
    for row in block["instructions"]:
        assert row["stw"] >> 1 & 1 == row["rlo"], row
        assert row["stw"] >> 2 & 1 == row["sta"], row

    # The status follows the program: with M1.1 set, AN gives RLO 0 and M1.2 becomes 0.
    plant.ok("modify", target="M1.1", value=True)
    block = plant.until(
        lambda m: m.block if _row(m.block, 7)["operand"] is True else None, "AN M1.1 to read 1"
    )
    assert (_row(block, 7)["rlo"], _row(block, 7)["sta"]) == (0, 1)
    assert (_row(block, 8)["operand"], _row(block, 8)["rlo"]) == (False, 0)

    # Only the networks on screen: network 3 is instructions 6 to 8.
    plant.ok("open_block", block="OB1", networks=[3])
    # (A frame sent before the ack may still bring the whole block: wait for the new one.)
    block = plant.until(
        lambda m: m.block if m.block and m.block["instructions"][0]["index"] >= 6 else None,
        "network 3 only",
    )
    assert [row["index"] for row in block["instructions"]] == [6, 7, 8]
    assert block["elements"] == []
    plant.ok("open_block", block=None)


def test_open_block_stl_fb_rows_show_the_instance_data_operands(plant: Monitor) -> None:
    """FB1: L #count; L #inc; +I; T #count. The operand column shows the values the
    instructions read and wrote, as for any other operand."""
    assert plant.ok("open_block", block="FB1")["language"] == "stl"
    plant.ok("run")
    block = plant.until(lambda m: m.block if m.block and m.block["scan"] >= 3 else None, "status")
    scan = block["scan"]
    load_count, load_inc, add, store = (_row(block, k) for k in range(4))
    assert load_count["accu1"] == scan - 1
    assert load_inc["accu1"] == 1
    assert add["accu1"] == scan
    assert load_count["operand"] == scan - 1, load_count
    assert load_inc["operand"] == 1, load_inc
    assert store["operand"] == scan, store


def test_open_block_scl_fc_lines_show_the_variables_values(calc: Monitor) -> None:
    ack = calc.ok("open_block", block="FC3")
    assert ack["block"] == "FC3"
    assert ack["language"] == "scl"
    calc.ok("watch", entries=["MW40", "MW42"])
    calc.ok("run")
    block = calc.until(lambda m: m.block, "the status of FC3")
    assert block["language"] == "scl"
    # OB1 calls FC3 with a := total = 1 + 2 + 3 + 4 = 10.
    assert _line(block, line_of(CALC_SCL, "sq := a * a;")) == {"a": 10, "sq": 100}
    assert _line(block, line_of(CALC_SCL, "FC3 := sq + 1;"))["sq"] == 100
    calc.until_value("MW42", 101)
    calc.until_value("MW40", 20)


def test_open_block_scl_fb_lines_show_the_instance_variables(calc: Monitor) -> None:
    """FB2's lines write its static variables ``total`` and ``runs``; an SCL line lists "the
    block's variables its code read or wrote"."""
    calc.ok("open_block", block="FB2")
    calc.ok("watch", entries=["DB2.runs"])
    calc.ok("run")
    block = calc.until(lambda m: m.block if m.block and m.block["scan"] >= 2 else None, "status")
    # The FOR loop ends with i = limit + 1.
    assert _line(block, line_of(CALC_SCL, "FOR i := 1 TO limit DO"))["i"] == 5
    assert _line(block, line_of(CALC_SCL, "total := total + i;")).get("total") == 10
    assert _line(block, line_of(CALC_SCL, "runs := runs + 1;")).get("runs") == block["scan"]


def test_open_block_of_an_unknown_or_data_block_is_mon613(plant: Monitor) -> None:
    assert "FC9" in plant.fails("open_block", "MON613", block="FC9")["message"]
    plant.fails("open_block", "MON613", block="DB1")
    # Opening by a block's number with spaces works.
    assert plant.ok("open_block", block="fb 1")["block"] == "FB1"


# -- trend --------------------------------------------------------------------------------------


def test_trend_samples_every_scan(plant: Monitor) -> None:
    ack = plant.ok("trend", entries=["MW30", "DB5.count", "M1.2"])
    assert [entry["entry"] for entry in ack["entries"]] == ["MW30", "DB5.count", "M1.2"]
    plant.ok("run")
    plant.until(lambda m: len(m.trend) >= 40, "40 trend samples")
    samples = plant.trend
    scans = [sample["scan"] for sample in samples]
    assert scans == list(range(scans[0], scans[0] + len(scans))), "a scan is missing"
    for sample in samples:
        assert sample["time_ms"] == sample["scan"] * 10
        assert sample["values"] == [sample["scan"], sample["scan"], True]
    # The values change as the program runs.
    assert len({tuple(s["values"]) for s in samples}) == len(samples)
    # A new trend list starts afresh.
    plant.ok("trend", entries=["DB1.level"])

    def new_samples(m: Monitor) -> list[dict[str, Any]]:
        # (samples of the old list may still have been on their way)
        return [s for s in m.trend if len(s["values"]) == 1]

    plant.until(lambda m: len(new_samples(m)) > 3, "samples of the new list")
    assert all(s["values"] == [5] for s in new_samples(plant))


# -- LAD element status ---------------------------------------------------------------------

LATCH = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
RUNG Contact(I 0.0) Coil(Q 0.0) END_RUNG
NETWORK
RUNG
  PARALLEL
    BRANCH Contact(I 0.1) END_BRANCH
    BRANCH Contact(M 1.0) END_BRANCH
  END_PARALLEL
  ContactNC(I 0.2)
  Coil(M 1.0)
END_RUNG
END_ORGANIZATION_BLOCK
"""


def test_open_block_of_a_lad_block_reports_the_elements_of_its_networks_on_screen(
    live: LiveServer,
) -> None:
    session_id = live.create([source("main.lad", LATCH)])["id"]
    try:
        with live.monitor(session_id) as client:
            ack = client.ok("open_block", block="OB1", networks=[2])
            assert ack["language"] == "lad"
            client.ok("run")
            block = client.until(lambda m: m.block, "the block status")
            assert block["language"] == "lad"
            assert {e["network"] for e in block["elements"]} == {2}
            # Network 1 (instructions 0 and 1) is not recorded.
            assert min(row["index"] for row in block["instructions"]) == 2
            client.ok("set_input", address="I0.1", value=True)

            def latched(m: Monitor) -> dict[str, Any] | None:
                found = {e["id"]: e for e in (m.block or {}).get("elements", [])}
                coil = found.get("e5")
                return found if coil is not None and coil["value"] is True else None

            found = client.until(latched, "the latch coil on")
            assert found["e2"]["value"] is True  # I 0.1
            assert found["e5"]["out"] is True
            assert found["e1"] == {"network": 2, "id": "e1", "value": None, "out": None, "pins": {}}
            client.fails("open_block", "MON601", block="OB1", networks=[0])
    finally:
        live.delete(session_id)
