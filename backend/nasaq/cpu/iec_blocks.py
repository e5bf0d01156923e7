"""The IEC counters and timers of the S7-300/400: SFB 0 CTU, 1 CTD, 2 CTUD, 3 TP, 4 TON, 5 TOF;
and IEC's edge detectors R_TRIG (SFB 1000) and F_TRIG (SFB 1001), numbered by Nasaq.

Each block is a pure function ``body(buf, base, now) -> BR`` on its instance data: ``buf`` is
the instance DB (the DI register during the call), ``base`` the byte where the instance starts
(0 for an instance DB, the offset of a multi-instance), ``now`` the CPU's system time in ms as
TIME_TCK reads it (31 bits, wraps round to 0 after 2**31 - 1). The body reads the inputs and
the static data from the instance and writes outputs and static data back, as the code of an FB
would: ``nasaq.cpu.calls`` copies the actuals into the instance before and out of it after the
call, so a parameter not supplied keeps its value in the instance. The result is BR (ENO).

The offsets come from ``nasaq.lang.system_blocks``, laid out once, at import, by the compiler's
own layout (so they are those of the instance DBs and multi-instances the compiler makes: TP,
TON and TOF 22 bytes, CTU, CTD and CTUD 10).

Behaviour (System Software for S7-300/400, System and Standard Functions, chapter 25):

- CTU: a rising edge at CU (against CUO, the value CU had at the previous call) counts CV up,
  not beyond 32767; R = 1 sets CV to 0 whatever CU does. Q = CV >= PV.
- CTD: a rising edge at CD (against CDO) counts down, not below -32768; LOAD = 1 sets CV to PV
  whatever CD does. Q = CV <= 0.
- CTUD: R = 1 sets CV to 0 (over LOAD, CU and CD), else LOAD = 1 sets CV to PV, else a rising
  edge counts up (CU) or down (CD) within -32768..32767; rising edges at both in one call leave
  CV as it is (the manual's documented deviation from IEC 1131-3). QU = CV >= PV, QD = CV <= 0.
  The edge memories CUO/CDO take the input's value at every call, whatever R and LOAD do.
- TP: a rising edge at IN (IN = 1 while the timer is neither running nor expired) starts a pulse:
  Q = 1 until PT has elapsed, ET counts up to PT; a new edge during the pulse is ignored. After
  the pulse ET keeps PT while IN = 1 and goes to 0 when IN is 0.
- TON: IN = 1 starts the timer; Q = 1 once IN has been 1 for PT, ET counts up to PT and keeps it;
  IN = 0 resets Q and ET.
- TOF: IN = 1 sets Q = 1 and ET = 0; a falling edge of IN starts the timer, Q falls when PT has
  elapsed, ET counts up to PT and keeps it until IN is 1 again.
- Timers read PT at every call: while a timer runs, a changed PT counts from the same start (a
  shorter PT than the time already elapsed ends it at this call). Once expired, a TON or TP
  keeps its outputs until IN falls.
- PT = 0 resets the timer (Q = 0, ET = 0, STATE = 0, and IN in the instance := 0), as the manual
  says to do in OB100 after a warm restart; a negative PT ("PT must be positive") does the same
  without touching IN, and gives BR = 0.
- R_TRIG/F_TRIG: CLK input, Q output, M the value CLK had at the previous call (FALSE at
  first, so R_TRIG sees an edge at a first call with CLK = 1 and F_TRIG none at a first call with
  CLK = 0, as IEC 61131-3 and TIA Portal's instructions do).
- STATE (bit 0 running, bit 1 expired for TP/TON; bit 0 previous IN, bit 1 delaying for TOF),
  STIME (start time) and ATIME (time of the last call while running) use awlsim's encoding; what
  a real CPU keeps there is not documented. Elapsed time is ``(ATIME - STIME) mod 2**31``, so a
  timer runs across the wrap of the system time as long as it is called at least once every
  2**31 ms (about 24.8 days).
"""

from __future__ import annotations

import struct
from collections.abc import Callable

from nasaq.ir import Variable
from nasaq.lang.layout import Layout, variables
from nasaq.lang.system_blocks import F_TRIG_SFB, R_TRIG_SFB, SFB_INTERFACES, SFB_NAMES
from nasaq.lang.system_types import fields, system_fb_sections
from nasaq.lang.types import BlockType, Field

