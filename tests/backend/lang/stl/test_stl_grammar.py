"""Grammar coverage: every rule, every alternative of every rule (each optional part present and
absent) and every terminal of grammars/stl.lark is used by the compiler's own parse of the test
corpus (tests/backend/lang/stl/corpus/*.awl), and every place where error recovery inserts
``bad`` is reached by a syntax error. An untested grammar change shows up here.

The corpus is parsed exactly as the compiler parses (``parse_source``: newline rules, recovery),
by a parser whose rule callbacks record which expansion (Lark ``Rule``) each reduction used."""

from __future__ import annotations

from pathlib import Path

from grammar_coverage import Recorder, describe

from nasaq.lang.stl.grammar import GRAMMAR_PATH, build_parser
from nasaq.lang.stl.parse import parse_source

CORPUS = Path(__file__).parent / "corpus"

# One syntax error in each construct where recovery shifts ERROR (see the rules using ``bad``).
RECOVERY = [
    "ORGANIZATION_BLOCK OB 1\nBEGIN\n  A I 0.0 0.0\n  NOP 0\nEND_ORGANIZATION_BLOCK\n",
    "ORGANIZATION_BLOCK OB 1\nBEGIN\n  NOP 0\n  A I 0.0 0.0\nEND_ORGANIZATION_BLOCK\n",
    "FUNCTION FC 1 : VOID\nVAR_INPUT\n  a : : INT;\nEND_VAR\nBEGIN\nEND_FUNCTION\n",
    "FUNCTION FC 1 : VOID\n  := 5\nBEGIN\nEND_FUNCTION\n",
    "DATA_BLOCK DB 1\n  STRUCT\n    a : INT;\n  END_STRUCT;\nBEGIN\n  a := := 1;\nEND_DATA_BLOCK\n",
    "  A I 0.0 0.0\n  NOP 0\n",
]


def _recorder() -> Recorder:
    return Recorder(build_parser(), parse_source)


def test_every_rule_alternative_and_terminal_is_exercised() -> None:
    recorder = _recorder()
    for path in sorted(CORPUS.glob("*.awl")):
        assert recorder.parse(path.name, path.read_text("utf-8")) == [], path.name
    assert recorder.parse("empty.awl", "") == []
    for number, text in enumerate(RECOVERY):  # a lone newline item only follows an error
        recorder.parse(f"bad{number}.awl", text)
    missing = recorder.missing_alternatives()
    assert not missing, "grammar alternatives never exercised:\n" + describe(missing)
    never = recorder.missing_terminals()
    assert not never, f"terminals never shifted: {sorted(never)}"
    text = (CORPUS / "coverage.awl").read_text("utf-8")
    assert "//" in text
    assert "\t" not in text


def test_every_error_insertion_point_is_reached_by_recovery() -> None:
    recorder = _recorder()
    for number, text in enumerate(RECOVERY):
        codes = recorder.parse(f"bad{number}.awl", text)
        assert codes == ["STL101"], (text, codes)
    missing = recorder.missing_error_insertions()
    assert not missing, f"recovery never inserts bad in: {sorted(missing)}"
    assert "ERROR" in recorder.terminals


def test_the_grammar_is_found_beside_the_backend() -> None:
    assert GRAMMAR_PATH.is_file()
    assert GRAMMAR_PATH.parent.name == "grammars"
