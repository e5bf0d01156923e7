"""``nasaq compile``: compile sources and print what they became, as teachers show it: the STL
that S7-SCL blocks are compiled to, each SCL line marked where its code starts, and the STL an
S7-Graph FB lowers to (its sequencer machinery, steps, actions and transitions), each part
marked with the Graph line it comes from. The Graph files come first, in the order given."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TextIO

from nasaq.diagnostics import Severity
from nasaq.headless import project_file
from nasaq.headless.sources import SourceError, compile_files, diagnostic_line
from nasaq.lang.stl import ast
from nasaq.lang.stl.format import format_block
from nasaq.workbench.names import GRAPH_SUFFIXES


def _source_lines(path: Path) -> list[str]:
    try:
        return path.read_text(encoding="utf-8", errors="replace").split("\n")
    except OSError:
        return []


def graph_stl(file: str, source: list[str]) -> str:
    """The STL of a ``.graph`` file's FBs, a ``// 12: STEP Fill (2)`` comment line before the
    code of each Graph line (the lowering keeps each generated line's Graph line)."""
    from nasaq.lang.graph.compile import lower_file  # only Graph sources need it

    lowered = lower_file(file, "\n".join(source))
    out: list[str] = []
    last = 0
    in_code = False
    for number, text in enumerate(lowered.stl.rstrip("\n").split("\n"), start=1):
        head = text.strip().upper()
        if head == "BEGIN":
            in_code = True
        elif head.startswith("END_"):
            in_code = False
        line, _network = lowered.place(number)
        if in_code and head not in ("BEGIN", "") and line != last:
            last = line
            shown = source[line - 1].strip() if 0 < line <= len(source) else ""
            out.append(f"// {line}: {shown}" if shown else f"// {line}")
        out.append(text)
    return "\n".join(out) + "\n\n"


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


def main(
    paths: list[Path],
    emit: str,
    out: TextIO | None = None,
    err: TextIO | None = None,
    profile: str | None = None,
) -> int:
    """``profile`` None: the sources' cpu.properties decides (``nasaq run`` does the same), else
    S7-300."""
    out = sys.stdout if out is None else out  # looked up now: a test may replace them
    err = sys.stderr if err is None else err
    try:
        result = compile_files(paths, profile=profile or project_file.profile_of(paths))
    except SourceError as exc:
        print(f"nasaq compile: {exc}", file=err)
        return 2
    for diagnostic in result.diagnostics:
        print(diagnostic_line(diagnostic), file=err)
    if emit == "stl":
        lines: dict[str, list[str]] = {}
        for file, _block in result.generated:
            if file not in lines:
                lines[file] = _source_lines(Path(file))
        graphs = [path for path in paths if path.suffix.lower() in GRAPH_SUFFIXES]
        for path in graphs:
            out.write(graph_stl(str(path), _source_lines(path)))
        for file, block in result.generated:
            out.write(format_block(block, comment=line_marks(lines, file)))  # type: ignore[arg-type]
            out.write("\n")
    errors = sum(1 for item in result.diagnostics if item.severity is Severity.ERROR)
    return 1 if errors else 0
