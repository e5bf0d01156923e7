"""What TIA Portal's filter instructions (S7-1500 "basic functions for controllers",
LibVersion 1.0) do on the simulated CPU: bodies ``(buf, base, now) -> BR`` on the instance
data, merged into ``nasaq.cpu.iec_blocks.BODIES``. The interfaces are
``nasaq.lang.tia_filters``'s.

Every filter is discretised with the backward (implicit) Euler rule, stable for any cycle time
and exact in its steady state; ``Ts`` is the cycle time in seconds:

- Filter_PT1, ``Gain / (1 + Lag*s)``: ``y := (Lag*y + Ts*Gain*u) / (Lag + Ts)``
  (Lag = 0: no lag, y = Gain*u).
- Filter_DT1, ``Gain*s / (1 + Lag*s)``: ``y := (Lag*y + Gain*(u - u_old)) / (Lag + Ts)``; the
  first call after a start only takes the input over (no jump from the initial 0.0).
- Filter_PT2, ``Gain / (1 + 2*Damping*T*s + T^2*s^2)`` (T = TimeConstant), with the output and
  its slope as state (T = 0: y = Gain*u).

``Ts``: with ``CycleTime.EnableMeasurement`` the time since the previous call on the CPU's
virtual clock, written to ``CycleTime.Value`` (the first call, or two calls in the same
millisecond, use ``CycleTime.Value``); without it ``CycleTime.Value``.

``Reset`` (first) and ``SubstituteOutputActive``: Output := SubstituteOutput and the filter
state follows it, so the filter continues from that value without a jump afterwards. Reset
also clears ErrorBits. An invalid parameter (COMPATIBILITY.md, "Filters"): Error TRUE, ErrorBits
says which, BR (ENO) 0, Output keeps its last value and the state is not changed.
"""

from __future__ import annotations

import math
import struct

from nasaq.cpu.iec_blocks import INTERFACES, Body
from nasaq.ir import Variable
from nasaq.lang.tia_filters import FILTER_DT1, FILTER_PT1, FILTER_PT2

_REAL = struct.Struct(">f")
_DINT = struct.Struct(">i")
_DWORD = struct.Struct(">I")
REAL_LIMIT = 3.4028234663852886e38

# ErrorBits (Nasaq's assignment; COMPATIBILITY.md, "Filters")
ERROR_CYCLE_TIME = 0x0000_0001  # CycleTime.Value <= 0 (or not a number) and no measurement
ERROR_LAG = 0x0000_0002  # Lag (PT2: TimeConstant) < 0 or not a number
ERROR_GAIN = 0x0000_0004  # Gain not a number
ERROR_DAMPING = 0x0000_0008  # PT2: Damping < 0 or not a number
ERROR_INPUT = 0x0000_0010  # Input or SubstituteOutput not a number


def _find(variables: list[Variable], path: str) -> Variable:
    head, _, rest = path.partition(".")
    found = next(v for v in variables if v.name == head)
    return _find(found.members, rest) if rest else found


class _Layout:
    """Offsets of one filter's members (bytes; BOOLs: bit addresses), found once."""

    def __init__(self, number: int, time_name: str) -> None:
        def at(path: str) -> int:
            v = _find(INTERFACES[number], path)
            return v.offset_bits if v.type == "BOOL" else v.offset_bits // 8

        self.input, self.substitute = at("Input"), at("SubstituteOutput")
        self.substitute_active, self.reset = at("SubstituteOutputActive"), at("Reset")
        self.output, self.error_bits, self.error = at("Output"), at("ErrorBits"), at("Error")
        self.gain, self.time = at("Gain"), at(time_name)
        self.cycle, self.measure = at("CycleTime.Value"), at("CycleTime.EnableMeasurement")
        self.tick, self.started = at("Tick_N"), at("Started_N")


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


def _cycle(buf: bytearray, base: int, at: _Layout, now: int) -> float:
    """The cycle time in seconds (measured and stored in CycleTime.Value when enabled)."""
    last: int = _DINT.unpack_from(buf, base + at.tick)[0]
    _DINT.pack_into(buf, base + at.tick, now)
    if _bit(buf, base, at.measure) and _bit(buf, base, at.started):
        elapsed = (now - last) & 0x7FFFFFFF
        if elapsed:
            _put_real(buf, base, at.cycle, elapsed / 1000.0)
            return elapsed / 1000.0
    return _real(buf, base, at.cycle)


def _errors(buf: bytearray, base: int, at: _Layout, ts: float) -> int:
    error = 0
    if not (math.isfinite(ts) and ts > 0.0):
        error |= ERROR_CYCLE_TIME
    time = _real(buf, base, at.time)
    if not (math.isfinite(time) and time >= 0.0):
        error |= ERROR_LAG
    if not math.isfinite(_real(buf, base, at.gain)):
        error |= ERROR_GAIN
    if not (
        math.isfinite(_real(buf, base, at.input)) and math.isfinite(_real(buf, base, at.substitute))
    ):
        error |= ERROR_INPUT
    return error