Body = Callable[[bytearray, int, int], int]

TIME_MASK = 0x7FFFFFFF  # the system time (TIME_TCK) counts 0 .. 2**31 - 1 ms

NAMES: dict[int, str] = SFB_NAMES


def _layout(number: int) -> tuple[list[Variable], int]:
    """The instance variables of SFB ``number`` and the instance size in bytes."""
    slots, bits = Layout(_expand).instance(fields(SFB_INTERFACES[number]))
    return variables(slots), bits // 8


def _expand(block: BlockType) -> list[tuple[str, list[Field]]] | None:
    """A system FB inside a system FB's instance (an IEC_TIMER member): its sections."""
    return system_fb_sections(block.number) if block.kind == "SFB" else None


_LAYOUTS = {number: _layout(number) for number in NAMES}

INTERFACES: dict[int, list[Variable]] = {n: layout[0] for n, layout in _LAYOUTS.items()}
INSTANCE_BYTES: dict[int, int] = {n: layout[1] for n, layout in _LAYOUTS.items()}


def _at(number: int, *names: str) -> tuple[int, ...]:
    """Byte offsets (BOOLs: bit address, byte * 8 + bit) of the named members of SFB ``number``."""
    found = {v.name: v for v in INTERFACES[number]}
    return tuple(
        found[name].offset_bits if found[name].type == "BOOL" else found[name].offset_bits // 8
        for name in names
    )


_U32 = struct.Struct(">I")
_get_time, _put_time = _U32.unpack_from, _U32.pack_into  # STIME, ATIME: the system time


def _bit(buf: bytearray, base: int, address: int) -> int:
    return buf[base + (address >> 3)] >> (address & 7) & 1


def _set(buf: bytearray, base: int, address: int, value: int) -> None:
    byte, mask = base + (address >> 3), 1 << (address & 7)
    buf[byte] = buf[byte] | mask if value else buf[byte] & ~mask


# -- counters and timers: one body per instruction, made for a layout and a value type -------------
# SFB 0-5 (INT counters, TIME timers) and TIA Portal's typed counters and LTIME timers
# (``nasaq.cpu.tia_iec``) are the same operations on other widths, so both are made here.

_VALUE_FORMATS = {
    "SINT": ">b",
    "USINT": ">B",
    "INT": ">h",
    "UINT": ">H",
    "DINT": ">i",
    "UDINT": ">I",
    "LINT": ">q",
    "ULINT": ">Q",
}


def _offsets(number: int) -> dict[str, int]:
    """Member offsets of SFB ``number``: BOOLs as bit addresses, others as bytes."""
    return {
        v.name: v.offset_bits if v.type == "BOOL" else v.offset_bits // 8
        for v in INTERFACES[number]
    }


