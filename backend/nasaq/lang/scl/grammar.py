"""Loads ``grammars/scl.lark`` and builds the one LALR parser every SCL compilation shares.

As for STL (``nasaq.lang.stl.grammar``), the grammar lives at the top of the repository and the
parser is built once per process with the AST builder as its inline transformer, so no parse
tree is made; ``build_parser`` makes a parser of one's own (the grammar-coverage test records
the rules it reduces).
"""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import Any

from lark import Lark

GRAMMAR_PATH = Path(__file__).resolve().parents[4] / "grammars" / "scl.lark"


class GrammarMissingError(RuntimeError):
    """The SCL grammar file is not where the package expects it."""


def grammar_text() -> str:
    try:
        return GRAMMAR_PATH.read_text(encoding="utf-8")
    except OSError as error:
        raise GrammarMissingError(
            f"The SCL grammar is missing: expected it at {GRAMMAR_PATH}. Nasaq must run from its "
            "repository (or an installation that keeps grammars/ beside backend/)."
        ) from error


@cache
def parser() -> Lark:
    """The shared LALR parser; its transformer builds ``nasaq.lang.scl.ast`` nodes."""
    return build_parser()


def build_parser() -> Lark:
    """A new production parser (``parser`` shares one; tests instrument their own)."""
    from nasaq.lang.scl.build import AstBuilder

    builder: Any = AstBuilder()
    return Lark(
        grammar_text(),
        parser="lalr",
        lexer="contextual",
        maybe_placeholders=False,
        transformer=builder,
    )
