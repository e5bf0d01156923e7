"""The formal parameters of what SCL code calls: user FCs and FBs (their IN, OUT and IN_OUT
sections), the IEC timers and counters (``system_blocks.SFB_INTERFACES``), and the S5 timer and
counter functions, whose signatures are kept here, in one place (seeds-003b §2.13, §2.14).

Every call also takes ``EN`` (BOOL input) and ``ENO`` (BOOL output), §2.11.

Which parameters must be supplied (S7-SCL, as STEP 7's CALL):
- an FC: every parameter (inputs, in/outs and outputs);
- an FB: none, except in/outs of a type passed by reference (STRING, ARRAY, STRUCT, UDT,
  DATE_AND_TIME), which have no value of their own in the instance;
- an S5 timer/counter function: the timer/counter number ``T_NO``/``C_NO``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from nasaq.ir import BlockKind
from nasaq.lang.scl.bind import IEC_INSTANCES, SclBlock, SclIndex
from nasaq.lang.system_blocks import SFB_INTERFACES, SFB_NAMES
from nasaq.lang.system_types import parse as parse_type
from nasaq.lang.types import BlockType, DataType, Elementary, is_reference

PARAMETER_SECTIONS = ("IN", "OUT", "IN_OUT")
BOOL = Elementary("BOOL")
IEC_NAMES = {number: name for name, number in IEC_INSTANCES.items()}


@dataclass(frozen=True, slots=True)
class Param:
    """A formal parameter. ``types``: the declared type first, then other types it accepts
    (``T_NO`` takes a TIMER or an INT timer number)."""

    name: str
    section: str  # IN, OUT or IN_OUT
    types: tuple[DataType, ...]
    required: bool = False
    bcd: bool = False  # a BCD word (a counter's PV): a decimal constant is taken as its bits


@dataclass(frozen=True, slots=True)
class Signature:
    """``label`` names the callee in messages; ``kind`` FC, FB, SFB or FUNCTION (a standard
    function); ``params`` by casefolded name; ``result`` the function value (None: none)."""

    label: str
    kind: str
    params: dict[str, Param]
    result: DataType | None = None

    def inputs(self) -> list[Param]:
        """The input parameters, without EN (and without another name of one: TIA's
        ``LEN(IN := s)`` for FC 21's S, ``nasaq.lang.scl.typecheck.library.ALIASES``)."""
        return [
            p
            for key, p in self.params.items()
            if p.section == "IN" and p.name != "EN" and key == p.name.casefold()
        ]


def _signature(
    label: str, kind: str, params: list[Param], result: DataType | None = None
) -> Signature:
    found = {param.name.casefold(): param for param in params}
    found.setdefault("en", Param("EN", "IN", (BOOL,)))
    found.setdefault("eno", Param("ENO", "OUT", (BOOL,)))
    return Signature(label, kind, found, result)


def of_block(block: SclBlock) -> Signature:
    """An SCL FC's or FB's parameters."""
    params: list[Param] = []
    for section in PARAMETER_SECTIONS:
        for declared in block.fields(section):
            required = block.kind is BlockKind.FC or (
                section == "IN_OUT" and is_reference(declared.type)
            )
            params.append(Param(declared.name, section, (declared.type,), required))
    return _signature(block.label, block.kind.value, params, block.return_type)


def of_instance(index: SclIndex, instance: BlockType) -> Signature | None:
    """The parameters of the FB or SFB an instance belongs to; None when they are unknown."""
    if instance.kind == "SFB":
        return _system(instance.number)
    block = index.get(BlockKind.FB, instance.number) if instance.kind == "FB" else None
    return of_block(block) if block is not None else None


@cache  # a system FB's interface is fixed: one signature each, shared (read, never changed)
def _system(number: int) -> Signature | None:
    interface = SFB_INTERFACES.get(number)
    if interface is None:
        return None
    params = [
        Param(name, section, (parse_type(type_name),))
        for section, name, type_name in interface
        if section in PARAMETER_SECTIONS
    ]
    return _signature(IEC_NAMES.get(number, SFB_NAMES.get(number, f"SFB {number}")), "SFB", params)


def _s5(name: str, number: str, area: str, inputs: list[str], outputs: list[str]) -> Signature:
    word, result = Elementary("WORD"), Elementary("S5TIME" if number == "T_NO" else "WORD")
    params = [Param(number, "IN", (Elementary(area), Elementary("INT")), True)]
    for parameter in inputs:
        if parameter == "TV":
            params.append(Param(parameter, "IN", (Elementary("S5TIME"), word)))
        elif parameter == "PV":
            params.append(Param(parameter, "IN", (word,), bcd=True))
        else:
            params.append(Param(parameter, "IN", (BOOL,)))
    params += [Param(output, "OUT", (BOOL if output == "Q" else word,)) for output in outputs]
    return _signature(name, "FUNCTION", params, result)


_TIMER = (["S", "TV", "R"], ["Q", "BI"])
S5_FUNCTIONS = {
    "S_PULSE": _s5("S_PULSE", "T_NO", "TIMER", *_TIMER),
    "S_PEXT": _s5("S_PEXT", "T_NO", "TIMER", *_TIMER),
    "S_ODT": _s5("S_ODT", "T_NO", "TIMER", *_TIMER),
    "S_ODTS": _s5("S_ODTS", "T_NO", "TIMER", *_TIMER),
    "S_OFFDT": _s5("S_OFFDT", "T_NO", "TIMER", *_TIMER),
    "S_CU": _s5("S_CU", "C_NO", "COUNTER", ["CU", "S", "PV", "R"], ["Q", "CV"]),
    "S_CD": _s5("S_CD", "C_NO", "COUNTER", ["CD", "S", "PV", "R"], ["Q", "CV"]),
    "S_CUD": _s5("S_CUD", "C_NO", "COUNTER", ["CU", "CD", "S", "PV", "R"], ["Q", "CV"]),
}
"""The S5 timer and counter functions: result S5TIME (timers) or WORD (counters), in BCD."""
