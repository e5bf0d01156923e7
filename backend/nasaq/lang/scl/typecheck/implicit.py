"""TIA Portal's implicit conversions on S7-1200/1500 with the block property "IEC check" off,
TIA's default for new blocks (Nasaq has no such property and behaves as with it off).

The table is TIA Portal's help, "Implicit conversions (S7-1500, S7-1200 G2)", one table per
source type, column "Without IEC check" (COMPATIBILITY.md, "Implicit conversions (implicit)"):
- BOOL converts to nothing, and nothing converts to BOOL (``IF #dint THEN`` stays ``SCL220``);
- every integer and bit string (BYTE ... LWORD, SINT ... ULINT) converts to every other one,
  wider or narrower: a bit string counts as the unsigned integer of its width (WORD as UINT), a
  narrower target keeps the low bits (INT -1 into a USINT is 255, UINT 60000 into an INT
  -5536), an integer into a wider bit string is its bit pattern filled with zeros;
- REAL/LREAL into every integer, rounded half to even, the value wrapping as the integer's bits
  (REAL 305.5 → INT 306 → USINT 50); REAL into DWORD and LREAL into LWORD are the bit
  pattern; DWORD into REAL and LWORD into LREAL the unsigned value; LREAL into REAL rounded;
  integers into REAL/LREAL (those TIA does with the IEC check on: what ``types.widens`` and
  ``s7_1500_types.widens`` already take, plus DINT/UDINT/LINT/ULINT into REAL, LINT/ULINT
  into LREAL);
- CHAR/WCHAR from and to the integers and bit strings (the code, zero-filled), STRING into
  CHAR (the first character);
- TIME and TIME_OF_DAY from and to DINT, UDINT and DWORD (milliseconds, the bit pattern), LTIME
  from and to LINT, ULINT and LWORD (nanoseconds), LTIME into TIME.
In an expression TIA computes with a bit string as with the unsigned integer of its width
(``DINT + WORD`` is ``DINT + UINT``, a DINT), and a logic operation takes an integer as the bit
string of its width (``INT XOR INT`` is a WORD operation, ``UDINT AND DWORD`` a DWORD one).

TIA marks a conversion that can change a value (its "light grey rectangle"; with the IEC check
on it would be refused) and compiles it: Nasaq compiles it too and says so with the warning
``SCL705`` at the converted value. The checker makes each accepted conversion explicit in the
tree (``wrap``: the value becomes the ``*_TO_*`` call the conversion equals, ``INT_TO_USINT(#i)``),
so the code generator compiles exactly what an explicit conversion compiles. S7-SCL Classic
(S7-300/400) keeps its own rules (``types``): nothing here applies under those profiles.
"""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING

from nasaq.lang import s7_1500_types as s7_1500
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import CONVERSIONS, IntConst, Type, scalar, widens
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

# A bit string as the unsigned integer of its width, and an integer as the bit string of its.
AS_UNSIGNED = {"BYTE": "USINT", "WORD": "UINT", "DWORD": "UDINT", "LWORD": "ULINT"}
AS_BITS = {
    "SINT": "BYTE",
    "USINT": "BYTE",
    "INT": "WORD",
    "UINT": "WORD",
    "DINT": "DWORD",
    "UDINT": "DWORD",
    "LINT": "LWORD",
    "ULINT": "LWORD",
}
BITS = frozenset(AS_UNSIGNED)
INTEGERS = frozenset(AS_BITS)
FLOATS = frozenset({"REAL", "LREAL"})
CHARS = frozenset({"CHAR", "WCHAR"})
_CODE = {"CHAR": "BYTE", "WCHAR": "WORD"}
_WIDTH = {
    "BYTE": 8,
    "SINT": 8,
    "USINT": 8,
    "CHAR": 8,
    "WORD": 16,
    "INT": 16,
    "UINT": 16,
    "WCHAR": 16,
    "DWORD": 32,
    "DINT": 32,
    "UDINT": 32,
    "REAL": 32,
    "LWORD": 64,
    "LINT": 64,
    "ULINT": 64,
    "LREAL": 64,
}
# The pairs TIA also converts with the IEC check on (its "dark grey" mark): nothing is lost.
_LOSSLESS_FLOAT = frozenset({("UDINT", "LREAL"), ("DINT", "LREAL"), ("REAL", "LREAL")})
# Times into the integers that hold every value of theirs (a time of day is never negative).
_LOSSLESS_TIME = frozenset(
    {("TIME_OF_DAY", "DINT"), ("TIME_OF_DAY", "UDINT"), ("TIME_OF_DAY", "DWORD")}
    | {("LTIME", "LINT"), ("LINT", "LTIME")}
)
_LOGIC = frozenset({"AND", "&", "OR", "XOR"})
_ARITHMETIC = frozenset({"+", "-", "*", "/", "DIV", "MOD", "=", "<>", "<", ">", "<=", ">="})


