"""RUNTIME, RESET_TIMER and PRESET_TIMER (``nasaq.lang.tia_timing``) in S7-SCL code.

RESET_TIMER and PRESET_TIMER are compiled in line on the timer's instance data, wherever it is
(an instance DB, a multi-instance, a member of a structure, an FC parameter): its address into
AR1 (``references.locate``), then Q, ET and the running state cleared (RESET_TIMER: the timer is
as before its first call; an IN still TRUE starts it again at its next call), or PT written
(PRESET_TIMER). RUNTIME is ``CALL SFC 780 (MEM := m, RET_VAL := value)``: its body reads the
CPU's clock (``nasaq.cpu.tia_control``).
"""

from __future__ import annotations

from functools import cache

from nasaq.lang.layout import Layout, Slot
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.long_functions import LongFunctions
from nasaq.lang.scl.lower.places import LoweringError
from nasaq.lang.scl.lower.references import Result
from nasaq.lang.scl.typecheck.types import DbRef
from nasaq.lang.stl import ast as stl
from nasaq.lang.system_types import system_fb_sections
from nasaq.lang.tia_control import RUNTIME_SFC
from nasaq.lang.types import Elementary

_TON = 4  # TP, TON and TOF share one layout (``nasaq.cpu.iec_blocks``)


@cache
def timer_offsets() -> dict[str, int]:
    """Bit offsets of the members of an IEC timer's instance data."""
    sections = system_fb_sections(_TON)
    assert sections is not None
    slots: list[Slot] = Layout(lambda _block: None).instance(sections)[0]
    return {slot.name: slot.offset_bits for slot in slots}


class TiaTiming(LongFunctions):
    def call_value(self, node: ast.Call) -> None:
        name = self.standard_name(node)
        if name in ("RESET_TIMER", "PRESET_TIMER"):
            self.timer_instruction(node, name)
            return
        if name == "RUNTIME":  # as a statement: the value is dropped
            temp = self.em.temp(Elementary("LREAL"))
            self.runtime(node, temp)
            self.em.release(temp)
            return
        super().call_value(node)

    def long_value(self, node: ast.Expr, kind: str, have: str | None, result: Result) -> None:
        runtime = isinstance(node, ast.Call) and self.standard_name(node) == "RUNTIME"
        if runtime and have == kind == "LREAL":
            assert isinstance(node, ast.Call)
            self.runtime(node, result)
            return
        super().long_value(node, kind, have, result)

    def runtime(self, node: ast.Call, result: Result) -> None:
        em = self.em
        mem = self.parameter(node, "RUNTIME", "MEM")
        access = self.access(mem)
        if not self.direct(access):
            raise LoweringError(mem.loc, "this MEM of RUNTIME")
        target = em.ref(result) if isinstance(result, Temp) else result
        args = [em.arg("MEM", self.operand(access, mem.loc)), em.arg("RET_VAL", target)]
        em.call([stl.AddressNode(f"SFC {RUNTIME_SFC}", node.loc)], args)

    def timer_instruction(self, node: ast.Call, name: str) -> None:
        em = self.em
        offsets = timer_offsets()
        duration: Temp | None = None
        if name == "PRESET_TIMER":
            duration = em.temp(Elementary("TIME"))
            self.load_value(self.parameter(node, name, "PT"), "TIME")
            em.op("T", em.ref(duration))
        timer = self.parameter(node, name, "TIMER")
        whole = self.type_of(timer)
        place = None
        if isinstance(whole, DbRef) and whole.number is not None:  # an IEC timer's instance DB
            em.op("OPN", em.address(f"DB {whole.number}"))
            em.op("L", em.literal("TYPED", "DW#16#84000000"))  # P#DBX 0.0, area-crossing
            em.op("LAR1")
        else:
            place = self.place_of(timer)
            self.reach(place)
        if duration is not None:
            em.op("L", em.ref(duration))
            em.op("T", self.at("D", offsets["PT"] // 8))
            em.release(duration)
        else:
            em.op("L", em.literal("TYPED", "L#0"))
            em.op("T", self.at("D", offsets["ET"] // 8))
            em.op("T", self.at("B", offsets["STATE"] // 8))
            em.op("CLR")
            em.op("=", self._bit(offsets["Q"]))
        if place is not None:
            self.release_place(place)

    def _bit(self, offset_bits: int) -> stl.IndirectNode:
        loc = self.em.loc
        pointer = stl.LiteralNode("POINTER", f"P#{offset_bits // 8}.{offset_bits % 8}", loc)
        return stl.IndirectNode(None, stl.BareNode("AR1", None, loc), pointer, loc)
