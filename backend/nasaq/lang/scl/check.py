"""The public entry of the SCL front end after parsing: bind the sources into one index and
type-check every code block.

    parsed = [parse_source(name, text).source for name, text in files]
    index, diagnostics = check_sources(parsed, symbols)

``diagnostics`` holds the binder's problems (``SCL202``–``SCL210``) and the checker's
(``SCL201``, ``SCL211``–``SCL247``; ``SCL246`` and ``SCL247`` are warnings), sorted by file,
line and column. Syntax problems are the parser's (``ParseResult.diagnostics``) and are not
repeated here. The index also knows the instance DBs that ``FB.DB(...)`` calls create
(``SclIndex.implicit_dbs``).
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclIndex, bind
from nasaq.lang.scl.typecheck import check_index
from nasaq.lang.stl.diag import sort_key
from nasaq.lang.stl.symbols import SymbolTable


def check_sources(
    sources: list[ast.SourceFile], symbols: SymbolTable | None = None
) -> tuple[SclIndex, list[Diagnostic]]:
    """The project index of ``sources`` and every binding and type problem found in them."""
    index = bind(sources, symbols)
    diagnostics = [*index.diagnostics, *check_index(index)]
    return index, sorted(diagnostics, key=sort_key)