def counter(number: int, instruction: str, kind: str, load: str = "LD") -> Body:
    """The body of counter SFB ``number`` (``CTU``, ``CTD`` or ``CTUD``) counting in ``kind``
    within its range; ``load`` names the preset input (SFB 1/2: LOAD, TIA's: LD)."""
    at = _offsets(number)
    value = struct.Struct(_VALUE_FORMATS[kind])
    bits = value.size * 8
    low, high = (
        (0, (1 << bits) - 1) if kind.startswith("U") else (-(1 << bits - 1), (1 << bits - 1) - 1)
    )
    get, put = value.unpack_from, value.pack_into
    cv_at, pv_at = at["CV"], at["PV"]
    if instruction == "CTU":
        cu, r, q, cuo = at["CU"], at["R"], at["Q"], at["CUO"]

        def ctu(buf: bytearray, base: int, now: int) -> int:
            """Count up on a rising edge of CU; R resets (and wins)."""
            up = _bit(buf, base, cu)
            edge = up and not _bit(buf, base, cuo)
            _set(buf, base, cuo, up)
            cv = get(buf, base + cv_at)[0]
            if _bit(buf, base, r):
                cv = 0
            elif edge and cv < high:
                cv += 1
            put(buf, base + cv_at, cv)
            _set(buf, base, q, cv >= get(buf, base + pv_at)[0])
            return 1

        return ctu
    if instruction == "CTD":
        cd, ld, q, cdo = at["CD"], at[load], at["Q"], at["CDO"]

        def ctd(buf: bytearray, base: int, now: int) -> int:
            """Count down on a rising edge of CD; the load input presets CV to PV (and wins)."""
            down = _bit(buf, base, cd)
            edge = down and not _bit(buf, base, cdo)
            _set(buf, base, cdo, down)
            cv = get(buf, base + cv_at)[0]
            if _bit(buf, base, ld):
                cv = get(buf, base + pv_at)[0]
            elif edge and cv > low:
                cv -= 1
            put(buf, base + cv_at, cv)
            _set(buf, base, q, cv <= 0)
            return 1

        return ctd
    cu, cd, r, ld = at["CU"], at["CD"], at["R"], at[load]
    qu, qd, cuo, cdo = at["QU"], at["QD"], at["CUO"], at["CDO"]

    def ctud(buf: bytearray, base: int, now: int) -> int:
        """R before the load input before counting; edges at CU and CD together cancel."""
        up_in, down_in = _bit(buf, base, cu), _bit(buf, base, cd)
        up = up_in and not _bit(buf, base, cuo)
        down = down_in and not _bit(buf, base, cdo)
        _set(buf, base, cuo, up_in)
        _set(buf, base, cdo, down_in)
        cv = get(buf, base + cv_at)[0]
        pv = get(buf, base + pv_at)[0]
        if _bit(buf, base, r):
            cv = 0
        elif _bit(buf, base, ld):
            cv = pv
        elif up and not down and cv < high:
            cv += 1
        elif down and not up and cv > low:
            cv -= 1
        put(buf, base + cv_at, cv)
        _set(buf, base, qu, cv >= pv)
        _set(buf, base, qd, cv <= 0)
        return 1

    return ctud


RUNNING = 0x01  # TP, TON: the time is running
EXPIRED = 0x02  # TP, TON: the time has expired, the outputs hold until IN is 0
PREV_IN = 0x01  # TOF: IN was 1 at the previous call
DELAYING = 0x02  # TOF: the off delay is running


def timer(number: int, instruction: str, span: str = ">i", unit: int = 1) -> Body:
    """The body of timer SFB ``number`` (``TP``, ``TON`` or ``TOF``): PT and ET packed as
    ``span`` (TIME: a DINT of ms; LTIME: a LINT of ns), ``unit`` of them per ms of the system
    time, which STIME and ATIME keep."""
    at = _offsets(number)
    get, put = struct.Struct(span).unpack_from, struct.Struct(span).pack_into
    in_, pt_at, q, et_at = at["IN"], at["PT"], at["Q"], at["ET"]
    state_at, stime, atime = at["STATE"], at["STIME"], at["ATIME"]

    def reset(buf: bytearray, base: int, pt: int) -> int:
        """PT <= 0: Q = 0, ET = 0, STATE = 0; PT = 0 also clears IN (the initialising call), a
        negative PT is an error (BR = 0)."""
        if pt == 0:
            _set(buf, base, in_, 0)
        _set(buf, base, q, 0)
        put(buf, base + et_at, 0)
        buf[base + state_at] = 0
        return 1 if pt == 0 else 0

    def elapsed(buf: bytearray, base: int, now: int) -> int:
        """Time since STIME, across the wrap of the system time; ATIME := now."""
        _put_time(buf, base + atime, now)
        begun: int = _get_time(buf, base + stime)[0]
        return ((now - begun) & TIME_MASK) * unit

    def tp(buf: bytearray, base: int, now: int) -> int:
        """A pulse of length PT on a rising edge of IN, not retriggerable."""
        pt = get(buf, base + pt_at)[0]
        if pt <= 0:
            return reset(buf, base, pt)
        state = buf[base + state_at]
        on = _bit(buf, base, in_)
        if on and not state & (RUNNING | EXPIRED):
            _put_time(buf, base + stime, now)
            state = RUNNING
        if state & RUNNING:
            et = elapsed(buf, base, now)
            if et >= pt:
                et, state = pt, EXPIRED
            _set(buf, base, q, state & RUNNING)
            put(buf, base + et_at, et)
        if not on and state & EXPIRED:
            state = 0
            put(buf, base + et_at, 0)
        buf[base + state_at] = state
        return 1

    def ton(buf: bytearray, base: int, now: int) -> int:
        """Q after IN has been 1 for PT; IN = 0 resets."""
        pt = get(buf, base + pt_at)[0]
        if pt <= 0:
            return reset(buf, base, pt)
        state = buf[base + state_at]
        if _bit(buf, base, in_):
            if not state & (RUNNING | EXPIRED):
                _put_time(buf, base + stime, now)
                state = RUNNING
            if state & RUNNING:
                et = elapsed(buf, base, now)
                if et >= pt:
                    et, state = pt, EXPIRED
                _set(buf, base, q, state & EXPIRED)
                put(buf, base + et_at, et)
        else:
            state = 0
            _set(buf, base, q, 0)
            put(buf, base + et_at, 0)
        buf[base + state_at] = state
        return 1

    def tof(buf: bytearray, base: int, now: int) -> int:
        """Q = 1 while IN, falls PT after IN falls; IN = 1 resets the delay."""
        pt = get(buf, base + pt_at)[0]
        if pt <= 0:
            return reset(buf, base, pt)
        state = buf[base + state_at]
        if _bit(buf, base, in_):
            state = PREV_IN
            _set(buf, base, q, 1)
            put(buf, base + et_at, 0)
        else:
            if state & PREV_IN:  # falling edge: the delay starts
                _put_time(buf, base + stime, now)
                state = DELAYING
            if state & DELAYING:
                et = elapsed(buf, base, now)
                if et >= pt:
                    et, state = pt, 0
                _set(buf, base, q, state & DELAYING)
                put(buf, base + et_at, et)
        buf[base + state_at] = state
        return 1

    return {"TP": tp, "TON": ton, "TOF": tof}[instruction]


