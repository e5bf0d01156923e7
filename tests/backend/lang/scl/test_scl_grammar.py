"""Grammar coverage: every rule, every alternative of every rule (each optional part present and
absent) and every terminal of grammars/scl.lark is used by the parser's own parse of the test
corpus (tests/backend/lang/scl/corpus/*.scl), and every place where error recovery inserts
``bad`` is reached by a syntax error. An untested grammar change shows up here.

The corpus is parsed exactly as the compiler parses (``parse_source``, with recovery), by a
parser whose rule callbacks record which expansion (Lark ``Rule``) each reduction used."""

from __future__ import annotations

from pathlib import Path

from grammar_coverage import Recorder, describe

from nasaq.lang.scl.grammar import GRAMMAR_PATH, build_parser
from nasaq.lang.scl.parse import parse_source

CORPUS = Path(__file__).parent / "corpus"

# One syntax error in each list where recovery shifts ERROR (see the rules using ``bad``).
RECOVERY = [
    "x := 1;\n",  # a statement outside any block
    "FUNCTION FC1 : VOID\n  := 5\nBEGIN\nEND_FUNCTION\n",  # a header item
    "FUNCTION FC1 : VOID\nVAR_INPUT\n  a : : INT;\nEND_VAR\nEND_FUNCTION\n",  # a declaration
    "FUNCTION FC1 : VOID\nCONST\n  A = 1;\nEND_CONST\nEND_FUNCTION\n",  # a constant
    "TYPE UDT1\nSTRUCT\n  a INT;\nEND_STRUCT\nEND_TYPE\n",  # a STRUCT member
    "FUNCTION FC1 : VOID\nBEGIN\n  x := 1 +;\nEND_FUNCTION\n",  # a statement
    "DATA_BLOCK DB1\nSTRUCT a : INT; END_STRUCT\nBEGIN\n  a := := 1;\nEND_DATA_BLOCK\n",
]


def _recorder() -> Recorder:
    return Recorder(build_parser(), parse_source)


def test_every_rule_alternative_and_terminal_is_exercised() -> None:
    recorder = _recorder()
    for path in sorted(CORPUS.glob("*.scl")):
        assert recorder.parse(path.name, path.read_text("utf-8")) == [], path.name
    assert recorder.parse("empty.scl", "") == []
    for number, text in enumerate(RECOVERY):
        recorder.parse(f"bad{number}.scl", text)
    missing = recorder.missing_alternatives()
    assert not missing, "grammar alternatives never exercised:\n" + describe(missing)
    never = recorder.missing_terminals()
    assert not never, f"terminals never shifted: {sorted(never)}"


def test_every_error_insertion_point_is_reached_by_recovery() -> None:
    recorder = _recorder()
    for number, text in enumerate(RECOVERY):
        codes = recorder.parse(f"bad{number}.scl", text)
        assert codes == ["SCL101"], (text, codes)
    missing = recorder.missing_error_insertions()
    assert not missing, f"recovery never inserts bad in: {sorted(missing)}"
    assert "ERROR" in recorder.terminals


def test_the_grammar_is_found_beside_the_backend() -> None:
    assert GRAMMAR_PATH.is_file()
    assert GRAMMAR_PATH.parent.name == "grammars"
