"""Shared by the STL and SCL grammar-coverage tests: a production parser that records every rule
expansion it reduces and every terminal it shifts, and the shape of a rule for comparing them."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from lark import Lark, Token
from lark.grammar import Rule

Shape = tuple[str, tuple[str, ...]]


class Recorder:
    """Wraps Lark's callbacks of ``lark`` so a parse through ``parse`` notes what it used."""

    def __init__(self, lark: Lark, parse: Callable[[str, str, Lark], Any]) -> None:
        self.lark = lark
        self._parse = parse
        self.rules: set[Rule] = set()
        self.terminals: set[str] = set()
        callbacks: dict[Any, Callable[[Any], Any]] = lark._callbacks
        assert callbacks is lark.parser.parser.parser.callbacks, "Lark changed its internals"
        for rule, callback in list(callbacks.items()):
            callbacks[rule] = self._rule(rule, callback)
        for name in [terminal.name for terminal in lark.terminals] + ["ERROR"]:
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
        """The diagnostic codes of parsing ``text`` as file ``name``."""
        return [item.code for item in self._parse(name, text, self.lark).diagnostics]

    def missing_alternatives(self) -> set[Shape]:
        return shapes(self.lark.rules) - shapes(self.rules)

    def missing_terminals(self) -> set[str]:
        ignored = set(self.lark.ignore_tokens)
        declared = {terminal.name for terminal in self.lark.terminals} - ignored - {"ERROR"}
        return declared - self.terminals

    def missing_error_insertions(self) -> set[Shape]:
        declared = {shape for shape in shapes(self.lark.rules) if _has_bad(shape)}
        return declared - shapes(self.rules)


def shape(rule: Rule) -> Shape:
    """A Lark repetition helper (``__x_star_3: item | __x_star_3 item``) counts each item once,
    first or not; any other rule counts each expansion."""
    name = str(rule.origin.name)
    symbols = tuple(str(symbol.name) for symbol in rule.expansion)
    if name.startswith("__") and symbols[:1] == (name,):
        symbols = symbols[1:]
    return name, symbols


def shapes(rules: Iterable[Rule]) -> set[Shape]:
    return {shape(rule) for rule in rules}


def _has_bad(found: Shape) -> bool:
    name, symbols = found
    return name == "bad" or "bad" in symbols


def describe(missing: Iterable[Shape]) -> str:
    return "\n".join(
        f"  {name} -> {' '.join(symbols) or '(empty)'}" for name, symbols in sorted(missing)
    )
