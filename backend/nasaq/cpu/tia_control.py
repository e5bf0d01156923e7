"""What TIA Portal's PID_Compact (V1.x, SFB 1100 in Nasaq) and CTRL_HSC (SFB 1101) do on the
simulated CPU: bodies ``(buf, base, now) -> BR`` on the instance data, as the IEC timers'
(``nasaq.cpu.iec_blocks``, which merges ``BODIES``). The interfaces are
``nasaq.lang.tia_control``'s.

PID_Compact (S7-1200/1500 PID control manual, "PID_Compact V1"), a PIDT1 controller:

    y = Kp * [ (b*w - x) + 1/(Ti*s) * (w - x) + Td*s / (a*Td*s + 1) * (c*w - x) ]

with Kp, Ti, Td, a, b, c the active parameters ``sRet.r_Ctrl_Gain/Ti/Td/A/B/C`` (Ti = 0: no
integral action; Td = 0: no derivative action), discretised with the measured time between two
calls (the CPU's virtual system time; the previous ``sPid_Calc.r_Cycle`` when two calls fall in
the same millisecond), which is kept in ``sPid_Calc.r_Cycle``.

- Process value x: ``Input``, or with ``sPid_Cmpt.b_Input_PER_On`` ``Input_PER`` (an INT)
  scaled linearly from r_Pv_Norm_IN_1/2 to r_Pv_Norm_OUT_1/2; ``ScaledInput`` shows it.
  Outside r_Pv_Llm .. r_Pv_Hlm: Error 16#0001 and "Inactive". InputWarning_H/L against
  r_Pv_HWrn/LWrn.
- Setpoint w limited to r_Sp_Llm .. r_Sp_Hlm (SetpointLimit_H/L).
- Output limited to r_Lmn_Llm .. r_Lmn_Hlm, with anti-windup: the integral action does not grow
  while the output is at a limit in the direction it pushes. ``b_InvCtrl`` inverts the action.
  Output_PER = Output * 27648 / 100 (an INT word).
- Modes (State): 0 Inactive (Output 0), 3 Automatic, 4 Manual (Output = ManualValue within
  the limits). ``sRet.i_Mode`` switches the mode on a change (edge), as the manual says; at the
  first call the mode is i_Mode when ``sb_RunModeByStartup``, else Inactive. ``ManualEnable``
  = TRUE is manual mode while it is TRUE; afterwards the previous mode continues bumplessly
  (the integral action takes the output over). ``Reset`` = TRUE: Inactive, Error cleared;
  its falling edge restarts in the mode of i_Mode.
- Not simulated (COMPATIBILITY.md, "sysfb"): pretuning and fine tuning (i_Mode 1 and 2 run
  automatic mode with the active parameters, State 3), the cycle-time monitoring (Error
  16#0800), PWM (Output_PWM stays FALSE).

RUNTIME (SFC 780 in Nasaq): RET_VAL := seconds since the time stamp MEM holds, MEM := now, both
LREAL seconds of the CPU's virtual system time (millisecond steps; the first call measures from
the CPU's start, as MEM starts at 0).

CTRL_HSC: the simulated CPU has no high-speed counter: every call answers STATUS 16#80A1
("the HSC identifier does not address an HSC", as a real CPU answers for an HSC that is
not there), BUSY = FALSE and BR (ENO) = 0. Nothing is counted or loaded.
"""

from __future__ import annotations

import math
import struct

from nasaq.cpu.iec_blocks import INTERFACES, Body
from nasaq.ir import Variable
from nasaq.lang.tia_control import CTRL_HSC, PID_COMPACT, RUNTIME_SFC

_REAL = struct.Struct(">f")
_INT = struct.Struct(">h")
_DINT = struct.Struct(">i")
_WORD = struct.Struct(">H")
_DWORD = struct.Struct(">I")
REAL_LIMIT = 3.4028234663852886e38

INACTIVE, PRETUNING, FINE_TUNING, AUTOMATIC, MANUAL = 0, 1, 2, 3, 4
ERROR_INPUT_LIMITS = 0x0001  # the process value is outside its limits
ERROR_INVALID_INPUT = 0x0200  # Input is not a valid REAL
ERROR_INVALID_SETPOINT = 0x1000  # Setpoint is not a valid REAL
NO_HSC = 0x80A1  # CTRL_HSC: no high-speed counter at this identifier


