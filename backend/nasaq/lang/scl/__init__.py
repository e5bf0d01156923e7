"""The S7-SCL front end: grammar (``grammars/scl.lark``), AST, parser with error recovery and
a formatter. Type checking and lowering to the STL IR come next (see README.md)."""

from nasaq.lang.scl.parse import ParseResult, parse_source

__all__ = ["ParseResult", "parse_source"]
