"""TIA Portal's timing instructions without an instance (S7-1200/1500): ``RUNTIME(MEM := m)``,
the seconds (LREAL) since the previous call that stored its time stamp in ``m``;
``RESET_TIMER(TIMER := t)``, an IEC timer (IEC_TIMER, TON_TIME, TP_TIME, TOF_TIME or one of
TON/TP/TOF) back to its state before the first call (Q FALSE, ET 0, not running); and
``PRESET_TIMER(PT := d, TIMER := t)``, the duration PT of such a timer set to d.

The checker reads their signatures here; the SCL compiler lowers RESET_TIMER and PRESET_TIMER in
line (``lang/scl/lower/tia_timing.py``) and RUNTIME to a call of SFC 780, Nasaq's number for it
(``nasaq.lang.tia_control``), whose body reads the CPU's clock (``nasaq.cpu.tia_control``).
"""

from __future__ import annotations

from nasaq.lang.types import BlockType, DataType, Elementary

NAMES = frozenset({"RUNTIME", "RESET_TIMER", "PRESET_TIMER"})
LREAL = Elementary("LREAL")
TIME = Elementary("TIME")
# The IEC timers an instance of which RESET_TIMER and PRESET_TIMER take (SFB 3 TP, 4 TON, 5 TOF:
# TIA's IEC_TIMER, TON_TIME ... are laid out as these).
TIMERS: tuple[DataType, ...] = (BlockType("SFB", 4), BlockType("SFB", 3), BlockType("SFB", 5))
# name -> ((formal, section, accepted types) ..., result)
PARAMETERS: dict[str, tuple[tuple[tuple[str, str, tuple[DataType, ...]], ...], DataType | None]] = {
    "RUNTIME": ((("MEM", "IN_OUT", (LREAL,)),), LREAL),
    "RESET_TIMER": ((("TIMER", "IN_OUT", TIMERS),), None),
    "PRESET_TIMER": ((("PT", "IN", (TIME,)), ("TIMER", "IN_OUT", TIMERS)), None),
}
