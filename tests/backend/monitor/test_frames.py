"""Frames that wait for a slow socket are merged: the newest state, every sample and entry."""

from __future__ import annotations

import json
from typing import Any

from nasaq.monitor import protocol as p
from nasaq.monitor.frames import MAX_MERGED_SAMPLES, merge


def frame(seq: int, **fields: Any) -> str:
    return p.Frame(seq=seq, **fields).model_dump_json()


def sample(scan: int) -> p.TrendSample:
    return p.TrendSample(scan=scan, time_ms=scan * 10, values=[scan])


def cpu(scans: int) -> p.CpuState:
    return p.CpuState(
        mode="RUN",
        time_mode="virtual",
        cycle_ms=10,
        scans=scans,
        time_ms=scans * 10,
        stop_code=None,
        stop_reason=None,
        cycle=None,
        forced=[],
    )


def test_one_frame_is_sent_as_it_is() -> None:
    text = frame(1, cpu=cpu(1))
    assert merge([text]) is text


def test_the_newest_state_wins_and_nothing_is_lost() -> None:
    merged = json.loads(
        merge(
            [
                frame(1, cpu=cpu(1), watch={"MW10": p.WatchValue(value=1)}, trend=[sample(1)]),
                frame(2, watch={"Q0.0": p.WatchValue(value=True)}, trend=[sample(2)]),
                frame(3, cpu=cpu(3), watch={"MW10": p.WatchValue(value=3)}, trend=[sample(3)]),
            ]
        )
    )
    assert merged["seq"] == 3
    assert merged["cpu"]["scans"] == 3
    assert merged["watch"] == {
        "MW10": {"value": 3, "forced": False, "error": None},
        "Q0.0": {"value": True, "forced": False, "error": None},
    }
    assert [s["scan"] for s in merged["trend"]] == [1, 2, 3]
    p.SERVER_MESSAGE.validate_python(merged)  # still a frame of the protocol


def test_a_hold_and_its_release_end_released() -> None:
    hold = p.HoldState(
        reason="breakpoint",
        breakpoint=1,
        location=p.StackFrame(block="FC1", instruction=2, line=5, file="a.awl", network=1),
        registers={},
        locals=[],
        call_stack=[],
    )
    held_then_released = json.loads(merge([frame(1, hold=hold), frame(2, released=True)]))
    assert held_then_released["released"] is True
    assert held_then_released["hold"] is None
    released_then_held = json.loads(merge([frame(1, released=True), frame(2, hold=hold)]))
    assert released_then_held["released"] is True
    assert released_then_held["hold"]["breakpoint"] == 1


def test_a_client_that_does_not_read_keeps_only_the_newest_samples() -> None:
    batches = [frame(k, trend=[sample(k * 1000 + n) for n in range(1000)]) for k in range(1, 8)]
    merged = json.loads(merge(batches))
    scans = [s["scan"] for s in merged["trend"]]
    assert len(scans) == MAX_MERGED_SAMPLES
    assert scans[-1] == 7999
    assert scans == sorted(scans)
