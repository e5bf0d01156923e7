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
from nasaq.lang.types import Field, elementary

Body = Callable[[bytearray, int, int], int]

TIME_MASK = 0x7FFFFFFF  # the system time (TIME_TCK) counts 0 .. 2**31 - 1 ms

NAMES: dict[int, str] = SFB_NAMES


def _layout(number: int) -> tuple[list[Variable], int]:
    """The instance variables of SFB ``number`` and the instance size in bytes."""
    sections: dict[str, list[Field]] = {}
    for section, name, type_name in SFB_INTERFACES[number]:
        found = elementary(type_name)
        assert found is not None, type_name
        sections.setdefault(section, []).append(Field(name, found))
    slots, bits = Layout(lambda _block: None).instance(list(sections.items()))
    return variables(slots), bits // 8


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


_I16 = struct.Struct(">h")
_I32 = struct.Struct(">i")
_U32 = struct.Struct(">I")
_get_int, _put_int = _I16.unpack_from, _I16.pack_into
_get_dint, _put_dint = _I32.unpack_from, _I32.pack_into
_get_time, _put_time = _U32.unpack_from, _U32.pack_into


def _bit(buf: bytearray, base: int, address: int) -> int:
    return buf[base + (address >> 3)] >> (address & 7) & 1


def _set(buf: bytearray, base: int, address: int, value: int) -> None:
    byte, mask = base + (address >> 3), 1 << (address & 7)
    buf[byte] = buf[byte] | mask if value else buf[byte] & ~mask


# -- counters -------------------------------------------------------------------------------------
_CTU_CU, _CTU_R, _CTU_PV, _CTU_Q, _CTU_CV, _CTU_CUO = _at(0, "CU", "R", "PV", "Q", "CV", "CUO")
_CTD_CD, _CTD_LOAD, _CTD_PV, _CTD_Q, _CTD_CV, _CTD_CDO = _at(
    1, "CD", "LOAD", "PV", "Q", "CV", "CDO"
)
(_UD_CU, _UD_CD, _UD_R, _UD_LOAD, _UD_PV, _UD_QU, _UD_QD, _UD_CV, _UD_CUO, _UD_CDO) = _at(
    2, "CU", "CD", "R", "LOAD", "PV", "QU", "QD", "CV", "CUO", "CDO"
)


def ctu(buf: bytearray, base: int, now: int) -> int:
    """SFB 0 CTU: count up on a rising edge of CU; R resets (and wins)."""
    cu = _bit(buf, base, _CTU_CU)
    edge = cu and not _bit(buf, base, _CTU_CUO)
    _set(buf, base, _CTU_CUO, cu)
    cv = _get_int(buf, base + _CTU_CV)[0]
    if _bit(buf, base, _CTU_R):
        cv = 0
    elif edge and cv < 32767:
        cv += 1
    _put_int(buf, base + _CTU_CV, cv)
    _set(buf, base, _CTU_Q, cv >= _get_int(buf, base + _CTU_PV)[0])
    return 1


def ctd(buf: bytearray, base: int, now: int) -> int:
    """SFB 1 CTD: count down on a rising edge of CD; LOAD presets CV to PV (and wins)."""
    cd = _bit(buf, base, _CTD_CD)
    edge = cd and not _bit(buf, base, _CTD_CDO)
    _set(buf, base, _CTD_CDO, cd)
    cv = _get_int(buf, base + _CTD_CV)[0]
    if _bit(buf, base, _CTD_LOAD):
        cv = _get_int(buf, base + _CTD_PV)[0]
    elif edge and cv > -32768:
        cv -= 1
    _put_int(buf, base + _CTD_CV, cv)
    _set(buf, base, _CTD_Q, cv <= 0)
    return 1


def ctud(buf: bytearray, base: int, now: int) -> int:
    """SFB 2 CTUD: R before LOAD before counting; edges at CU and CD together cancel."""
    cu, cd = _bit(buf, base, _UD_CU), _bit(buf, base, _UD_CD)
    up = cu and not _bit(buf, base, _UD_CUO)
    down = cd and not _bit(buf, base, _UD_CDO)
    _set(buf, base, _UD_CUO, cu)
    _set(buf, base, _UD_CDO, cd)
    cv = _get_int(buf, base + _UD_CV)[0]
    pv = _get_int(buf, base + _UD_PV)[0]
    if _bit(buf, base, _UD_R):
        cv = 0
    elif _bit(buf, base, _UD_LOAD):
        cv = pv
    elif up and not down and cv < 32767:
        cv += 1
    elif down and not up and cv > -32768:
        cv -= 1
    _put_int(buf, base + _UD_CV, cv)
    _set(buf, base, _UD_QU, cv >= pv)
    _set(buf, base, _UD_QD, cv <= 0)
    return 1


