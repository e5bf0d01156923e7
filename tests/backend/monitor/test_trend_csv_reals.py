"""The trend CSV writes REALs as the trend and the watch table show them: 7 significant digits."""

from __future__ import annotations

import csv
import io
import struct
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import LiveServer, running_server, source

# DB1.level grows by 0.1 each scan: a REAL whose double value is 0.30000001192092896 after 3.
RAMP = """\
DATA_BLOCK DB 1
  STRUCT
    level : REAL;
  END_STRUCT;
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      L     DB1.level;
      L     1.000000e-001;
      +R    ;
      T     DB1.level;
      L     DB1.level;
      T     MD     4;
END_ORGANIZATION_BLOCK
"""


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


def _float32_sum(steps: int) -> float:
    total = 0.0
    for _ in range(steps):
        total = struct.unpack(
            "f", struct.pack("f", total + struct.unpack("f", struct.pack("f", 0.1))[0])
        )[0]
    return total


def test_reals_in_the_trend_csv_are_rounded_to_a_reals_precision(
    live: LiveServer,
) -> None:
    session_id = live.create([source("ramp.awl", RAMP)])["id"]
    try:
        with live.monitor(session_id) as client:
            client.ok("trend", entries=["DB1.level", "MD4"])
            client.ok("run")
            client.until(lambda m: len(m.trend) >= 12, "12 trend samples")
            # The frames carry the exact value; the CSV writes it as a REAL is written.
            assert any(len(repr(s["values"][0])) > 12 for s in client.trend)
            answer = live.http.get(
                f"/api/sessions/{session_id}/trend.csv",
                params={"client": client.client_id},
            )
        assert answer.status_code == 200
        rows = list(csv.reader(io.StringIO(answer.text)))
        assert rows[0] == ["scan", "time_ms", "DB1.level", "MD4"]
        for scan, _time, level, word in rows[1:]:
            assert level == format(_float32_sum(int(scan)), ".7g"), (scan, level)
            assert len(level.replace("-", "").replace(".", "").lstrip("0")) <= 7
            assert word.isdigit()  # a DWORD stays an integer
        by_scan = {int(row[0]): row[2] for row in rows[1:]}
        if 3 in by_scan:  # sampled after the 3rd scan: 0.1 + 0.1 + 0.1
            assert by_scan[3] == "0.3"
    finally:
        live.delete(session_id)
