"""The mnemonic → emitter table, assembled from the instruction family modules."""

from __future__ import annotations

from nasaq.cpu.codegen import (
    accumulators,
    address_registers,
    bit_logic,
    calls,
    compare,
    convert,
    integer_math,
    jumps,
    load_transfer,
    mcr,
    real_math,
    shifts,
    test_ops,
    timers,
    word_logic,
)
from nasaq.cpu.codegen.model import Emitter

EMITTERS: dict[str, Emitter] = {}
for _family in (
    bit_logic,
    load_transfer,
    accumulators,
    integer_math,
    real_math,
    compare,
    convert,
    word_logic,
    shifts,
    jumps,
    mcr,
    calls,
    address_registers,
    test_ops,
    timers,
):
    EMITTERS.update(_family.EMITTERS)

# Instructions that end a basic block.
TERMINATORS = frozenset({*jumps.JUMPS, "BE", "BEU", "BEC"})