# -- timers (TP, TON and TOF share one layout) ----------------------------------------------------
_TIMER_MEMBERS = ("IN", "PT", "Q", "ET", "STATE", "STIME", "ATIME")
_IN, _PT, _Q, _ET, _STATE, _STIME, _ATIME = _at(4, *_TIMER_MEMBERS)
assert _at(3, *_TIMER_MEMBERS) == _at(5, *_TIMER_MEMBERS) == _at(4, *_TIMER_MEMBERS)

RUNNING = 0x01  # TP, TON: the time is running
EXPIRED = 0x02  # TP, TON: the time has expired, the outputs hold until IN is 0
PREV_IN = 0x01  # TOF: IN was 1 at the previous call
DELAYING = 0x02  # TOF: the off delay is running


def _reset(buf: bytearray, base: int, pt: int) -> int:
    """PT <= 0: Q = 0, ET = 0, STATE = 0; PT = 0 also clears IN (the initialising call), a
    negative PT is an error (BR = 0)."""
    if pt == 0:
        _set(buf, base, _IN, 0)
    _set(buf, base, _Q, 0)
    _put_dint(buf, base + _ET, 0)
    buf[base + _STATE] = 0
    return 1 if pt == 0 else 0


def _elapsed(buf: bytearray, base: int, now: int) -> int:
    """Time since STIME, across the wrap of the system time; ATIME := now."""
    _put_time(buf, base + _ATIME, now)
    start: int = _get_time(buf, base + _STIME)[0]
    return (now - start) & TIME_MASK


def tp(buf: bytearray, base: int, now: int) -> int:
    """SFB 3 TP: a pulse of length PT on a rising edge of IN, not retriggerable."""
    pt = _get_dint(buf, base + _PT)[0]
    if pt <= 0:
        return _reset(buf, base, pt)
    state = buf[base + _STATE]
    on = _bit(buf, base, _IN)
    if on and not state & (RUNNING | EXPIRED):
        _put_time(buf, base + _STIME, now)
        state = RUNNING
    if state & RUNNING:
        et = _elapsed(buf, base, now)
        if et >= pt:
            et, state = pt, EXPIRED
        _set(buf, base, _Q, state & RUNNING)
        _put_dint(buf, base + _ET, et)
    if not on and state & EXPIRED:
        state = 0
        _put_dint(buf, base + _ET, 0)
    buf[base + _STATE] = state
    return 1


def ton(buf: bytearray, base: int, now: int) -> int:
    """SFB 4 TON: Q after IN has been 1 for PT; IN = 0 resets."""
    pt = _get_dint(buf, base + _PT)[0]
    if pt <= 0:
        return _reset(buf, base, pt)
    state = buf[base + _STATE]
    if _bit(buf, base, _IN):
        if not state & (RUNNING | EXPIRED):
            _put_time(buf, base + _STIME, now)
            state = RUNNING
        if state & RUNNING:
            et = _elapsed(buf, base, now)
            if et >= pt:
                et, state = pt, EXPIRED
            _set(buf, base, _Q, state & EXPIRED)
            _put_dint(buf, base + _ET, et)
    else:
        state = 0
        _set(buf, base, _Q, 0)
        _put_dint(buf, base + _ET, 0)
    buf[base + _STATE] = state
    return 1


def tof(buf: bytearray, base: int, now: int) -> int:
    """SFB 5 TOF: Q = 1 while IN, falls PT after IN falls; IN = 1 resets the delay."""
    pt = _get_dint(buf, base + _PT)[0]
    if pt <= 0:
        return _reset(buf, base, pt)
    state = buf[base + _STATE]
    if _bit(buf, base, _IN):
        state = PREV_IN
        _set(buf, base, _Q, 1)
        _put_dint(buf, base + _ET, 0)
    else:
        if state & PREV_IN:  # falling edge: the delay starts
            _put_time(buf, base + _STIME, now)
            state = DELAYING
        if state & DELAYING:
            et = _elapsed(buf, base, now)
            if et >= pt:
                et, state = pt, 0
            _set(buf, base, _Q, state & DELAYING)
            _put_dint(buf, base + _ET, et)
    buf[base + _STATE] = state
    return 1


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