@cache  # a few hundred name pairs at most
def conversion(source: str, goal: str) -> tuple[str, ...] | None:
    """The explicit conversions (innermost first) TIA's implicit conversion of a ``source``
    into a ``goal`` equals, without the IEC check; () when no code is needed (the conversions
    S7-SCL already makes silently), None when TIA does not convert implicitly."""
    if source == goal or widens(source, goal):
        return ()
    chain = _chain(source, goal)
    if chain is None or any(name not in CONVERSIONS for name in chain):
        return None
    return chain


def _chain(source: str, goal: str) -> tuple[str, ...] | None:
    numbers = INTEGERS | BITS
    if source in numbers and goal in numbers:
        if goal in BITS:  # an integer into a bit string: its own width, then zero-filled
            own = AS_BITS.get(source, source)
            if _WIDTH[goal] > _WIDTH[own]:
                return (f"{source}_TO_{own}",) if own != source else ()
        direct = _name(source, goal)
        return (direct,) if direct else None
    if source in FLOATS and goal in INTEGERS:  # rounded half to even, then the low bits
        wide = "DINT" if _WIDTH[goal] <= 32 and goal != "UDINT" else "LINT"
        first = f"{source}_TO_{wide}"
        return (first,) if goal == wide else (first, f"{wide}_TO_{goal}")
    if (source, goal) in (("REAL", "DWORD"), ("LREAL", "LWORD"), ("LREAL", "REAL")):
        return (f"{source}_TO_{goal}",)  # the bit pattern; LREAL rounded to REAL
    if (source, goal) in (("DWORD", "REAL"), ("LWORD", "LREAL")):
        unsigned = AS_UNSIGNED[source]
        return (f"{source}_TO_{unsigned}", f"{unsigned}_TO_{goal}")
    if source in INTEGERS and goal in FLOATS:
        return (f"{source}_TO_{goal}",)  # DINT → REAL: rounded to REAL's 24 bits
    if (source in CHARS and goal in numbers) or (source in numbers and goal in CHARS):
        direct = _name(source, goal)  # else through the bit string of the character's code
        return (direct,) if direct else _via_code(source, goal)
    if (source, goal) == ("STRING", "CHAR"):
        return ("STRING_TO_CHAR",)
    return _time_chain(source, goal)


# The times with the integers of their width (the bit pattern: TIME and TOD milliseconds in a
# DINT, LTIME nanoseconds in a LINT): TIME/TOD with DINT, UDINT, DWORD; LTIME with LINT, ULINT,
# LWORD; LTIME into TIME (the tables of TIME, TOD, LTIME and of those integers).
_TIMES = {"TIME": "DINT", "TIME_OF_DAY": "DINT", "LTIME": "LINT"}
_TIME_PARTNERS = {"DINT": ("DINT", "UDINT", "DWORD"), "LINT": ("LINT", "ULINT", "LWORD")}
_SHORT = {"TIME_OF_DAY": "TOD"}


def _time_chain(source: str, goal: str) -> tuple[str, ...] | None:
    if (source, goal) == ("LTIME", "TIME"):
        return ("LTIME_TO_TIME",)
    if source in _TIMES and goal in _TIME_PARTNERS[_TIMES[source]]:
        base = _TIMES[source]
        first = f"{_SHORT.get(source, source)}_TO_{base}"
        return (first,) if goal == base else (first, f"{base}_TO_{goal}")
    if goal in _TIMES and source in _TIME_PARTNERS[_TIMES[goal]]:
        base = _TIMES[goal]
        last = f"{base}_TO_{_SHORT.get(goal, goal)}"
        return (last,) if source == base else (f"{source}_TO_{base}", last)
    return None


def _name(source: str, goal: str) -> str | None:
    name = f"{source}_TO_{goal}"
    return name if name in CONVERSIONS else None


def _via_code(source: str, goal: str) -> tuple[str, ...]:
    """A character from or into a number without a function of its own: as the bit string
    of its code (BYTE for a CHAR, WORD for a WCHAR), zero-filled or cut to the low bits."""
    if source in CHARS:
        code = _CODE[source]
        return (
            (f"{source}_TO_{code}", f"{code}_TO_{goal}")
            if goal != code
            else (f"{source}_TO_{code}",)
        )
    code = _CODE[goal]
    first = f"{source}_TO_{code}"
    return (first, f"{code}_TO_{goal}") if source != code else (f"{code}_TO_{goal}",)


