"""The parity fixture of the step view's action rules
(``tests/frontend/fixtures/graph-action-rules.json``) is what the Graph checker gives today:
its generator, in ``--check`` mode, agrees."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[4]
GENERATOR = ROOT / "tests" / "frontend" / "fixtures" / "make_graph_action_rules.py"
COMMAND = ".venv/bin/python tests/frontend/fixtures/make_graph_action_rules.py"


def test_the_committed_action_rules_fixture_is_up_to_date() -> None:
    checked = subprocess.run(
        [sys.executable, str(GENERATOR), "--check"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    assert checked.returncode == 0, (
        f"the Graph action rules changed: run `{COMMAND}` and commit the fixture\n{checked.stderr}"
    )
