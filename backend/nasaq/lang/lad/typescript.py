"""TypeScript types of the LAD/FBD network model and its layouts, generated from the pydantic
models, so the browser's editors hold exactly what the API sends.

``python -m nasaq.lang.lad.typescript`` prints ``frontend/src/lad/model.ts``; with ``--write`` it
writes it. Every type is in serialization mode: every field is present, as the API sends it and
as the front end's ports of the pure LAD functions (``frontend/src/lad/``) build it. The unions
of the model (``Element``, ``Final``, ``FbdNode``, ``FbdFinal``) are named types.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from pydantic import TypeAdapter

from nasaq.lang.lad.fbd import FbdFinal, FbdNetwork, FbdNode
from nasaq.lang.lad.layout import FbdLayout, LadLayout
from nasaq.lang.lad.model import Element, Final, LadBlock
from nasaq.lang.system_blocks import SFB_INTERFACES, SFB_NAMES, SFC_INTERFACES, SFC_NAMES
from nasaq.typescript import Root, generate, write_or_print

COMMAND = ".venv/bin/python -m nasaq.lang.lad.typescript --write"
TARGET = Path("frontend") / "src" / "lad" / "model.ts"


def _root(name: str, kind: Any, description: str = "") -> Root:
    return Root(name, TypeAdapter(kind), "serialization", description)


def _system_blocks() -> str:
    """The system blocks a call box can call, with their parameters (``lang/system_blocks``)."""
    rows = []
    for kind, names, interfaces in (
        ("SFB", SFB_NAMES, SFB_INTERFACES),
        ("SFC", SFC_NAMES, SFC_INTERFACES),
    ):
        for number, name in names.items():
            pins = ", ".join(
                f"{{ section: '{section}', name: '{pin}', type: '{type_}' }}"
                for section, pin, type_ in interfaces[number]
                if section in ("IN", "OUT", "IN_OUT")
            )
            head = f"kind: '{kind}', number: {number}, name: '{name}'"
            rows.append(f"  {{ {head}, pins: [{pins}] }},")
    return (
        "\n/** A parameter of a system block (`backend/nasaq/lang/system_blocks.py`). */\n"
        "export interface SystemPin {\n"
        "  section: 'IN' | 'OUT' | 'IN_OUT';\n"
        "  name: string;\n"
        "  type: string;\n"
        "}\n\n"
        "/** A system function (block) the CPU runs, as a LAD/FBD call box calls it. */\n"
        "export interface SystemBlock {\n"
        "  kind: 'SFB' | 'SFC';\n"
        "  number: number;\n"
        "  name: string;\n"
        "  pins: SystemPin[];\n"
        "}\n\n"
        "export const SYSTEM_BLOCKS: readonly SystemBlock[] = [\n" + "\n".join(rows) + "\n];\n"
    )


def model_typescript() -> str:
    """The contents of ``frontend/src/lad/model.ts``: the model's types, and the system blocks
    a call box can call."""
    return (
        "// Generated from backend/nasaq/lang/lad/ (model.py, fbd.py, layout.py, layout_fbd.py);\n"
        f"// do not edit. Regenerate with `{COMMAND}`.\n\n"
        + generate(
            [
                _root("LadBlock", LadBlock),
                _root("Element", Element, "An element of a series, told apart by its `kind`."),
                _root("Final", Final, "The final element of an output, told apart by its `kind`."),
                _root("FbdNetwork", FbdNetwork),
                _root("FbdNode", FbdNode, "A node of an FBD network, told apart by its `kind`."),
                _root("FbdFinal", FbdFinal, "A final box of an FBD network, by its `kind`."),
                _root("LadLayout", LadLayout),
                _root("FbdLayout", FbdLayout),
            ]
        )
        + _system_blocks()
    )


def main(argv: Sequence[str] | None = None) -> None:
    write_or_print(model_typescript, TARGET, "python -m nasaq.lang.lad.typescript", argv)


if __name__ == "__main__":
    main()
