"""``nasaq compile``: compile sources and print what they became, as teachers show it: the STL
that S7-SCL blocks are compiled to, each SCL line marked where its code starts."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TextIO

from nasaq.diagnostics import Severity
from nasaq.headless.sources import SourceError, compile_files, diagnostic_line
from nasaq.lang.stl import ast
from nasaq.lang.stl.format import format_block


def line_marks(lines: dict[str, list[str]], file: str) -> object:
    """A comment for the first instruction of each SCL line: ``// 12: total := total + x;``."""
    last = [0]
    source = lines.get(file, [])

    def comment(item: ast.CodeItem) -> str | None:
        line = item.loc.line
        if not isinstance(item, ast.InstrNode) or line == last[0]:
            return None
        last[0] = line
        text = source[line - 1].strip() if 0 < line <= len(source) else ""
        return f"{line}: {text}" if text else str(line)

    return comment


def main(paths: list[Path], emit: str, out: TextIO = sys.stdout, err: TextIO = sys.stderr) -> int:
    try:
        result = compile_files(paths)
    except SourceError as exc:
        print(f"nasaq compile: {exc}", file=err)
        return 2
    for diagnostic in result.diagnostics:
        print(diagnostic_line(diagnostic), file=err)
    if emit == "stl":
        lines: dict[str, list[str]] = {}
        for file, _block in result.generated:
            if file not in lines:
                try:
                    lines[file] = (
                        Path(file).read_text(encoding="utf-8", errors="replace").split("\n")
                    )
                except OSError:
                    lines[file] = []
        for file, block in result.generated:
            out.write(format_block(block, comment=line_marks(lines, file)))  # type: ignore[arg-type]
            out.write("\n")
    errors = sum(1 for item in result.diagnostics if item.severity is Severity.ERROR)
    return 1 if errors else 0
