"""Loads ``grammars/stl.lark`` and builds the one LALR parser every compilation shares.

The grammar lives at the top of the repository (``grammars/``, beside the other languages'), so
this module finds it relative to its own location; an installation that lacks it fails with a
clear message instead of a bare ``FileNotFoundError``. The parser is built once per process
(about 60 ms) with the AST builder as its inline transformer, so no parse tree is ever made;
its nodes take their positions from tokens, so the parser skips Lark's ``propagate_positions``
wrapper (a third of the parse time). ``build_parser`` makes a parser of one's own (the grammar
coverage test records the rules it reduces).
"""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import Any

from lark import Lark

GRAMMAR_PATH = Path(__file__).resolve().parents[4] / "grammars" / "stl.lark"


class GrammarMissingError(RuntimeError):
    """The STL grammar file is not where the package expects it."""


class _KeepNewlines:
    """Makes the contextual lexer produce ``_NL`` in every parser state; the parse driver then
    decides which newlines end a statement (see ``parse.NewlineFilter``)."""

    always_accept = ("_NL",)

    def process(self, stream: Any) -> Any:
        return stream


def grammar_text() -> str:
    try:
        return GRAMMAR_PATH.read_text(encoding="utf-8")
    except OSError as error:
        raise GrammarMissingError(
            f"The STL grammar is missing: expected it at {GRAMMAR_PATH}. Nasaq must run from its "
            "repository (or an installation that keeps grammars/ beside backend/)."
        ) from error


@cache
def parser() -> Lark:
    """The shared LALR parser; its transformer builds ``nasaq.lang.stl.ast`` nodes."""
    return build_parser()


def build_parser() -> Lark:
    """A new production parser (``parser`` shares one; tests instrument their own)."""
    from nasaq.lang.stl.build import AstBuilder

    builder: Any = AstBuilder()  # a plain object of rule callbacks (see ``AstBuilder``)
    return Lark(
        grammar_text(),
        parser="lalr",
        lexer="contextual",
        maybe_placeholders=False,
        postlex=_KeepNewlines(),
        transformer=builder,
    )
