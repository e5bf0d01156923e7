"""Modify of a process input holds, as PLCSIM's input modify does: the simulated input module is
the source of the inputs, so a watch table's modify of ``I0.0`` or ``IW64`` is not overwritten at
the next scan's process-image update, and the I/O panel (which shows the peripheral inputs) sees
the same value."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import (
    LOOP_PROGRAM,
    PLANT_SYMBOLS,
    LiveServer,
    Monitor,
    running_server,
    source,
)


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


@pytest.fixture
def lamp(live: LiveServer) -> Iterator[Monitor]:
    """The LOOP program (Q0.0 = I0.0), subscribed, in STOP."""
    session_id = live.create([source("prog.awl", LOOP_PROGRAM), source("io.sdf", PLANT_SYMBOLS)])[
        "id"
    ]
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        yield client
    live.delete(session_id)


def test_a_modified_input_bit_holds_over_many_scans_and_drives_the_program(
    lamp: Monitor,
) -> None:
    lamp.ok("watch", entries=["I0.0", "PIB0", "Q0.0"])
    lamp.ok("run")
    lamp.until_value("Q0.0", False)
    lamp.ok("modify", target="I0.0", value=True)
    lamp.until_value("Q0.0", True)
    # The simulated input module holds it: the panel's byte shows bit 0.
    lamp.until_value("PIB0", 1)
    assert lamp.cpu is not None
    scans = lamp.cpu["scans"]
    lamp.until(lambda m: m.cpu is not None and m.cpu["scans"] > scans + 20, "20 more scans")
    assert lamp.value("I0.0") is True
    assert lamp.value("Q0.0") is True
    # Modified back, it holds FALSE likewise; set_input and modify agree.
    lamp.ok("modify", target="I0.0", value=False)
    lamp.until_value("Q0.0", False)
    lamp.ok("set_input", address="I0.0", value=True)
    lamp.until_value("I0.0", True)


def test_a_modified_input_word_holds_and_a_force_still_wins(lamp: Monitor) -> None:
    lamp.ok("watch", entries=["IW64", "PIW64", "I0.0"])
    lamp.ok("run")
    lamp.ok("modify", target="IW64", value=13824)
    lamp.until_value("PIW64", 13824)
    assert lamp.cpu is not None
    scans = lamp.cpu["scans"]
    lamp.until(lambda m: m.cpu is not None and m.cpu["scans"] > scans + 20, "20 more scans")
    assert lamp.value("IW64") == 13824
    # A force wins over the modified value at every PII update.
    lamp.ok("modify", target="I0.0", value=True)
    lamp.ok("force", address="I0.0", value=False)
    lamp.until_value("I0.0", False)
    lamp.ok("unforce", address="I0.0")
    lamp.until_value("I0.0", True)
