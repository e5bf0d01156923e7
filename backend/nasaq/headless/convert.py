"""``nasaq convert SOURCE --to stl|lad|fbd [--out FILE]``: a source in another language (see
``nasaq.lang.lad.convert``). The converted text goes to ``--out`` or standard output; problems,
and the reason each network that stays STL does not convert, go to standard error. An S7-Graph
source converts to its STL; ``--to graph`` is accepted only to say why nothing converts to
S7-Graph (LAD503), rather than an argument error that would suggest a typo."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Literal, TextIO

from nasaq.diagnostics import Severity
from nasaq.headless.sources import diagnostic_line
from nasaq.lang.lad.convert import Target, convert, refused_to_graph


def main(
    source: Path,
    to: Target | Literal["graph"],
    out_path: Path | None,
    out: TextIO | None = None,
    err: TextIO | None = None,
) -> int:
    out = sys.stdout if out is None else out  # looked up now: a test may replace them
    err = sys.stderr if err is None else err
    try:
        text = source.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        text = source.read_text(encoding="cp1252")
    except OSError as exc:
        print(f"nasaq convert: cannot read {source}: {exc.strerror}", file=err)
        return 2
    result = refused_to_graph(str(source)) if to == "graph" else convert(str(source), text, to)
    for diagnostic in result.diagnostics:
        print(diagnostic_line(diagnostic), file=err)
    if result.kept:
        print(
            f"nasaq convert: {result.converted} network(s) converted, {result.kept} kept as STL",
            file=err,
        )
    if any(item.severity is Severity.ERROR for item in result.diagnostics):
        return 1
    if out_path is None:
        out.write(result.text)
    else:
        try:
            out_path.write_text(result.text, encoding="utf-8")
        except OSError as exc:
            print(f"nasaq convert: cannot write {out_path}: {exc.strerror}", file=err)
            return 2
    return 0
