"""The S7-SCL front end: grammar (``grammars/scl.lark``), AST, parser with error recovery, a
formatter, the binder (project index, numbering, layout) and the type checker. Lowering to the
STL IR comes next (see README.md).

``parse_source(file, text)`` parses one source; ``check_sources([source, ...], symbols)`` binds
the parsed sources and type-checks them, giving ``(index, diagnostics)``.
"""

from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.scl.check import check_sources
from nasaq.lang.scl.parse import ParseResult, parse_source

__all__ = ["ParseResult", "SclBlock", "SclIndex", "check_sources", "parse_source"]
