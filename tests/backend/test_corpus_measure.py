"""The corpus measurement (tests/conformance/corpus.py) on a tiny corpus written here: the figures
it prints are only worth something if it sorts files into the right kinds and outcomes."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

SCRIPT = Path(__file__).resolve().parents[1] / "conformance" / "corpus.py"


@pytest.fixture(scope="module")
def corpus() -> ModuleType:
    spec = importlib.util.spec_from_file_location("nasaq_corpus_measure", SCRIPT)
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


CLASSIC_FC = """FUNCTION FC 7 : INT
VAR_INPUT
  a : INT;
END_VAR
BEGIN
  FC 7 := a * 2;
END_FUNCTION
"""

TIA_FB = """FUNCTION_BLOCK "Pump"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      run : Bool;
   END_VAR
BEGIN
    REGION the motor
        #run := NOT #run;
    END_REGION
END_FUNCTION_BLOCK
"""

USES_OTHER = """FUNCTION FC 8 : VOID
VAR_TEMP
  x : INT;
END_VAR
BEGIN
  x := "Elsewhere_FC"(a := 1);
END_FUNCTION
"""

BROKEN = """FUNCTION FC 9 : VOID
BEGIN
  IF THEN ;
END_FUNCTION
"""

STL_OB = """ORGANIZATION_BLOCK OB 1
BEGIN
      U     E      0.0;
      =     A      4.0;
