"""The bad-input corpus (tests/corpus/bad/): every broken source gives a clear diagnostic with a
location and a code, or a CPU STOP with a reason, or runs; never an exception."""

import io
import json
import re
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml

from nasaq.headless.run import RunOptions, execute

CORPUS = Path(__file__).resolve().parents[1] / "corpus"
ENTRIES: list[dict[str, Any]] = yaml.safe_load(
    (CORPUS / "bad" / "expected.yaml").read_text("utf-8")
)
DIAGNOSTIC = re.compile(r"^.+:\d+:\d+: STL\d{3}: \S.*$")


@pytest.fixture(scope="module")
def big_source(tmp_path_factory: pytest.TempPathFactory) -> Path:
    sys.path.insert(0, str(CORPUS))
    try:
        from make_big import write_big  # type: ignore[import-not-found]
    finally:
        sys.path.remove(str(CORPUS))
    path: Path = write_big(tmp_path_factory.mktemp("big"))
    return path


def test_the_corpus_covers_the_named_cases() -> None:
    files = {entry["file"] for entry in ENTRIES}
    assert len(files) == len(ENTRIES) >= 40
    on_disk = {path.name for path in (CORPUS / "bad").glob("*.awl")}
    assert files - on_disk == {"big_ob1.awl"}
    assert on_disk <= files


@pytest.mark.parametrize("entry", ENTRIES, ids=lambda entry: entry["file"])
def test_bad_input(entry: dict[str, Any], big_source: Path) -> None:
    path = big_source if entry["file"] == "big_ob1.awl" else CORPUS / "bad" / entry["file"]
    out, err = io.StringIO(), io.StringIO()
    code = execute(RunOptions(sources=[path], cycles=5), out, err)
    stderr = err.getvalue()
    assert "Traceback" not in stderr
    expected = entry["expect"]
    if expected == "compile_error":
        assert code == 1, entry["what"]  # the program has errors (nasaq.cli's exit status)
        lines = stderr.strip().splitlines()
        assert lines, "no diagnostic printed"
        assert all(DIAGNOSTIC.match(line) for line in lines), lines
        return
    state = json.loads(out.getvalue())
    warnings = [line for line in stderr.strip().splitlines() if DIAGNOSTIC.match(line)]
    assert bool(warnings) == bool(entry.get("warning")), stderr
    if expected == "stop":
        assert code == 1, entry["what"]
        assert state["mode"] == "STOP"
        assert re.search(r"\(SIM5\d\d\)", state["stop_reason"]), state["stop_reason"]
    else:
        assert expected == "run"
        assert code == 0, (entry["what"], state["stop_reason"], stderr)
        assert state["mode"] == "RUN"
