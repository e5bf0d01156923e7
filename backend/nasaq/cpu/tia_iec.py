"""What the typed IEC counters and the LTIME timers of TIA Portal (``nasaq.lang.tia_iec``, SFB
1200-1223 in Nasaq) do: bodies ``(buf, base, now) -> BR`` on the instance data, made by the
``counter`` and ``timer`` of ``nasaq.cpu.iec_blocks`` that also make SFB 0-5 (it merges
``BODIES``).

They behave as SFB 0-5 do (the S7-1200/1500 system manuals describe the same operation for
every count type), with the limits of their type: a counter does not count beyond its type's
highest value nor below its lowest (0 for the unsigned ones; a CTD_UDINT at 0 stays at 0, and
its Q = CV <= 0 is then TRUE). CTUD: R before LD before counting, edges at CU and CD in one call
cancel. The LTIME timers count the CPU's millisecond system time into nanoseconds: ET grows in
steps of 1 ms (1 000 000 ns) up to PT; PT = 0 resets the timer, a negative PT too, with ENO
FALSE.
"""

from __future__ import annotations

from nasaq.cpu.iec_blocks import Body, counter, timer
from nasaq.lang.tia_iec import KINDS

_NS_PER_MS = 1_000_000  # LTIME counts ns; the system time STIME and ATIME keep counts ms

BODIES: dict[int, Body] = {
    number: timer(number, instruction, ">q", _NS_PER_MS)
    if kind == "LTIME"
    else counter(number, instruction, kind)
    for number, (instruction, kind) in KINDS.items()
}
