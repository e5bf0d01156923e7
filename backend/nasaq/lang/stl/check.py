"""Operand rules per instruction: which operands each international op accepts (area, size,
constant range). The parser accepts any mnemonic with any operands, so this module is where
``A MW 10``, ``= IW 0``, ``SP C 1``, ``T PIB 0``/``L PQW 0`` and ``INC 300`` are caught.
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    Constant,
    ConstType,
    CounterRef,
    Direct,
    MemoryIndirect,
    MultiInstance,
    ParamRef,
    Register,
    RegisterIndirect,
    StatusCondition,
    TimerRef,
    Width,
)
from nasaq.lang.stl.constants import NOT_LOADABLE
from nasaq.lang.stl.resolve import Resolved
from nasaq.lang.types import Elementary, width_of

_WIDTH_KIND = {Width.BIT: "bit", Width.BYTE: "byte", Width.WORD: "word", Width.DWORD: "dword"}
_PARAM_KIND = {
    "TIMER": "timer",
    "COUNTER": "counter",
    "BLOCK_DB": "db",
    "BLOCK_FC": "code",
    "BLOCK_FB": "code",
}
_TARGET_KIND = {
    "T": "timer",
    "C": "counter",
    "DB": "db",
    "DI": "db",
    "FC": "code",
    "FB": "code",
    "SFC": "code",
    "SFB": "code",
}
DESCRIBE = {
    "bit": "a bit address",
    "byte": "a byte",
    "word": "a word",
    "dword": "a double word",
    "const": "a constant",
    "timer": "a timer",
    "counter": "a counter",
    "register": "a register",
    "status": "a status bit",
    "db": "a data block",
    "code": "an FC or FB",
    "label": "a label",
    "multi": "a multi-instance",
}

JUMPS = frozenset(
    [
        "JU",
        "JC",
        "JCN",
        "JCB",
        "JNB",
        "JBI",
        "JNBI",
        "JO",
        "JOS",
        "JZ",
        "JN",
        "JP",
        "JM",
        "JPZ",
        "JMZ",
        "JUO",
        "JL",
        "LOOP",
    ]
)
_BIT_READ = frozenset({"bit", "timer", "counter", "status"})
_DATA = frozenset({"byte", "word", "dword"})


@dataclass(frozen=True, slots=True)
class Rule:
    kinds: frozenset[str]
    optional: bool = False


def _rules() -> dict[str, Rule]:
    rules: dict[str, Rule] = {}
    for op in ("A", "AN", "ON", "X", "XN"):
        rules[op] = Rule(_BIT_READ)
    rules["O"] = Rule(_BIT_READ, optional=True)
    rules["="] = Rule(frozenset({"bit"}))
    rules["S"] = Rule(frozenset({"bit", "counter"}))
    rules["R"] = Rule(frozenset({"bit", "counter", "timer"}))
    for op in ("FP", "FN"):
        rules[op] = Rule(frozenset({"bit"}))
    for op in ("SP", "SE", "SD", "SS", "SF"):
        rules[op] = Rule(frozenset({"timer"}))
    for op in ("CU", "CD"):
        rules[op] = Rule(frozenset({"counter"}))
    for op in ("FR", "LC"):
        rules[op] = Rule(frozenset({"timer", "counter"}))
    rules["L"] = Rule(_DATA | {"const", "timer", "counter", "register"})
    rules["T"] = Rule(_DATA | {"register"})
    for op in ("INC", "DEC", "BLD", "NOP", "+", "__SLEEP", "__FEATURE"):
        rules[op] = Rule(frozenset({"const"}))
    for op in (
        "AW",
        "OW",
        "XOW",
        "AD",
        "OD",
        "XOD",
        "SSI",
        "SSD",
        "SLW",
        "SRW",
        "SLD",
        "SRD",
        "RLD",
        "RRD",
        "+AR1",
        "+AR2",
    ):
        rules[op] = Rule(frozenset({"const"}), optional=True)
    for op in ("UC", "CC"):
        rules[op] = Rule(frozenset({"code"}))
    rules["OPN"] = Rule(frozenset({"db"}))
    rules["LAR1"] = Rule(frozenset({"const", "dword", "register"}), optional=True)
    rules["LAR2"] = Rule(frozenset({"const", "dword"}), optional=True)
    rules["TAR1"] = Rule(frozenset({"dword", "register"}), optional=True)
    rules["TAR2"] = Rule(frozenset({"dword"}), optional=True)
    return rules


RULES = _rules()
_CONST_RANGE = {
    "INC": (0, 255),
    "DEC": (0, 255),
    "BLD": (0, 255),
    "NOP": (0, 1),
}
_TEST_REGISTERS = frozenset({"ACCU1", "ACCU2", "ACCU3", "ACCU4", "AR1", "AR2"})
_REGISTERS_OF = {
    "T": frozenset({"STW"}),
    "L": frozenset({"STW", "DBNO", "DBLG", "DINO", "DILG"}) | _TEST_REGISTERS,
    "LAR1": frozenset({"AR2"}),
    "TAR1": frozenset({"AR2"}),
}
# STEP 7's shift counts; awlsim accepts larger ones, so exceeding them is only a warning.
SHIFT_LIMITS = {
    "SSI": 15,
    "SLW": 15,
    "SRW": 15,
    "SSD": 32,
    "SLD": 32,
    "SRD": 32,
    "RLD": 32,
    "RRD": 32,
}
_WORD_CONSTANTS = frozenset(
    {ConstType.WORD, ConstType.BYTE, ConstType.BYTES, ConstType.INT, ConstType.CHAR}
)
_DWORD_CONSTANTS = _WORD_CONSTANTS | {ConstType.DWORD, ConstType.DINT}


# The kind of the operands whose class alone tells it.
_KIND_OF_CLASS: dict[type, str] = {
    Constant: "const",
    TimerRef: "timer",
    CounterRef: "counter",
    StatusCondition: "status",
    Register: "register",
    MultiInstance: "multi",
}


def kind_of(resolved: Resolved) -> str:
    operand = resolved.operand
    kind = _KIND_OF_CLASS.get(type(operand))
    if kind is not None:
        return kind
    if isinstance(operand, Direct | RegisterIndirect):
        return _WIDTH_KIND[operand.width]
    if isinstance(operand, MemoryIndirect):
        if operand.target is not None:
            return _TARGET_KIND.get(operand.target, "code")
        return _WIDTH_KIND[operand.width] if operand.width is not None else "bit"
    if isinstance(operand, ParamRef):
        if operand.width is not None:
            return _WIDTH_KIND[operand.width]
        name = resolved.type.name if isinstance(resolved.type, Elementary) else ""
        return _PARAM_KIND.get(name, "structured")
    if isinstance(operand, BlockRef):
        return "db" if operand.kind in (BlockKind.DB, BlockKind.DI) else "code"
    return "other"  # pragma: no cover - every operand kind is listed above


def expected_text(kinds: frozenset[str]) -> str:
    order = [
        "bit",
        "byte",
        "word",
        "dword",
        "const",
        "timer",
        "counter",
        "register",
        "status",
        "db",
        "code",
        "label",
    ]
    names = [DESCRIBE[kind] for kind in order if kind in kinds]
    return " or ".join(names)


Problem = tuple[str, dict[str, object]]


def check_operand(op: str, resolved: Resolved) -> Problem | None:
    """None when ``resolved`` suits ``op``; else a diagnostic code and its parameters."""
    rule = RULES.get(op)
    if rule is None:
        return "STL203", {"mnemonic": op}
    kind = kind_of(resolved)
    data_type = resolved.type
    not_elementary = (
        data_type is not None
        and width_of(data_type) is None
        and kind in ("bit", "byte", "word", "dword")
    )
    if kind == "structured" or not_elementary:
        type_name = data_type.name if isinstance(data_type, Elementary) else "a structured type"
        return "STL228", {"name": resolved.text, "type": type_name}
    operand = resolved.operand
    if isinstance(operand, Register) and operand.name.startswith("STW.") and "status" in rule.kinds:
        return None  # test mode: a status bit read like any bit (__STW A0)
    if isinstance(operand, Constant):
        if kind not in rule.kinds:
            return _wrong(op, resolved, rule)
        return _check_constant(op, operand, resolved.text)
    if kind not in rule.kinds:
        return _wrong(op, resolved, rule)
    area = getattr(operand, "area", None)
    if (op == "L" and area is Area.PQ) or (op == "T" and area is Area.PI):
        return _wrong(op, resolved, rule)
    if isinstance(operand, Register) and operand.name not in _REGISTERS_OF.get(op, ()):
        return _wrong(op, resolved, rule)
    return None


def _wrong(op: str, resolved: Resolved, rule: Rule) -> Problem:
    return "STL204", {
        "mnemonic": op,
        "operand": resolved.text,
        "expected": expected_text(rule.kinds),
    }


def _check_constant(op: str, constant: Constant, text: str) -> Problem | None:
    if constant.type in NOT_LOADABLE:
        return "STL107", {"text": text, "reason": NOT_LOADABLE[constant.type]}
    if op == "L":  # the common case first
        return _wrong_constant(op, text) if constant.type is ConstType.BOOL else None
    if op in _CONST_RANGE:
        low, high = _CONST_RANGE[op]
        if constant.type is not ConstType.INT or not low <= int(constant.value) <= high:
            return "STL214", {"text": text, "type": op, "hint": f" ({low} to {high})"}
        return None
    if op in SHIFT_LIMITS:
        if constant.type is not ConstType.INT or not 0 <= int(constant.value) <= 255:
            return "STL214", {"text": text, "type": op, "hint": " (0 to 255)"}
        if int(constant.value) > SHIFT_LIMITS[op]:
            return "STL237", {"text": text, "mnemonic": op, "limit": SHIFT_LIMITS[op]}
        return None
    if op == "+":
        fits = constant.type in (ConstType.INT, ConstType.DINT)
    elif op in ("AW", "OW", "XOW"):
        fits = constant.type in _WORD_CONSTANTS and constant.pattern <= 0xFFFF
    elif op in ("AD", "OD", "XOD"):
        fits = constant.type in _DWORD_CONSTANTS
    elif op in ("LAR1", "LAR2", "+AR1", "+AR2"):
        fits = constant.type is ConstType.POINTER
    else:
        fits = True
    return None if fits else _wrong_constant(op, text)


def _wrong_constant(op: str, text: str) -> Problem:
    return "STL204", {"mnemonic": op, "operand": text, "expected": "another constant"}