def _finish(buf: bytearray, base: int, at: _Layout, error: int) -> int:
    _DWORD.pack_into(buf, base + at.error_bits, error)
    _set(buf, base, at.error, bool(error))
    _set(buf, base, at.started, True)
    return 0 if error else 1


def _substitute(buf: bytearray, base: int, at: _Layout) -> float | None:
    """SubstituteOutput when Reset or SubstituteOutputActive asks for it (written to Output)."""
    if not (_bit(buf, base, at.reset) or _bit(buf, base, at.substitute_active)):
        return None
    value = _real(buf, base, at.substitute)
    _put_real(buf, base, at.output, value)
    return value


def _substituted(buf: bytearray, base: int, at: _Layout, ts: float) -> int:
    """The end of a call that output SubstituteOutput: Reset clears the errors."""
    return _finish(buf, base, at, 0 if _bit(buf, base, at.reset) else _errors(buf, base, at, ts))


# -- Filter_PT1 ------------------------------------------------------------------------------------
_PT1 = _Layout(FILTER_PT1, "Lag")


def filter_pt1(buf: bytearray, base: int, now: int) -> int:
    """Filter_PT1: y := (Lag*y + Ts*Gain*u) / (Lag + Ts)."""
    at = _PT1
    ts = _cycle(buf, base, at, now)
    if _substitute(buf, base, at) is not None:
        return _substituted(buf, base, at, ts)
    error = _errors(buf, base, at, ts)
    if not error:
        lag, gain = _real(buf, base, at.time), _real(buf, base, at.gain)
        y = _real(buf, base, at.output)
        u = _real(buf, base, at.input)
        _put_real(buf, base, at.output, (lag * y + ts * gain * u) / (lag + ts))
    return _finish(buf, base, at, error)


# -- Filter_DT1 ------------------------------------------------------------------------------------
_DT1 = _Layout(FILTER_DT1, "Lag")
_DT1_INPUT_OLD = _find(INTERFACES[FILTER_DT1], "InputOld_N").offset_bits // 8


def filter_dt1(buf: bytearray, base: int, now: int) -> int:
    """Filter_DT1: y := (Lag*y + Gain*(u - u_old)) / (Lag + Ts)."""
    at = _DT1
    ts = _cycle(buf, base, at, now)
    u = _real(buf, base, at.input)
    first = not _bit(buf, base, at.started)
    if _substitute(buf, base, at) is not None:
        _put_real(buf, base, _DT1_INPUT_OLD, u)
        return _substituted(buf, base, at, ts)
    error = _errors(buf, base, at, ts)
    if not error:
        lag, gain = _real(buf, base, at.time), _real(buf, base, at.gain)
        change = 0.0 if first else u - _real(buf, base, _DT1_INPUT_OLD)
        y = _real(buf, base, at.output)
        _put_real(buf, base, at.output, (lag * y + gain * change) / (lag + ts))
        _put_real(buf, base, _DT1_INPUT_OLD, u)
    return _finish(buf, base, at, error)


# -- Filter_PT2 ------------------------------------------------------------------------------------
_PT2 = _Layout(FILTER_PT2, "TimeConstant")
_PT2_DAMPING = _find(INTERFACES[FILTER_PT2], "Damping").offset_bits // 8
_PT2_SLOPE = _find(INTERFACES[FILTER_PT2], "Slope_N").offset_bits // 8


def filter_pt2(buf: bytearray, base: int, now: int) -> int:
    """Filter_PT2: T^2*y'' + 2*D*T*y' + y = Gain*u, backward Euler on (y, y')."""
    at = _PT2
    ts = _cycle(buf, base, at, now)
    if _substitute(buf, base, at) is not None:
        _put_real(buf, base, _PT2_SLOPE, 0.0)
        return _substituted(buf, base, at, ts)
    error = _errors(buf, base, at, ts)
    damping = _real(buf, base, _PT2_DAMPING)
    if not (math.isfinite(damping) and damping >= 0.0):
        error |= ERROR_DAMPING
    if not error:
        t, gain = _real(buf, base, at.time), _real(buf, base, at.gain)
        y, slope = _real(buf, base, at.output), _real(buf, base, _PT2_SLOPE)
        target = gain * _real(buf, base, at.input)
        if t == 0.0:
            y, slope = target, 0.0
        else:
            slope = (slope + ts * (target - y) / (t * t)) / (
                1.0 + 2.0 * damping * ts / t + ts * ts / (t * t)
            )
            y += ts * slope
        _put_real(buf, base, at.output, y)
        _put_real(buf, base, _PT2_SLOPE, slope)
    return _finish(buf, base, at, error)


BODIES: dict[int, Body] = {
    FILTER_PT1: filter_pt1,
    FILTER_DT1: filter_dt1,
    FILTER_PT2: filter_pt2,
}
