"""SCL constants as STL constants of a wanted type: ``5`` into a DINT is ``L#5``, into a REAL
``5.000000e+00``, ``16#FF`` into a WORD ``W#16#FF``, ``T#1h_20m`` into an S5TIME ``S5T#1H20M``.

``evaluate`` reads a constant expression (a literal, a signed literal, a CONST name, simple
integer arithmetic of those) into a ``Value``; ``stl_constant`` writes it in STL syntax for a
type, as an ``(kind, text)`` pair of the STL literal token kinds (NUMBER, REAL, TYPED, CHARS,
IDENT for TRUE/FALSE).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from nasaq.lang.s7_1500_values import ltime_ns
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.stl.build import unquote_chars

_INT_PREFIXES = {
    "INT",
    "DINT",
    "SINT",
    "USINT",
    "UINT",
    "UDINT",
    "LINT",
    "ULINT",
    "LWORD",
    "LW",
    "BYTE",
    "WORD",
    "DWORD",
    "L",
    "B",
    "W",
    "DW",
}
_TIME_PREFIXES = {
    "T": "TIME",
    "TIME": "TIME",
    "S5T": "S5TIME",
    "S5TIME": "S5TIME",
    "D": "DATE",
    "DATE": "DATE",
    "TOD": "TIME_OF_DAY",
    "TIME_OF_DAY": "TIME_OF_DAY",
    "DT": "DATE_AND_TIME",
    "DATE_AND_TIME": "DATE_AND_TIME",
}
_STL_PREFIX = {
    "TIME": "T#",
    "S5TIME": "S5T#",
    "DATE": "D#",
    "TIME_OF_DAY": "TOD#",
    "DATE_AND_TIME": "DT#",
}


@dataclass(frozen=True, slots=True)
class Value:
    """``kind``: ``int`` (also BOOL 0/1 and bit strings), ``real``, ``chars`` (``text`` with
    quotes), or a time/date type name with ``text`` the STL body (``1H20M``)."""

    kind: str
    number: int | float = 0
    text: str = ""


def evaluate(node: ast.Expr, index: SclIndex | None, block: SclBlock | None) -> Value | None:
    """The value of a constant expression, or None when it is not one."""
    if isinstance(node, ast.Paren):
        return evaluate(node.inner, index, block)
    if isinstance(node, ast.Literal):
        return _literal(node.kind, node.text)
    if isinstance(node, ast.Unary) and node.op in ("-", "+"):
        inner = evaluate(node.operand, index, block)
        if inner is None or inner.kind not in ("int", "real"):
            return None
        return inner if node.op == "+" else Value(inner.kind, -inner.number)
    if isinstance(node, ast.Name | ast.Local) and block is not None:
        found = block.constants.get(node.name.casefold())
        if found is not None and found.node is not node:
            return evaluate(found.node, index, block)
        return None
    if isinstance(node, ast.Binary) and node.op in ("AND", "&", "OR", "XOR"):
        left, right = evaluate(node.left, index, block), evaluate(node.right, index, block)
        if left is None or right is None or left.kind != "int" or right.kind != "int":
            return None
        a, b = int(left.number), int(right.number)
        return Value(
            "int", a & b if node.op in ("AND", "&") else a | b if node.op == "OR" else a ^ b
        )
    if isinstance(node, ast.Binary) and index is not None and block is not None:
        number = index.const_value(block, node)
        if isinstance(number, int):
            return Value("int", number)
        if isinstance(number, float):
            return Value("real", number)
    return None


@cache  # the same literals come back again and again (``Value`` is frozen)
def _literal(kind: str, text: str) -> Value | None:
    try:
        return _parse(kind, text)
    except ValueError:
        return None  # not a number Nasaq reads (the checker has reported what is wrong)


def _parse(kind: str, text: str) -> Value | None:
    if kind == "INTEGER":
        return Value("int", int(text.replace("_", "")))
    if kind == "REAL":
        return Value("real", float(text.replace("_", "")))
    if kind == "BOOL":
        return Value("int", 1 if text.upper() == "TRUE" else 0)
    if kind == "STRING":
        return Value("chars", text=text)
    prefix, _, body = text.partition("#")
    upper = prefix.upper()
    if upper in ("2", "8", "16"):
        return Value("int", int(body.replace("_", ""), int(upper)))
    if upper == "B" and body.startswith("("):  # B#(1, 2): bytes, the first one highest
        number = 0
        for part in body.strip("()").split(","):
            number = number << 8 | int(part.strip())
        return Value("int", number)
    if upper in _INT_PREFIXES and body.startswith("'"):
        chars = unquote_chars(body)  # BYTE#'a': the character's code
        return Value("int", ord(chars)) if len(chars) == 1 else None
    if upper in _INT_PREFIXES:
        return _literal("INTEGER" if "#" not in body else "TYPED", body)
    if upper in ("REAL", "LREAL"):
        return Value("real", float(body.replace("_", "")))
    if upper in ("LT", "LTIME"):  # in nanoseconds (``nasaq.lang.s7_1500_values``)
        return Value("int", ltime_ns(body, text))
    if upper == "BOOL":
        inner = body.upper()
        return Value("int", 1 if inner in ("TRUE", "1") else 0)
    if upper == "CHAR" and body.replace("_", "").isdigit():
        return Value("int", int(body.replace("_", "")))  # CHAR#49: the character of code 49
    if upper == "CHAR":
        return Value("chars", text=body)
    if upper in ("STRING", "WSTRING"):  # TIA's STRING#'text', WSTRING#'text'
        return Value("chars", text=body)
    if upper == "WCHAR":  # its UTF-16 code unit
        units = unquote_chars(body).encode("utf-16-be", errors="surrogatepass")
        return Value("int", int.from_bytes(units, "big")) if len(units) == 2 else None
    if upper == "C":
        return Value("int", int(body.replace("_", "")))
    if upper in _TIME_PREFIXES:
        return Value(_TIME_PREFIXES[upper], text=body.replace("_", "").upper())
    return None


def dt_body(text: str) -> str:
    """``95-1-1-12:00`` → ``1995-1-1-12:00``: a DATE_AND_TIME's two-digit year 90-99 is 19xx,
    00-89 is 20xx (STL's ``DT#`` takes four digits)."""
    year, _, rest = text.partition("-")
    if len(year) <= 2 and year.isdigit():
        number = int(year)
        year = str(1900 + number if number >= 90 else 2000 + number)
    return f"{year}-{rest}"


def stl_constant(value: Value, want: str) -> tuple[str, str]:
    """``value`` written as an STL constant of type ``want`` (an elementary type name)."""
    if value.kind == "chars" and want == "WCHAR":  # one UTF-16 code unit
        text = value.text if value.text.startswith("'") else f"'{value.text}'"
        units = unquote_chars(text).encode("utf-16-be", errors="surrogatepass")
        if len(units) == 2:
            return "TYPED", f"W#16#{int.from_bytes(units, 'big'):04X}"
    if value.kind == "chars":
        return "CHARS", value.text
    if value.kind in _STL_PREFIX:
        if want == "S5TIME" and value.kind == "TIME":
            return "TYPED", "S5T#" + value.text
        if value.kind == "DATE_AND_TIME":
            return "TYPED", "DT#" + dt_body(value.text)
        return "TYPED", _STL_PREFIX[value.kind] + value.text
    if want == "REAL" or value.kind == "real":
        return "REAL", _real_text(float(value.number))
    number = int(value.number)
    if want == "BOOL":
        return "IDENT", "TRUE" if number else "FALSE"
    if want == "INT":
        if -32768 <= number <= 32767:
            return "NUMBER", str(number)
        return "TYPED", f"W#16#{number & 0xFFFF:X}"
    if want in ("BYTE", "CHAR"):
        return "TYPED", f"B#16#{number & 0xFF:X}"
    if want == "WORD":
        return "TYPED", f"W#16#{number & 0xFFFF:X}"
    if want == "DWORD":
        return "TYPED", f"DW#16#{number & 0xFFFFFFFF:X}"
    if want == "TIME":
        return "TYPED", f"T#{number}MS" if number >= 0 else f"T#-{-number}MS"
    if want in ("DINT", "DATE", "TIME_OF_DAY"):
        return "TYPED", f"L#{number}"
    if -32768 <= number <= 32767:
        return "NUMBER", str(number)
    return "TYPED", f"L#{number}"


def _real_text(number: float) -> str:
    text = repr(float(number))
    if "inf" in text or "nan" in text:
        return "3.402823e+38" if number > 0 else "-3.402823e+38"
    if "e" not in text and "." not in text:
        text += ".0"
    return text
