"""Grammar coverage: every rule, every alternative of every rule (each optional part present and
absent) and every terminal of grammars/scl.lark is used by the parser's own parse of the test
corpus (tests/backend/lang/scl/corpus/*.scl), and every place where error recovery inserts
``bad`` is reached by a syntax error. An untested grammar change shows up here.

The corpus is parsed exactly as the compiler parses (``parse_source``, with recovery), by a
parser whose rule callbacks record which expansion (Lark ``Rule``) each reduction used."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from lark import Lark, Token
from lark.grammar import Rule

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


class Recorder:
    """A production parser that notes every rule expansion it reduces and terminal it shifts."""

    def __init__(self) -> None:
        self.lark: Lark = build_parser()
        self.rules: set[Rule] = set()
        self.terminals: set[str] = set()
        callbacks: dict[Any, Callable[[Any], Any]] = self.lark._callbacks
        assert callbacks is self.lark.parser.parser.parser.callbacks, "Lark changed its internals"
        for rule, callback in list(callbacks.items()):
            callbacks[rule] = self._rule(rule, callback)
        for name in [terminal.name for terminal in self.lark.terminals] + ["ERROR"]:
            callbacks[name] = self._terminal(callbacks.get(name))

    def _rule(self, rule: Rule, callback: Callable[[Any], Any]) -> Callable[[Any], Any]:
        def record(children: Any) -> Any:
            self.rules.add(rule)
            return callback(children)

        return record

    def _terminal(self, callback: Callable[[Token], Any] | None) -> Callable[[Token], Any]:
        def record(token: Token) -> Any:
            self.terminals.add(token.type)
            return callback(token) if callback is not None else token

        return record

    def parse(self, name: str, text: str) -> list[str]:
        return [item.code for item in parse_source(name, text, self.lark).diagnostics]


def _shape(rule: Rule) -> tuple[str, tuple[str, ...]]:
    """A Lark repetition helper (``__x_star_3: item | __x_star_3 item``) counts each item once,
    first or not; any other rule counts each expansion."""
    name = str(rule.origin.name)
    symbols = tuple(str(symbol.name) for symbol in rule.expansion)
    if name.startswith("__") and symbols[:1] == (name,):
        symbols = symbols[1:]
    return name, symbols


def _shapes(rules: Iterable[Rule]) -> set[tuple[str, tuple[str, ...]]]:
    return {_shape(rule) for rule in rules}


def _has_bad(shape: tuple[str, tuple[str, ...]]) -> bool:
    name, symbols = shape
    return name == "bad" or "bad" in symbols


def test_every_rule_alternative_and_terminal_is_exercised() -> None:
    recorder = Recorder()
    for path in sorted(CORPUS.glob("*.scl")):
        assert recorder.parse(path.name, path.read_text("utf-8")) == [], path.name
    assert recorder.parse("empty.scl", "") == []
    for number, text in enumerate(RECOVERY):
        recorder.parse(f"bad{number}.scl", text)
    declared = _shapes(recorder.lark.rules)
    missing = declared - _shapes(recorder.rules)
    assert not missing, "grammar alternatives never exercised:\n" + "\n".join(
        f"  {name} -> {' '.join(symbols) or '(empty)'}" for name, symbols in sorted(missing)
    )
    ignored = set(recorder.lark.ignore_tokens)
    terminals = {terminal.name for terminal in recorder.lark.terminals} - ignored - {"ERROR"}
    assert not terminals - recorder.terminals, (
        f"terminals never shifted: {sorted(terminals - recorder.terminals)}"
    )


def test_every_error_insertion_point_is_reached_by_recovery() -> None:
    recorder = Recorder()
    for number, text in enumerate(RECOVERY):
        codes = recorder.parse(f"bad{number}.scl", text)
        assert codes == ["SCL101"], (text, codes)
    declared = {shape for shape in _shapes(recorder.lark.rules) if _has_bad(shape)}
    missing = declared - _shapes(recorder.rules)
    assert not missing, f"recovery never inserts bad in: {sorted(missing)}"
    assert "ERROR" in recorder.terminals


def test_the_grammar_is_found_beside_the_backend() -> None:
    assert GRAMMAR_PATH.is_file()
    assert GRAMMAR_PATH.parent.name == "grammars"
