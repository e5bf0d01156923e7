"""The hidden library FCs that compute with the S7-1200/1500 types the accumulators cannot hold
or compute right: the 64-bit LINT, ULINT, LREAL, LWORD and LTIME, UDINT's division and the
conversions of every S7-1200/1500 type. Their bodies are Python (``nasaq.cpu.long_library``),
as the IEC library's are (``nasaq.lang.iec_library``, which lists these FCs with its own, so
the compilers add and call them the same way).

One FC per operation and type: ``ADD_LREAL``, ``SUB_LINT``, ``DIV_UDINT``, ``NEG_LTIME``,
``AND_LWORD``, the comparisons ``EQ_LINT`` ... ``GE_LREAL`` (a BOOL), and one per conversion
with its TIA Portal name (``LREAL_TO_REAL``, ``UDINT_TO_DINT``, ``LINT_TO_LTIME`` ...). Every
parameter is an input; the result is RET_VAL. The S7-SCL compiler calls them for the operators
(``nasaq.lang.scl.lower.longs``); a program may also call them by name. They are numbered from
``BASE`` up in name order (a program block with the number moves them, as any library FC).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.iec_library import LibraryFunction

BASE = 700
INTEGERS_64 = ("LINT", "ULINT")
ARITHMETIC = ("ADD", "SUB", "MUL", "DIV", "MOD")
COMPARE = {"=": "EQ", "<>": "NE", "<": "LT", "<=": "LE", ">": "GT", ">=": "GE"}
OPERATORS = {
    "+": "ADD",
    "-": "SUB",
    "*": "MUL",
    "/": "DIV",
    "DIV": "DIV",
    "MOD": "MOD",
    "AND": "AND",
    "&": "AND",
    "OR": "OR",
    "XOR": "XOR",
}
# The types whose operations (per type) the library computes.
OPERATION_TYPES = ("LINT", "ULINT", "LREAL", "LWORD", "LTIME", "UDINT")


def _signatures() -> list[tuple[str, str, tuple[tuple[str, str], ...]]]:
    """(name, result type, (input, type) ...) of every library FC here."""
    from nasaq.lang.s7_1500_types import CONVERSIONS

    found: list[tuple[str, str, tuple[tuple[str, str], ...]]] = []
    for kind in ("LINT", "ULINT", "LREAL", "UDINT"):
        ops: tuple[str, ...] = ARITHMETIC if kind != "LREAL" else ARITHMETIC[:4]
        if kind == "UDINT":
            ops = ("DIV", "MOD")  # + - * of UDINTs are the accumulators' (the same bits)
        found += [(f"{op}_{kind}", kind, (("IN1", kind), ("IN2", kind))) for op in ops]
    found += [(f"NEG_{kind}", kind, (("IN", kind),)) for kind in ("LINT", "LREAL", "LTIME")]
    found += [
        (f"{op}_LTIME", "LTIME", (("IN1", "LTIME"), ("IN2", "LTIME"))) for op in ("ADD", "SUB")
    ]
    found += [
        (f"{op}_LTIME", "LTIME", (("IN1", "LTIME"), ("IN2", "LINT"))) for op in ("MUL", "DIV")
    ]
    found += [
        (f"{op}_LWORD", "LWORD", (("IN1", "LWORD"), ("IN2", "LWORD")))
        for op in ("AND", "OR", "XOR")
    ]
    found.append(("NOT_LWORD", "LWORD", (("IN", "LWORD"),)))
    for kind in OPERATION_TYPES:
        for op in COMPARE.values():
            found.append((f"{op}_{kind}", "BOOL", (("IN1", kind), ("IN2", kind))))
    for name in sorted(CONVERSIONS):
        source, _, target = name.partition("_TO_")
        found.append((name, target, (("IN", source),)))
    return found


def functions() -> list[LibraryFunction]:
    """The library FCs, numbered from ``BASE`` in name order."""
    from nasaq.lang.iec_library import LibraryFunction  # (it lists these with its own)

    made = []
    for number, (name, result, inputs) in enumerate(sorted(_signatures()), start=BASE):
        typed = tuple((formal, Elementary(kind)) for formal, kind in inputs)
        made.append(LibraryFunction(name, number, typed, Elementary(result), name))
    from nasaq.lang.long_functions import functions as standard_functions

    return made + standard_functions()  # SQRT_LREAL, MIN_LINT ... numbered after these


def operation(op: str, kind: str) -> str | None:
    """The library FC of ``op`` (an SCL operator) on two values of type ``kind``, if any."""
    if op in COMPARE:
        return f"{COMPARE[op]}_{kind}" if kind in OPERATION_TYPES else None
    name = OPERATORS.get(op)
    return None if name is None else f"{name}_{kind}"
