"""CPU profiles: the sizes and limits that differ between an S7-300, an S7-400 and an S7-1500.

The numbers model a CPU 315-2 PN/DP (S7-300), a CPU 416-2 (S7-400) and a CPU 1516-3 PN/DP
(S7-1500, standing for the S7-1200/1500 family) closely enough for teaching and for testing real
programs; COMPATIBILITY.md lists where they are rounded. What the compilers accept per profile is
``nasaq.lang.profiles``. ``Profile`` is an
enum (``Profile("S7-300")`` works, as in scenario files) whose members expose their figures.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from enum import Enum


@dataclass(frozen=True, slots=True)
class ProfileSpec:
    accumulators: int  # 2 on the S7-300, 4 on the S7-400
    process_image_bytes: int  # size of the PII and of the PIQ
    peripheral_bytes: int  # addressable PI/PQ bytes (every address there has a module)
    marker_bytes: int  # M area
    timers: int
    counters: int
    nesting_depth: int  # block calls per priority class (the OB is level 1)
    lstack_bytes: int  # local data per priority class
    pq_updates_piq: bool  # T PQW also writes the PIQ when the address is inside it (S7-300)
    ns_per_instruction: int  # nominal cost of one instruction for the cycle watchdog


_SPECS: dict[str, ProfileSpec] = {
    "S7-300": ProfileSpec(
        accumulators=2,
        process_image_bytes=2048,
        peripheral_bytes=2048,
        marker_bytes=2048,
        timers=256,
        counters=256,
        nesting_depth=16,
        lstack_bytes=2048,
        pq_updates_piq=True,
        ns_per_instruction=100,
    ),
    "S7-400": ProfileSpec(
        accumulators=4,
        process_image_bytes=8192,
        peripheral_bytes=8192,
        marker_bytes=16384,
        timers=2048,
        counters=2048,
        nesting_depth=24,
        lstack_bytes=16384,
        pq_updates_piq=False,
        ns_per_instruction=50,
    ),
}
# CPU 1516-3 PN/DP, an S7-400 in what STL sees (four accumulators, T PQ does not write the
# process image, its timers, counters, bit memory and nesting depth) with a 32 KB I/O address
# space (process images as large), 64 KB local data per priority class (rounded from the data
# sheet's per-class figure) and 10 ns per bit instruction.
_SPECS["S7-1500"] = replace(
    _SPECS["S7-400"],
    process_image_bytes=32768,
    peripheral_bytes=32768,
    lstack_bytes=65536,
    ns_per_instruction=10,
)


class Profile(Enum):
    S7_300 = "S7-300"
    S7_400 = "S7-400"
    S7_1500 = "S7-1500"

    @property
    def spec(self) -> ProfileSpec:
        return _SPECS[self.value]

    @property
    def accumulators(self) -> int:
        return self.spec.accumulators

    @property
    def process_image_bytes(self) -> int:
        return self.spec.process_image_bytes

    @property
    def peripheral_bytes(self) -> int:
        return self.spec.peripheral_bytes

    @property
    def marker_bytes(self) -> int:
        return self.spec.marker_bytes

    @property
    def timers(self) -> int:
        return self.spec.timers

    @property
    def counters(self) -> int:
        return self.spec.counters

    @property
    def nesting_depth(self) -> int:
        return self.spec.nesting_depth

    @property
    def lstack_bytes(self) -> int:
        return self.spec.lstack_bytes

    @property
    def pq_updates_piq(self) -> bool:
        return self.spec.pq_updates_piq

    @property
    def ns_per_instruction(self) -> int:
        return self.spec.ns_per_instruction