@cache
def lossless(source: str, goal: str) -> bool:
    """Whether every value of ``source`` arrives unchanged in ``goal`` (TIA's "dark grey"
    mark: a bit string counts as its unsigned integer); the other implicit conversions get the
    warning ``SCL705``."""
    if widens(source, goal) or (source in BITS and goal in BITS and _WIDTH[source] < _WIDTH[goal]):
        return True
    if (source, goal) in _LOSSLESS_TIME:
        return True
    low, high = _range(source) or (1, 0)
    if goal in FLOATS:  # exact up to the mantissa: 24 bits (REAL), 53 (LREAL)
        limit = 2**24 if goal == "REAL" else 2**53
        return source == "REAL" or (low <= high and -limit <= low and high <= limit)
    goal_range = _range(goal)
    return goal_range is not None and low <= high and goal_range[0] <= low and high <= goal_range[1]


def _range(name: str) -> tuple[int, int] | None:
    return s7_1500.INTEGER_RANGES.get(AS_UNSIGNED.get(name, name))


def accepts(ctx: Context, value: Type, goal: Type, node: ast.Expr) -> ast.Expr | None:
    """The value ``node`` (of type ``value``) converted into a ``goal`` as TIA converts it
    implicitly under the S7-1500 profile (and the warning reported where a value may change);
    None when TIA does not convert it (the caller reports its error)."""
    if not is_s7_1500(ctx.index.profile) or type(goal) is not Elementary:
        return None
    if type(value) is IntConst:
        return _constant(ctx, value.value, goal.name, node)
    source = scalar(value)
    if source is None or type(value) is not Elementary:
        return None
    chain = conversion(source, goal.name)
    if chain is None:
        return None
    if not lossless(source, goal.name):
        ctx.report("SCL705", node.loc, actual=source, expected=goal.name)
    return wrap(ctx, node, chain)


def _constant(ctx: Context, number: int, goal: str, node: ast.Expr) -> ast.Expr | None:
    """An integer constant out of ``goal``'s range that fits its width as a bit pattern (``-1``
    into a USINT, TIA's SINT#-1 → USINT): that pattern, with the warning naming the value."""
    limits = s7_1500.INTEGER_RANGES.get(goal)
    width = _WIDTH.get(goal)
    if limits is None or width is None or not -(2 ** (width - 1)) <= number < 2**width:
        return None
    stored = number & (2**width - 1)
    if limits[0] < 0 and stored >= 2 ** (width - 1):
        stored -= 2**width
    ctx.report("SCL706", node.loc, value=number, type=goal, stored=stored)
    literal = ast.Literal("INTEGER", str(abs(stored)), loc=node.loc)
    replaced: ast.Expr = literal if stored >= 0 else ast.Unary("-", literal, loc=node.loc)
    ctx.type_of(replaced)
    return replaced


def wrap(ctx: Context, node: ast.Expr, chain: tuple[str, ...]) -> ast.Expr:
    """``node`` inside the calls of ``chain`` (innermost first), typed: what replaces it in the
    tree so that the code generator compiles the conversion."""
    for name in chain:
        node = ast.Call(ast.Name(name, loc=node.loc), [ast.Arg(None, node, loc=node.loc)], node.loc)
        ctx.type_of(node)
    return node


def operand_types(op: str, left: str, right: str) -> tuple[str, str] | None:
    """The types TIA computes ``left op right`` in when S7-SCL's rules have none (S7-1500):
    a bit string as its unsigned integer next to a number, an integer as its bit string in a
    logic operation. None when TIA has no such reading either."""
    if op in _LOGIC:
        a, b = AS_BITS.get(left, left), AS_BITS.get(right, right)
        ok = a in BITS and b in BITS and (a, b) != (left, right)
        return (a, b) if ok else None
    if op in _ARITHMETIC:
        numbers = INTEGERS | FLOATS
        if (left in BITS and right in numbers) or (left in numbers and right in BITS):
            return AS_UNSIGNED.get(left, left), AS_UNSIGNED.get(right, right)
    return None


def convert_operands(ctx: Context, node: ast.Binary, types: tuple[str, str]) -> None:
    """Makes the operands of ``node`` the types ``operand_types`` gave (in the tree)."""
    have = (scalar(ctx.type_of(node.left)), scalar(ctx.type_of(node.right)))
    for side, (old, new) in zip(("left", "right"), zip(have, types, strict=True), strict=True):
        if old is None or old == new:
            continue
        chain = conversion(old, new) or ()
        setattr(node, side, wrap(ctx, getattr(node, side), chain))


__all__ = ["accepts", "conversion", "convert_operands", "lossless", "operand_types", "wrap"]
