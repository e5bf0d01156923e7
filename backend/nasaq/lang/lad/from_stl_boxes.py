"""Which accumulator operation is which LAD box (see ``STL_PATTERNS.md``, "Boxes").

The lifter reads ``L in1; L in2; +I; T out`` as the box ``ADD_I``; these tables name the box of
each operation by how many loads it takes. Shifts load ``N`` first, then ``IN`` (or take ``N``
as their operand, ``SRW 3``, as people type them).
"""

from __future__ import annotations

COMPARES = frozenset(
    f"{relation}{kind}"
    for relation in ("==", "<>", ">", "<", ">=", "<=")
    for kind in ("I", "D", "R")
)

BINARY: dict[str, str] = {
    "+I": "ADD_I",
    "-I": "SUB_I",
    "*I": "MUL_I",
    "/I": "DIV_I",
    "+D": "ADD_DI",
    "-D": "SUB_DI",
    "*D": "MUL_DI",
    "/D": "DIV_DI",
    "MOD": "MOD_DI",
    "+R": "ADD_R",
    "-R": "SUB_R",
    "*R": "MUL_R",
    "/R": "DIV_R",
    "AW": "WAND_W",
    "OW": "WOR_W",
    "XOW": "WXOR_W",
    "AD": "WAND_DW",
    "OD": "WOR_DW",
    "XOD": "WXOR_DW",
}

SHIFTS: dict[str, str] = {
    "SLW": "SHL_W",
    "SRW": "SHR_W",
    "SLD": "SHL_DW",
    "SRD": "SHR_DW",
    "SSI": "SHR_I",
    "SSD": "SHR_DI",
    "RLD": "ROL_DW",
    "RRD": "ROR_DW",
}

UNARY: dict[str, str] = {
    "ABS": "ABS",
    "SQR": "SQR",
    "SQRT": "SQRT",
    "EXP": "EXP",
    "LN": "LN",
    "SIN": "SIN",
    "COS": "COS",
    "TAN": "TAN",
    "ASIN": "ASIN",
    "ACOS": "ACOS",
    "ATAN": "ATAN",
    "BTI": "BCD_I",
    "ITB": "I_BCD",
    "ITD": "I_DI",
    "DTR": "DI_R",
    "BTD": "BCD_DI",
    "DTB": "DI_BCD",
    "RND": "ROUND",
    "TRUNC": "TRUNC",
    "RND+": "CEIL",
    "RND-": "FLOOR",
    "INVI": "INV_I",
    "INVD": "INV_DI",
    "NEGI": "NEG_I",
    "NEGD": "NEG_DI",
    "NEGR": "NEG_R",
}

TIMERS: dict[str, str] = {
    "SP": "S_PULSE",
    "SE": "S_PEXT",
    "SD": "S_ODT",
    "SS": "S_ODTS",
    "SF": "S_OFFDT",
}
