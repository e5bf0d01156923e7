"""TypeScript types for the monitoring protocol, generated from its pydantic models.

``python -m nasaq.monitor.typescript`` prints ``frontend/src/api/monitor.ts``; with ``--write`` it
writes it. The types come from the JSON Schema of ``CLIENT_MESSAGE`` in input (validation) mode, as
a client may leave out fields that have defaults, and of ``SERVER_MESSAGE`` in serialization mode,
where every field is always sent. A model used on both sides whose two schemas differ becomes two
interfaces, ``<Name>Input`` and ``<Name>Output`` (pydantic's own naming of such pairs). The
generator itself is ``nasaq.typescript``.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path

from nasaq.monitor import protocol
from nasaq.typescript import Root, UnsupportedSchemaError, generate, write_or_print

__all__ = [
    "COMMAND",
    "TARGET",
    "Root",
    "UnsupportedSchemaError",
    "generate",
    "main",
    "protocol_typescript",
]

COMMAND = ".venv/bin/python -m nasaq.monitor.typescript --write"
TARGET = Path("frontend") / "src" / "api" / "monitor.ts"


def protocol_typescript() -> str:
    """The contents of ``frontend/src/api/monitor.ts``."""
    return (
        "// Generated from backend/nasaq/monitor/protocol.py; do not edit. Regenerate with\n"
        f"// `{COMMAND}`.\n\n"
        f"export const PROTOCOL_VERSION = {json.dumps(protocol.PROTOCOL_VERSION)};\n\n"
        + generate(
            [
                Root("ClientMessage", protocol.CLIENT_MESSAGE, "validation"),
                Root("ServerMessage", protocol.SERVER_MESSAGE, "serialization"),
            ]
        )
    )


def main(argv: Sequence[str] | None = None) -> None:
    write_or_print(protocol_typescript, TARGET, "python -m nasaq.monitor.typescript", argv)


if __name__ == "__main__":
    main()