ctu = counter(0, "CTU", "INT")  # SFB 0
ctd = counter(1, "CTD", "INT", load="LOAD")  # SFB 1
ctud = counter(2, "CTUD", "INT", load="LOAD")  # SFB 2
tp = timer(3, "TP")  # SFB 3
ton = timer(4, "TON")  # SFB 4
tof = timer(5, "TOF")  # SFB 5


# -- edge detectors (IEC 61131-3 R_TRIG and F_TRIG) ----------------------------------------------
_CLK, _EDGE_Q, _EDGE_M = _at(R_TRIG_SFB, "CLK", "Q", "M")


def r_trig(buf: bytearray, base: int, now: int) -> int:
    """R_TRIG: Q = 1 for the one call at which CLK is 1 and was 0 at the previous call (M)."""
    clk = _bit(buf, base, _CLK)
    _set(buf, base, _EDGE_Q, clk and not _bit(buf, base, _EDGE_M))
    _set(buf, base, _EDGE_M, clk)
    return 1


def f_trig(buf: bytearray, base: int, now: int) -> int:
    """F_TRIG: Q = 1 for the one call at which CLK is 0 and was 1 at the previous call (M)."""
    clk = _bit(buf, base, _CLK)
    _set(buf, base, _EDGE_Q, not clk and _bit(buf, base, _EDGE_M))
    _set(buf, base, _EDGE_M, clk)
    return 1


BODIES: dict[int, Body] = {
    0: ctu,
    1: ctd,
    2: ctud,
    3: tp,
    4: ton,
    5: tof,
    R_TRIG_SFB: r_trig,
    F_TRIG_SFB: f_trig,
}

# -- merge points: each module that brings system block bodies adds its line here (it imports
# INTERFACES and Body from this module, which the package loads first) -----------------------------
from nasaq.cpu import tia_control  # noqa: E402  (sysfb: PID_Compact, CTRL_HSC)

BODIES.update(tia_control.BODIES)
from nasaq.cpu import tia_iec  # noqa: E402  (longs: CTU_DINT ..., TON_LTIME ...)

BODIES.update(tia_iec.BODIES)
from nasaq.cpu import tia_filters  # noqa: E402  (filters: Filter_PT1, Filter_DT1, Filter_PT2)

BODIES.update(tia_filters.BODIES)
