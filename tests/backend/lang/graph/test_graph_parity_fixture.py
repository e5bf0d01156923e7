"""The parity fixture of the front end's Graph printer and text splicing
(``tests/frontend/fixtures/graph-parity.json``) is what the Python Graph printer and reader give
today: its generator, in ``--check`` mode, agrees."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[4]
GENERATOR = ROOT / "tests" / "frontend" / "fixtures" / "make_graph_parity.py"
COMMAND = ".venv/bin/python tests/frontend/fixtures/make_graph_parity.py"


def test_the_committed_graph_parity_fixture_is_up_to_date() -> None:
    checked = subprocess.run(
        [sys.executable, str(GENERATOR), "--check"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    assert checked.returncode == 0, (
        f"the Graph printer or reader changed: run `{COMMAND}` and commit the fixture\n"
        f"{checked.stderr}"
    )
