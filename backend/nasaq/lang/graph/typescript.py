"""TypeScript types of the S7-Graph model, generated from the pydantic models, so the chart and
step editors hold exactly what ``POST /api/graph/read`` sends.

``python -m nasaq.lang.graph.typescript`` prints ``frontend/src/graph/model.ts``; with ``--write``
it writes it. Conditions and permanent networks are the LAD model's ``Series``/``Network``, which
``frontend/src/lad/model.ts`` already declares: they are imported from there, not declared twice.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from pathlib import Path

from pydantic import TypeAdapter

from nasaq.lang.graph.model import GraphBlock
from nasaq.lang.lad.model import LadBlock
from nasaq.typescript import Root, generate, write_or_print

COMMAND = ".venv/bin/python -m nasaq.lang.graph.typescript --write"
TARGET = Path("frontend") / "src" / "graph" / "model.ts"
# A declaration with the doc comment before it (the generator separates them by blank lines).
_DECLARATION = re.compile(r"(?:/\*\*.*?\*/\n)?export (?:interface|type) (\w+).*?\n}\n", re.DOTALL)


def _declared(text: str) -> dict[str, str]:
    return {match.group(1): match.group(0) for match in _DECLARATION.finditer(text)}


def model_typescript() -> str:
    """The contents of ``frontend/src/graph/model.ts``."""
    lad = _declared(generate([Root("LadBlock", TypeAdapter(LadBlock), "serialization", "")]))
    graph = _declared(generate([Root("GraphBlock", TypeAdapter(GraphBlock), "serialization", "")]))
    own = [text for name, text in graph.items() if name not in lad]
    body = "\n".join(own)
    shared = sorted(n for n in graph if n in lad and re.search(rf"\b{n}\b", body))
    return (
        "// Generated from backend/nasaq/lang/graph/model.py; do not edit.\n"
        f"// Regenerate with `{COMMAND}`.\n\n"
        f"import type {{ {', '.join(shared)} }} from '../lad/model';\n\n"
        f"export type {{ {', '.join(shared)} }};\n\n" + body
    )


def main(argv: Sequence[str] | None = None) -> None:
    write_or_print(model_typescript, TARGET, "python -m nasaq.lang.graph.typescript", argv)


if __name__ == "__main__":
    main()
