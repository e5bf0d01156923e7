"""The chart's layout fixture (``tests/frontend/fixtures/graph-chart.json``: every course S7-Graph
source as the Python reader gives it, for the front end's layout test) is current: its generator,
in ``--check`` mode, agrees."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[4]
GENERATOR = ROOT / "tests" / "frontend" / "fixtures" / "make_graph_chart.py"
COMMAND = ".venv/bin/python tests/frontend/fixtures/make_graph_chart.py"


def test_the_committed_chart_fixture_is_up_to_date() -> None:
    checked = subprocess.run(
        [sys.executable, str(GENERATOR), "--check"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    assert checked.returncode == 0, (
        f"the Graph reader or the course sources changed: run `{COMMAND}` and commit the fixture\n"
        f"{checked.stderr}"
    )
