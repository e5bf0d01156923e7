"""What the communication and data log blocks do on a CPU without a network (``syscomm``):
Open User Communication (TCON, TDISCON, TSEND, TRCV, TSEND_C, TRCV_C), S7 communication (GET,
PUT) and the data logs (DataLogCreate ... DataLogClear). Interfaces: ``nasaq.lang.tia_comm``.

The blocks of one CPU share state a real CPU keeps in its operating system: the connections
(by ID) and the data logs (load memory). ``Session`` holds it, one per CPU
(``nasaq.cpu.calls.Calls.comm``); its ``bodies`` are the blocks as ``body(buf, base, now) ->
BR`` on their instance data, the form of ``nasaq.cpu.iec_blocks``. Each call reads the inputs
from the instance, and writes the outputs and Nasaq's job state (STAT ``REQ_OLD``, ``STEP``,
``KEY``) back. BR (ENO) is 0 at a call that reports ERROR.

Behaviour (no partner is ever reachable; ``backend/nasaq/cpu/COMPATIBILITY.md``, section
"Communication and data logging (syscomm)", says why these codes):
- TCON: REQ's rising edge starts the establishment (BUSY, STATUS 16#7001), later calls report
  16#7002 (still being established) for as long as it lasts, which is forever: a real CPU keeps
  trying while the partner does not answer. ID 0 is 16#8086, an ID being established or
  established already 16#80A3; after TDISCON ended the attempt the next call reports 16#80A7.
- TDISCON: ends the establishment of its ID (BUSY 16#7001, then DONE, STATUS 0); an ID no TCON
  has started is 16#80A3.
- TSEND (REQ edge), TRCV (EN_R = 1): BUSY 16#7001 for one call, then ERROR 16#80A1 ("the
  connection is not established"). ID 0 is 16#8086; a negative LEN 16#8085.
- TSEND_C/TRCV_C: CONT = 1 establishes: BUSY 16#7001, then 16#7002 forever; CONT back to 0
  ends it (STATUS 16#7003 for one call, then 16#7000). A REQ (TSEND_C) or EN_R (TRCV_C) while
  CONT = 0 is ERROR 16#80A1. COM_RST = TRUE resets the block and is cleared, as TIA documents.
- GET/PUT: REQ's rising edge starts the job (STATUS 25, "communication started"), the next call
  reports ERROR with STATUS 1 ("connection to the partner not established").
- Data logs (in the CPU's memory, kept across restarts of the program as load memory keeps
  them): each job is BUSY (16#7001) at the REQ edge and ends at the next call. Create makes an
  open log of RECORDS records and returns its ID (from 1); Write adds a record to an open log
  (STATUS 16#0001 once the log is full: the next write overwrites the oldest), a closed log is
  ERROR 16#80B0, an unknown ID 16#8092 (every job on an unknown ID); Open (MODE 1 empties the
  log), Close, NewFile (a new open log of RECORDS records, the old one closed; ID := the new
  one), Delete, Clear (empties the log). NAME, HEADER and DATA are not read: a log is known by
  its ID and keeps the number of records written, not their values.
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

from nasaq.cpu import iec_blocks
from nasaq.cpu.errors import CpuError
from nasaq.lang import tia_comm as t

Body = Callable[[bytearray, int, int], int]

NO_JOB, STARTED, RUNNING = 0x7000, 0x7001, 0x7002
TERMINATING = 0x7003
BAD_ID, BAD_LEN = 0x8086, 0x8085
ID_IN_USE, DISCONNECTED_EARLY = 0x80A3, 0x80A7
NOT_CONNECTED = 0x80A1
GET_PUT_STARTED, GET_PUT_NO_CONNECTION = 25, 1
LOG_FULL, LOG_UNKNOWN, LOG_CLOSED = 0x0001, 0x8092, 0x80B0
MAX_OUC_ID = 0x0FFF  # the connection IDs TCON accepts: 1 .. 16#0FFF

_WORD = struct.Struct(">H")
_INT = struct.Struct(">h")
_DWORD = struct.Struct(">I")


Ref = tuple[bytearray, int, int]  # (buffer, byte, bit) of an actual parameter
SI_BYTES = 12  # the start information RD_SINFO gives: bytes 0-11 of the OB's local data
CP_JOB_ACTIVE, CP_NOT_CONNECTED = 0x8181, 0x8304


@dataclass(slots=True)
class DataLog:
    records: int  # the log's size in records
    written: int = 0  # records written (at most ``records``: then the oldest is overwritten)
    open: bool = True


class Session:
    """The connections and data logs of one CPU, and its blocks bound to them."""

    def __init__(self) -> None:
        self.connections: set[int] = set()  # IDs whose establishment TCON has started
        self.cp_jobs: set[tuple[int, int]] = set()  # AG_SEND jobs (LADDR, ID) under way
        self.top_si = bytes(SI_BYTES)  # the start information of the running OB (RD_SINFO)
        self.startup_si = bytes(SI_BYTES)  # ... of the last startup OB
        self.logs: dict[int, DataLog] = {}
        self.next_log = 1
        self.bodies: dict[int, Body] = {n: partial(body, self) for n, body in _BODIES.items()}

    def restart(self) -> None:
        """A restart ends every connection (the data logs stay, in load memory)."""
        self.connections.clear()
        self.cp_jobs.clear()

    def ob_started(self, start_info: bytes | bytearray, startup: bool) -> None:
        """The cycle starts an OB with ``start_info`` in its local data (RD_SINFO reads it)."""
        self.top_si = bytes(start_info[:SI_BYTES])
        if startup:
            self.startup_si = self.top_si


class _Members:
    """Where the members of one block's instance are: bit addresses of BOOLs, byte offsets of
    the rest (from ``iec_blocks.INTERFACES``, the compiler's layout)."""

    def __init__(self, number: int) -> None:
        self.at: dict[str, int] = {}
        for v in iec_blocks.INTERFACES[number]:
            self.at[v.name] = v.offset_bits if v.type == "BOOL" else v.offset_bits // 8

    def __getitem__(self, name: str) -> int:
        return self.at[name]


_MEMBERS = {number: _Members(number) for number in t.NAMES}


def _bit(buf: bytearray, base: int, address: int) -> bool:
    return bool(buf[base + (address >> 3)] >> (address & 7) & 1)


def _set(buf: bytearray, base: int, address: int, value: bool) -> None:
    byte, mask = base + (address >> 3), 1 << (address & 7)
    buf[byte] = buf[byte] | mask if value else buf[byte] & ~mask


class _Call:
    """One call of a block: its inputs read, its outputs written by ``end``."""

    __slots__ = ("at", "base", "buf", "edge", "step")

    def __init__(self, number: int, buf: bytearray, base: int, request: str = "REQ") -> None:
        self.at, self.buf, self.base = _MEMBERS[number], buf, base
        now = _bit(buf, base, self.at[request])
        self.edge = now and not _bit(buf, base, self.at["REQ_OLD"])
        _set(buf, base, self.at["REQ_OLD"], now)
        self.step = buf[base + self.at["STEP"]]

    def flag(self, name: str) -> bool:
        return _bit(self.buf, self.base, self.at[name])

    def word(self, name: str) -> int:
        return int(_WORD.unpack_from(self.buf, self.base + self.at[name])[0])

    def integer(self, name: str) -> int:
        return int(_INT.unpack_from(self.buf, self.base + self.at[name])[0])

    def dword(self, name: str) -> int:
        return int(_DWORD.unpack_from(self.buf, self.base + self.at[name])[0])

    def put_dword(self, name: str, value: int) -> None:
        _DWORD.pack_into(self.buf, self.base + self.at[name], value & 0xFFFFFFFF)

    def end(self, step: int, status: int, *, busy: bool = False, done: bool = False) -> int:
        """Writes STEP and the outputs; ERROR is set for a status from 16#8000 up."""
        return self.finish(step, status, busy=busy, done=done, error=status >= 0x8000)

    def finish(self, step: int, status: int, *, busy: bool, done: bool, error: bool) -> int:
        buf, base, at = self.buf, self.base, self.at
        buf[base + at["STEP"]] = step
        _WORD.pack_into(buf, base + at["STATUS"], status & 0xFFFF)
        _set(buf, base, at["ERROR"], error)
        if "BUSY" in at.at:
            _set(buf, base, at["BUSY"], busy)
        for name in ("DONE", "NDR"):
            if name in at.at:
                _set(buf, base, at[name], done)
        return 0 if error else 1


# -- Open User Communication ---------------------------------------------------------------------
def _bad_id(ident: int) -> bool:
    return ident == 0 or ident > MAX_OUC_ID


def tcon(s: Session, buf: bytearray, base: int, now: int) -> int:
    """TCON: the establishment starts and never ends (no partner answers)."""
    c = _Call(t.TCON, buf, base)
    if c.step:
        if c.dword("KEY") not in s.connections:  # TDISCON ended the attempt
            return c.end(0, DISCONNECTED_EARLY)
        return c.end(2, RUNNING, busy=True)
    if not c.edge:
        return c.end(0, NO_JOB)
    ident = c.word("ID")
    if _bad_id(ident):
        return c.end(0, BAD_ID)
    if ident in s.connections:
        return c.end(0, ID_IN_USE)
    s.connections.add(ident)
    c.put_dword("KEY", ident)
    return c.end(1, STARTED, busy=True)


def tdiscon(s: Session, buf: bytearray, base: int, now: int) -> int:
    """TDISCON: ends the connection (here: the establishment) of its ID."""
    c = _Call(t.TDISCON, buf, base)
    if c.step:
        return c.end(0, 0, done=True)
    if not c.edge:
        return c.end(0, NO_JOB)
    ident = c.word("ID")
    if _bad_id(ident):
        return c.end(0, BAD_ID)
    if ident not in s.connections:
        return c.end(0, ID_IN_USE)  # 16#80A3: no connection of this ID to end
    s.connections.discard(ident)
    return c.end(1, STARTED, busy=True)


def _transfer(number: int, request: str, s: Session, buf: bytearray, base: int) -> int:
    """TSEND (REQ edge) and TRCV (EN_R): busy for one call, then "not connected"."""
    c = _Call(number, buf, base, request)
    if c.step:
        if "RCVD_LEN" in c.at.at:
            _INT.pack_into(buf, base + c.at["RCVD_LEN"], 0)
        return c.end(0, NOT_CONNECTED)
    started = c.edge if request == "REQ" else c.flag(request)
    if not started:
        return c.end(0, NO_JOB)
    if _bad_id(c.word("ID")):
        return c.end(0, BAD_ID)
    if c.integer("LEN") < 0:
        return c.end(0, BAD_LEN)
    return c.end(1, STARTED, busy=True)


def tsend(s: Session, buf: bytearray, base: int, now: int) -> int:
    """TSEND: busy for one call, then 16#80A1 (the connection is not established)."""
    return _transfer(t.TSEND, "REQ", s, buf, base)


def trcv(s: Session, buf: bytearray, base: int, now: int) -> int:
    """TRCV: while EN_R, busy for one call, then 16#80A1; RCVD_LEN 0."""
    return _transfer(t.TRCV, "EN_R", s, buf, base)


def _compact(number: int, request: str, s: Session, buf: bytearray, base: int) -> int:
    """TSEND_C/TRCV_C: CONT = 1 establishes (forever), CONT = 0 ends it."""
    c = _Call(number, buf, base, request)
    if c.flag("COM_RST"):
        _set(buf, base, c.at["COM_RST"], False)
        return c.end(0, NO_JOB)
    if c.flag("CONT"):
        return c.end(2 if c.step else 1, RUNNING if c.step else STARTED, busy=True)
    if c.step:
        return c.end(0, TERMINATING, busy=True)
    started = c.edge if request == "REQ" else c.flag(request)
    return c.end(0, NOT_CONNECTED if started else NO_JOB)


def tsend_c(s: Session, buf: bytearray, base: int, now: int) -> int:
    return _compact(t.TSEND_C, "REQ", s, buf, base)


def trcv_c(s: Session, buf: bytearray, base: int, now: int) -> int:
    return _compact(t.TRCV_C, "EN_R", s, buf, base)


# -- S7 communication ---------------------------------------------------------------------------
def _get_put(number: int, s: Session, buf: bytearray, base: int) -> int:
    c = _Call(number, buf, base)
    if c.step:
        return c.finish(0, GET_PUT_NO_CONNECTION, busy=False, done=False, error=True)
    if c.edge:
        return c.finish(1, GET_PUT_STARTED, busy=False, done=False, error=False)
    return c.finish(0, 0, busy=False, done=False, error=False)


def get(s: Session, buf: bytearray, base: int, now: int) -> int:
    """GET (SFB 14): STATUS 25 at the REQ edge, then ERROR with STATUS 1."""
    return _get_put(t.GET, s, buf, base)


def put(s: Session, buf: bytearray, base: int, now: int) -> int:
    """PUT (SFB 15): STATUS 25 at the REQ edge, then ERROR with STATUS 1."""
    return _get_put(t.PUT, s, buf, base)


# -- data logs ----------------------------------------------------------------------------------
def _log_job(number: int, job: Callable[[Session, _Call], int], s: Session, buf: bytearray,
             base: int) -> int:  # fmt: skip
    """A data log job: BUSY at the REQ edge, ``job`` (the result) at the next call."""
    c = _Call(number, buf, base)
    if c.step:
        return job(s, c)
    if not c.edge:
        return c.end(0, NO_JOB)
    return c.end(1, STARTED, busy=True)


def _log(s: Session, c: _Call) -> DataLog | None:
    return s.logs.get(c.dword("ID"))


def _create(s: Session, c: _Call, records: int | None = None) -> int:
    ident = s.next_log
    s.next_log += 1
    s.logs[ident] = DataLog(max(1, c.dword("RECORDS") if records is None else records))
    c.put_dword("ID", ident)
    return c.end(0, 0, done=True)


def _write(s: Session, c: _Call) -> int:
    log = _log(s, c)
    if log is None:
        return c.end(0, LOG_UNKNOWN)
    if not log.open:
        return c.end(0, LOG_CLOSED)
    log.written = min(log.written + 1, log.records)
    return c.end(0, LOG_FULL if log.written == log.records else 0, done=True)


def _open(s: Session, c: _Call) -> int:
    log = _log(s, c)
    if log is None:
        return c.end(0, LOG_UNKNOWN)
    log.open = True
    if c.word("MODE") == 1:
        log.written = 0
    return c.end(0, 0, done=True)


def _close(s: Session, c: _Call) -> int:
    log = _log(s, c)
    if log is None:
        return c.end(0, LOG_UNKNOWN)
    log.open = False
    return c.end(0, 0, done=True)


def _new_file(s: Session, c: _Call) -> int:
    log = _log(s, c)
    if log is None:
        return c.end(0, LOG_UNKNOWN)
    log.open = False
    return _create(s, c)


def _delete(s: Session, c: _Call) -> int:
    if s.logs.pop(c.dword("ID"), None) is None:
        return c.end(0, LOG_UNKNOWN)
    return c.end(0, 0, done=True)


def _clear(s: Session, c: _Call) -> int:
    log = _log(s, c)
    if log is None:
        return c.end(0, LOG_UNKNOWN)
    log.written = 0
    return c.end(0, 0, done=True)


def _log_body(number: int, job: Callable[[Session, _Call], int]) -> Callable[..., int]:
    def body(s: Session, buf: bytearray, base: int, now: int) -> int:
        return _log_job(number, job, s, buf, base)

    body.__name__ = t.NAMES[number]
    return body


_BODIES: dict[int, Callable[[Session, bytearray, int, int], int]] = {
    t.GET: get,
    t.PUT: put,
    t.TCON: tcon,
    t.TDISCON: tdiscon,
    t.TSEND: tsend,
    t.TRCV: trcv,
    t.TSEND_C: tsend_c,
    t.TRCV_C: trcv_c,
    t.LOG_CREATE: _log_body(t.LOG_CREATE, _create),
    t.LOG_OPEN: _log_body(t.LOG_OPEN, _open),
    t.LOG_WRITE: _log_body(t.LOG_WRITE, _write),
    t.LOG_CLOSE: _log_body(t.LOG_CLOSE, _close),
    t.LOG_NEW_FILE: _log_body(t.LOG_NEW_FILE, _new_file),
    t.LOG_DELETE: _log_body(t.LOG_DELETE, _delete),
    t.LOG_CLEAR: _log_body(t.LOG_CLEAR, _clear),
}
assert _BODIES.keys() == t.NAMES.keys()


# -- system functions: RD_SINFO, AG_SEND, AG_RECV (references to their actual parameters) ----------
def _put_bytes(ref: Ref, data: bytes) -> None:
    buf, byte, _bit = ref
    if byte < 0 or byte + len(data) > len(buf):
        raise CpuError("SIM504", address=f"byte {byte} (parameter)")
    buf[byte : byte + len(data)] = data


def _put_bit(ref: Ref, value: bool) -> None:
    buf, byte, bit = ref
    if byte < 0 or byte >= len(buf):
        raise CpuError("SIM504", address=f"byte {byte} (parameter)")
    buf[byte] = buf[byte] | 1 << bit if value else buf[byte] & ~(1 << bit)


def _get_bit(ref: Ref) -> bool:
    buf, byte, bit = ref
    if byte < 0 or byte >= len(buf):
        raise CpuError("SIM503", address=f"byte {byte} (parameter)")
    return bool(buf[byte] >> bit & 1)


def _get_word(ref: Ref) -> int:
    buf, byte, _bit = ref
    if byte < 0 or byte + 2 > len(buf):
        raise CpuError("SIM503", address=f"byte {byte} (parameter)")
    return int(_WORD.unpack_from(buf, byte)[0])


def _outputs(refs: dict[str, Ref], **values: int) -> None:
    """Writes the outputs given (BOOLs as bits, the rest as words) that the call supplies."""
    for name, value in values.items():
        ref = refs.get(name)
        if ref is None:
            continue
        if name in ("DONE", "NDR", "ERROR"):
            _put_bit(ref, bool(value))
        else:
            _put_bytes(ref, _WORD.pack(value & 0xFFFF))


def rd_sinfo(s: Session, refs: dict[str, Ref]) -> int:
    """RD_SINFO (SFC 6): TOP_SI := the running OB's start information, START_UP_SI := the last
    startup OB's (bytes 0-11 of their local data); RET_VAL := 0."""
    for name, data in (("TOP_SI", s.top_si), ("START_UP_SI", s.startup_si)):
        if name in refs:
            _put_bytes(refs[name], data)
    _outputs(refs, RET_VAL=0)
    return 1


def ag_send(s: Session, refs: dict[str, Ref]) -> int:
    """AG_SEND: ACT = 1 starts a job (STATUS 16#8181, job active); the next call ends it with
    ERROR, STATUS 16#8304 (the connection is not established)."""
    job = (_get_word(refs["LADDR"]), _get_word(refs["ID"])) if "LADDR" in refs else (0, 0)
    if job in s.cp_jobs:
        s.cp_jobs.discard(job)
        _outputs(refs, DONE=0, ERROR=1, STATUS=CP_NOT_CONNECTED)
        return 0
    if "ACT" in refs and _get_bit(refs["ACT"]):
        s.cp_jobs.add(job)
        _outputs(refs, DONE=0, ERROR=0, STATUS=CP_JOB_ACTIVE)
        return 1
    _outputs(refs, DONE=0, ERROR=0, STATUS=0)
    return 1


def ag_recv(s: Session, refs: dict[str, Ref]) -> int:
    """AG_RECV: no data (NDR 0, LEN 0), ERROR with STATUS 16#8304 (not connected)."""
    _outputs(refs, NDR=0, ERROR=1, STATUS=CP_NOT_CONNECTED, LEN=0)
    return 0


CN_STATUS = 1  # AG_CNTRL's command: the connection's status in RESULT1
CP_RUN = 0x4000  # RESULT1 bit 14: the CP is in RUN (bits 12-13 00: the connection is not up)


def ag_cntrl(s: Session, refs: dict[str, Ref]) -> int:
    """AG_CNTRL: every command is done at once (DONE, STATUS 0); CN_STATUS reports the CP in
    RUN and the connection not established (RESULT1 16#4000), the rest RESULT1 = 0; CN_RESET
    and the others also end an AG_SEND job of the connection."""
    if "ACT" in refs and not _get_bit(refs["ACT"]):
        _outputs(refs, DONE=0, ERROR=0, STATUS=0)
        return 1
    job = (_get_word(refs["LADDR"]), _get_word(refs["ID"])) if "LADDR" in refs else (0, 0)
    command = _get_word(refs["CMD"]) if "CMD" in refs else 0
    if command != CN_STATUS:
        s.cp_jobs.discard(job)
    _outputs(refs, DONE=1, ERROR=0, STATUS=0)
    for name, value in (("RESULT1", CP_RUN if command == CN_STATUS else 0), ("RESULT2", 0)):
        if name in refs:
            _put_bytes(refs[name], _DWORD.pack(value))
    return 1


SFC_BODIES: dict[int, Callable[[Session, dict[str, Ref]], int]] = {
    t.RD_SINFO: rd_sinfo,
    t.AG_SEND: ag_send,
    t.AG_RECV: ag_recv,
    t.AG_CNTRL: ag_cntrl,
}
assert SFC_BODIES.keys() == t.SFC_NAMES.keys()


def parameter_bytes(number: int, name: str) -> int:
    """The size in bytes of parameter ``name`` of SFC ``number`` (for a constant actual)."""
    for _section, formal, text in t.SFC_INTERFACES[number]:
        if formal.upper() == name.upper():
            return {"BOOL": 1, "BYTE": 1, "INT": 2, "WORD": 2}.get(text, 4)  # DWORD: 4
    return 4