def _find(variables: list[Variable], path: str) -> Variable:
    head, _, rest = path.partition(".")
    found = next(v for v in variables if v.name == head)
    return _find(found.members, rest) if rest else found


def _at(number: int, *paths: str) -> tuple[int, ...]:
    """Byte offsets (BOOLs: bit addresses) of members of SFB ``number`` (dotted paths)."""
    found = [_find(INTERFACES[number], path) for path in paths]
    return tuple(v.offset_bits if v.type == "BOOL" else v.offset_bits // 8 for v in found)


def _bit(buf: bytearray, base: int, address: int) -> bool:
    return bool(buf[base + (address >> 3)] >> (address & 7) & 1)


def _set(buf: bytearray, base: int, address: int, value: bool) -> None:
    byte, mask = base + (address >> 3), 1 << (address & 7)
    buf[byte] = buf[byte] | mask if value else buf[byte] & ~mask


def _real(buf: bytearray, base: int, at: int) -> float:
    value: float = _REAL.unpack_from(buf, base + at)[0]
    return value


def _put_real(buf: bytearray, base: int, at: int, value: float) -> None:
    _REAL.pack_into(buf, base + at, max(-REAL_LIMIT, min(REAL_LIMIT, value)))


def _int(buf: bytearray, base: int, at: int) -> int:
    value: int = _INT.unpack_from(buf, base + at)[0]
    return value


# -- PID_Compact -----------------------------------------------------------------------------------
(
    _SETPOINT,
    _INPUT,
    _INPUT_PER,
    _MANUAL_ENABLE,
    _MANUAL_VALUE,
    _RESET,
    _SCALED_INPUT,
    _OUTPUT,
    _OUTPUT_PER,
    _OUTPUT_PWM,
    _SP_LIMIT_H,
    _SP_LIMIT_L,
    _WARN_H,
    _WARN_L,
    _STATE,
    _ERROR,
    _RUN_BY_STARTUP,
) = _at(
    PID_COMPACT,
    "Setpoint",
    "Input",
    "Input_PER",
    "ManualEnable",
    "ManualValue",
    "Reset",
    "ScaledInput",
    "Output",
    "Output_PER",
    "Output_PWM",
    "SetpointLimit_H",
    "SetpointLimit_L",
    "InputWarning_H",
    "InputWarning_L",
    "State",
    "Error",
    "sb_RunModeByStartup",
)
(_CYCLE, _ISUM, _DPART, _DIN_OLD, _TICK, _MODE_OLD, _FIRST) = _at(
    PID_COMPACT,
    "sPid_Calc.r_Cycle",
    "sPid_Calc.r_Isum_N",
    "sPid_Calc.r_Dpart_N",
    "sPid_Calc.r_PvOld_N",
    "sPid_Calc.d_Tick_N",
    "sPid_Calc.i_ModeOld_N",
    "sPid_Calc.b_First_N",
)
(_SP_HLM, _SP_LLM, _NORM_IN_1, _NORM_IN_2, _NORM_OUT_1, _NORM_OUT_2) = _at(
    PID_COMPACT,
    "sPid_Cmpt.r_Sp_Hlm",
    "sPid_Cmpt.r_Sp_Llm",
    "sPid_Cmpt.r_Pv_Norm_IN_1",
    "sPid_Cmpt.r_Pv_Norm_IN_2",
    "sPid_Cmpt.r_Pv_Norm_OUT_1",
    "sPid_Cmpt.r_Pv_Norm_OUT_2",
)
(_LMN_HLM, _LMN_LLM, _PER_ON, _INVERT, _PV_HLM, _PV_LLM, _PV_HWRN, _PV_LWRN) = _at(
    PID_COMPACT,
    "sPid_Cmpt.r_Lmn_Hlm",
    "sPid_Cmpt.r_Lmn_Llm",
    "sPid_Cmpt.b_Input_PER_On",
    "sPid_Cmpt.b_InvCtrl",
    "sPid_Cmpt.r_Pv_Hlm",
    "sPid_Cmpt.r_Pv_Llm",
    "sPid_Cmpt.r_Pv_HWrn",
    "sPid_Cmpt.r_Pv_LWrn",
)
(_I_MODE, _GAIN, _TI, _TD, _A, _B, _C, _RET_CYCLE) = _at(
    PID_COMPACT,
    "sRet.i_Mode",
    "sRet.r_Ctrl_Gain",
    "sRet.r_Ctrl_Ti",
    "sRet.r_Ctrl_Td",
    "sRet.r_Ctrl_A",
    "sRet.r_Ctrl_B",
    "sRet.r_Ctrl_C",
    "sRet.r_Ctrl_Cycle",
)
_RESET_OLD, _AUTO = _at(PID_COMPACT, "sPid_Calc.b_ResetOld_N", "sPid_Calc.i_Auto_N")


def _process_value(buf: bytearray, base: int) -> float:
    if not _bit(buf, base, _PER_ON):
        return _real(buf, base, _INPUT)
    raw = _int(buf, base, _INPUT_PER)
    in_1, in_2 = _real(buf, base, _NORM_IN_1), _real(buf, base, _NORM_IN_2)
    out_1, out_2 = _real(buf, base, _NORM_OUT_1), _real(buf, base, _NORM_OUT_2)
    if in_2 == in_1:
        return out_1
    return out_1 + (raw - in_1) * (out_2 - out_1) / (in_2 - in_1)


def _sample_time(buf: bytearray, base: int, now: int) -> float:
    """Seconds since the previous call (the stored cycle when none has passed), stored."""
    last: int = _DINT.unpack_from(buf, base + _TICK)[0]
    _DINT.pack_into(buf, base + _TICK, now)
    elapsed = (now - last) & 0x7FFFFFFF
    cycle = _real(buf, base, _CYCLE)
    if _bit(buf, base, _FIRST) or elapsed == 0:
        return cycle if cycle > 0 else 0.1
    seconds = elapsed / 1000.0
    _put_real(buf, base, _CYCLE, seconds)
    return seconds


def _write_output(buf: bytearray, base: int, value: float) -> None:
    _put_real(buf, base, _OUTPUT, value)
    per = round(value * 27648.0 / 100.0)
    _INT.pack_into(buf, base + _OUTPUT_PER, max(-32768, min(32767, per)))
    _set(buf, base, _OUTPUT_PWM, False)


def _mode(buf: bytearray, base: int) -> int:
    """The mode after this call's requests (i_Mode edges, Reset), without ManualEnable."""
    state = _int(buf, base, _AUTO)
    i_mode = _int(buf, base, _I_MODE)
    old = _int(buf, base, _MODE_OLD)
    reset = _bit(buf, base, _RESET)
    reset_old = _bit(buf, base, _RESET_OLD)
    _set(buf, base, _RESET_OLD, reset)
    _INT.pack_into(buf, base + _MODE_OLD, i_mode)
    if old == -1:  # the first call after a download or a start
        state = i_mode if _bit(buf, base, _RUN_BY_STARTUP) else INACTIVE
    elif i_mode != old or (reset_old and not reset):
        state = i_mode
    if reset:
        state = INACTIVE
    if state in (PRETUNING, FINE_TUNING):  # tuning is not simulated: automatic mode
        state = AUTOMATIC
    return state if state in (INACTIVE, AUTOMATIC, MANUAL) else INACTIVE


def pid_compact(buf: bytearray, base: int, now: int) -> int:
    """PID_Compact V1.x (see the module doc)."""
    dt = _sample_time(buf, base, now)
    state = _mode(buf, base)
    error = 0  # the errors pending at this call
    x = _process_value(buf, base)
    w = _real(buf, base, _SETPOINT)
    _put_real(buf, base, _SCALED_INPUT, x)
    sp_high, sp_low = _real(buf, base, _SP_HLM), _real(buf, base, _SP_LLM)
    _set(buf, base, _SP_LIMIT_H, w >= sp_high)
    _set(buf, base, _SP_LIMIT_L, w <= sp_low)
    w = min(sp_high, max(sp_low, w))
    _set(buf, base, _WARN_H, x >= _real(buf, base, _PV_HWRN))
    _set(buf, base, _WARN_L, x <= _real(buf, base, _PV_LWRN))
    if not math.isfinite(x):
        error |= ERROR_INVALID_INPUT
    elif not _real(buf, base, _PV_LLM) <= x <= _real(buf, base, _PV_HLM):
        error |= ERROR_INPUT_LIMITS
    if not math.isfinite(w):
        error |= ERROR_INVALID_SETPOINT
    if error and state == AUTOMATIC:
        state = INACTIVE  # V1: an error in automatic mode stops the controller
    _INT.pack_into(buf, base + _AUTO, state)
    if _bit(buf, base, _MANUAL_ENABLE) and not _bit(buf, base, _RESET):
        state = MANUAL  # while ManualEnable is TRUE; then the mode before it again
    high, low = _real(buf, base, _LMN_HLM), _real(buf, base, _LMN_LLM)
    gain = _real(buf, base, _GAIN) * (-1.0 if _bit(buf, base, _INVERT) else 1.0)
    ti, td = _real(buf, base, _TI), _real(buf, base, _TD)
    a, b, c = _real(buf, base, _A), _real(buf, base, _B), _real(buf, base, _C)
    d_in = c * w - x
    p_part = gain * (b * w - x)
    d_part = 0.0
    if td > 0.0 and not _bit(buf, base, _FIRST):
        t1 = a * td
        change = d_in - _real(buf, base, _DIN_OLD)
        d_part = (t1 * _real(buf, base, _DPART) + gain * td * change) / (t1 + dt)
    isum = _real(buf, base, _ISUM)
    if state == INACTIVE:
        output, isum, d_part = 0.0, 0.0, 0.0
    elif state == MANUAL:
        output = min(high, max(low, _real(buf, base, _MANUAL_VALUE)))
        isum = output - p_part - d_part  # so that automatic mode continues from here
    else:
        grown = isum + gain * dt / ti * (w - x) if ti > 0.0 else isum
        total = p_part + grown + d_part
        if total > high:  # anti-windup: the integral does not push further beyond a limit
            grown = min(grown, max(isum, high - p_part - d_part))
        elif total < low:
            grown = max(grown, min(isum, low - p_part - d_part))
        isum = grown
        output = min(high, max(low, p_part + isum + d_part))
    _write_output(buf, base, output)
    _put_real(buf, base, _ISUM, isum)
    _put_real(buf, base, _DPART, d_part)
    _put_real(buf, base, _DIN_OLD, d_in)
    _set(buf, base, _FIRST, False)
    _put_real(buf, base, _RET_CYCLE, dt)
    _INT.pack_into(buf, base + _STATE, state)
    _DWORD.pack_into(buf, base + _ERROR, error)
    return 0 if error else 1


# -- CTRL_HSC --------------------------------------------------------------------------------------
_HSC_BUSY, _HSC_STATUS = _at(CTRL_HSC, "BUSY", "STATUS")


def ctrl_hsc(buf: bytearray, base: int, now: int) -> int:
    """CTRL_HSC without counter hardware: STATUS 16#80A1, BUSY FALSE, ENO FALSE."""
    _set(buf, base, _HSC_BUSY, False)
    _WORD.pack_into(buf, base + _HSC_STATUS, NO_HSC)
    return 0


BODIES: dict[int, Body] = {PID_COMPACT: pid_compact, CTRL_HSC: ctrl_hsc}


# -- RUNTIME (a system function: references to its actual parameters) ------------------------------
_LREAL = struct.Struct(">d")
Ref = tuple[bytearray, int, int]


def runtime(refs: dict[str, Ref], now_ms: int) -> int:
    """RUNTIME: RET_VAL := the seconds since the time stamp in MEM, MEM := now (seconds of the
    CPU's virtual system time, so a measurement is as repeatable as the scan it measures)."""
    now = now_ms / 1000.0
    mem_buf, mem_byte, _ = refs["MEM"]
    ret_buf, ret_byte, _ = refs["RET_VAL"]
    before: float = _LREAL.unpack_from(mem_buf, mem_byte)[0]
    _LREAL.pack_into(mem_buf, mem_byte, now)
    _LREAL.pack_into(ret_buf, ret_byte, now - before if math.isfinite(before) else 0.0)
    return 1


SFC_BODIES = {RUNTIME_SFC: runtime}