END_ORGANIZATION_BLOCK
"""


def test_corpus_kinds_follow_extension_then_content(corpus: ModuleType) -> None:
    assert corpus.kind_of(Path("a.scl"), CLASSIC_FC) == "Classic SCL"
    assert corpus.kind_of(Path("a.scl"), TIA_FB) == "TIA SCL"
    assert corpus.kind_of(Path("a.scl"), "TYPE T STRUCT n : USINT; END_STRUCT") == "TIA SCL"
    assert corpus.kind_of(Path("a.scl"), "TYPE T STRUCT n : DINT; END_STRUCT") == "Classic SCL"
    assert corpus.kind_of(Path("a.AWL"), STL_OB) == "STL"
    assert corpus.kind_of(Path("a.udt"), "TYPE x") == ".db/.udt"


def test_corpus_outside_reference_is_quoted_or_defined_and_not_a_system_name(
    corpus: ModuleType,
) -> None:
    lines = ['  x := "Other".y;', "  t : TON_TIME;", "  z := w;"]
    quoted = {"code": "SCL201", "params": {"name": '"Other"'}, "line": 1, "column": 8}
    system = {"code": "SCL202", "params": {"type": "TON_TIME"}, "line": 2, "column": 7}
    local = {"code": "SCL201", "params": {"name": "w"}, "line": 3, "column": 8}
    defined = {
        "code": "SCL202",
        "params": {"type": "MotorData"},
        "line": 3,
        "column": 8,
    }
    assert corpus.is_outside_reference(quoted, lines, set())
    assert not corpus.is_outside_reference(system, lines, set())
    assert not corpus.is_outside_reference(local, lines, set())
    assert corpus.is_outside_reference(defined, lines, {"MOTORDATA"})


def test_corpus_names_a_repository_writes_quoted_are_its_global_names(
    corpus: ModuleType, tmp_path: Path
) -> None:
    """A tag-table constant the repository lacks: written ``"K_MAX"`` in one file and ``K_MAX``
    in another, it is defined outside both; quoted words in comments and texts are no names."""
    (tmp_path / "a.scl").write_text(
        'FUNCTION "A" : VOID\nBEGIN\n  "Data".n := "K_MAX"; // "NOTE"\n'
        '  "Data".s := \'say "HELLO"\';\nEND_FUNCTION\n'
    )
    names = corpus.defined_names([str(tmp_path / "a.scl")])
    assert {"A", "DATA", "K_MAX"} <= names
    assert "NOTE" not in names
    assert "HELLO" not in names
    use = {"code": "SCL201", "params": {"name": "K_MAX"}, "line": 1, "column": 8}
    assert corpus.is_outside_reference(use, ["  x := K_MAX;"], names)


def test_corpus_histogram_replaces_names_but_keeps_the_construct(
    corpus: ModuleType,
) -> None:
    error = {
        "code": "SCL101",
        "message": "Syntax error: unexpected 'THEN'.",
        "params": {"found": "'THEN'"},
    }
    assert corpus.normalise(error) == "SCL101 Syntax error: unexpected 'THEN'."
    named = {
        "code": "SCL201",
        "message": "speed is not declared in FB 3.",
        "params": {"name": "speed", "block": "FB 3"},
    }
    assert corpus.normalise(named) == "SCL201 speed is not declared in <name>."


def test_corpus_measures_a_small_corpus(corpus: ModuleType, tmp_path: Path) -> None:
    repo = tmp_path / "someone+plant"
    repo.mkdir()
    (repo / "double.scl").write_text(CLASSIC_FC)
    (repo / "pump.scl").write_text(TIA_FB)
    (repo / "caller.scl").write_text(USES_OTHER)
    (repo / "broken.scl").write_text(BROKEN)
    (repo / "notes.txt").write_text("not a source")
    files, repos = corpus.measure(tmp_path, None, 1, 30.0, True)
    status = {Path(o.label).name: o.status for o in files}
    assert status == {
        "double.scl": "accepted",
        "pump.scl": "accepted-1500",
        "caller.scl": "elsewhere",
        "broken.scl": "refused",
    }
    broken = next(o for o in files if o.label.endswith("broken.scl"))
    assert broken.first.startswith("SCL10")
    assert broken.example.endswith(":3:6")
    assert broken.first in broken.constructs
    (whole,) = repos
    assert whole.status == "refused"
    assert sorted(Path(p).name for p in whole.clean_files) == [
        "caller.scl",
        "double.scl",
        "pump.scl",
    ]
    text = corpus.report(files, repos, 30.0)
    assert "Accepted: 3/4 (75.0 %)" in text
    assert "Uncaught exceptions, timeouts, crashes: 0" in text
    assert f"     1  {broken.first}" in text.split("containing each construct anywhere")[1]


def test_corpus_counts_exceptions_timeouts_and_crashes_with_their_place(
    corpus: ModuleType, tmp_path: Path
) -> None:
    source = tmp_path / "a.scl"
    source.write_text(CLASSIC_FC)
    job = corpus.Job("someone+plant", str(source), [str(source)], [])

    def explode() -> None:
        raise KeyError("boom")

    try:
        explode()
    except KeyError as error:
        text = corpus.describe(error)
    assert text.startswith("KeyError at outside nasaq: 'boom'")
    answers = [
        (
            {
                "exception": "RecursionError at nasaq/lang/x.py:3 in f: deep",
                "seconds": 1.0,
            },
            "exception",
        ),
        ({"timeout": True, "seconds": 30.0}, "timeout"),
        ({"crash": "the worker died (exit code -9)", "seconds": 0.0}, "crash"),
    ]
    outcomes = [corpus.judge_file(job, answer, set()) for answer, _ in answers]
    assert [o.status for o in outcomes] == [status for _, status in answers]
    text = corpus.report(outcomes, [], 5.0)
    assert "Uncaught exceptions, timeouts, crashes: 3" in text
    assert "RecursionError at nasaq/lang/x.py:3 in f" in text


def test_corpus_names_the_place_in_nasaq_that_raised(corpus: ModuleType) -> None:
    from nasaq.lang.stl import compiler

    try:
        compiler._suffix(None)  # type: ignore[arg-type]
    except AttributeError as error:
        text = corpus.describe(error)
    assert text.startswith("AttributeError at nasaq/lang/stl/compiler.py:")
    assert " in _suffix: " in text


def test_corpus_fails_on_any_escape_and_below_the_required_share(
    corpus: ModuleType,
) -> None:
    def outcome(status: str, kind: str = "TIA SCL") -> object:
        return corpus.Outcome("r", "f.scl", kind=kind, status=status)

    measured = [outcome("accepted"), outcome("elsewhere"), outcome("refused")]
    assert corpus.verdict(measured, 0.0) == 0
    assert corpus.verdict(measured, 66.0) == 0
    assert corpus.verdict(measured, 95.0) == 1
    assert corpus.verdict([*measured, outcome("timeout", "repository")], 0.0) == 1
    assert corpus.verdict([*measured, outcome("exception")], 0.0) == 1


@pytest.fixture(scope="module")
def gather() -> ModuleType:
    path = SCRIPT.parent / "corpus_gather.py"
    spec = importlib.util.spec_from_file_location("nasaq_corpus_gather", path)
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def test_corpus_gather_keeps_sources_and_leaves_look_alikes_out(
    gather: ModuleType,
) -> None:
    assert gather.is_source("src/Pump.scl", TIA_FB.encode())
    assert gather.is_source("OB1.AWL", STL_OB.encode())
    assert gather.is_source("types/Motor.udt", b'TYPE "Motor"\nSTRUCT\n a : Bool;\n')
    assert gather.is_source("Symbols.asc", b"126,Start      I     0.0 BOOL\n")
    assert not gather.is_source("station.scl", b'<?xml version="1.0"?>\n<SCL>FUNCTION</SCL>')
    assert not gather.is_source("part.stl", b"solid part\n facet normal 0 0 1\n")
    assert not gather.is_source("XRef.db", b"SQLite format 3\x00\x10\x00FUNCTION")
    assert not gather.is_source("tmpl.awl", b"FUNCTION_BLOCK @@NAME@@\nBEGIN\n")
    assert not gather.is_source("key.asc", b"-----BEGIN PGP PUBLIC KEY BLOCK-----\n")
    assert not gather.is_source("notes.txt", b"FUNCTION")


def test_corpus_gather_reads_the_repository_list(gather: ModuleType, tmp_path: Path) -> None:
    listing = tmp_path / "repos.txt"
    listing.write_text("# comment\nsomeone/plant 0123abc  # pinned\n\nother/lib\n")
    repos = gather.read_list(listing)
    assert [(r.owner, r.name, r.commit, r.folder) for r in repos] == [
        ("someone", "plant", "0123abc", "someone+plant"),
        ("other", "lib", "HEAD", "other+lib"),
    ]


def fake_worker(behaviour: str) -> subprocess.Popen[bytes]:
    """A process that answers like a corpus worker would not: it hangs or dies on its job."""
    program = {
        "hang": "import sys, time; sys.stdin.readline(); time.sleep(60)",
        "die": "import os, sys; sys.stdin.readline(); os._exit(3)",
    }[behaviour]
    return subprocess.Popen(
        [sys.executable, "-c", program], stdin=subprocess.PIPE, stdout=subprocess.PIPE
    )


@pytest.mark.parametrize(("behaviour", "key"), [("hang", "timeout"), ("die", "crash")])
def test_corpus_measures_a_worker_that_hangs_or_dies(
    corpus: ModuleType, behaviour: str, key: str
) -> None:
    job = corpus.Job("r", "f.scl", ["f.scl"], [])
    process = fake_worker(behaviour)
    try:
        answer = corpus.ask(process, job, 0.2)
    finally:
        corpus.stop(process)
    assert key in answer
    if key == "crash":
        assert "exit code 3" in answer["crash"]
