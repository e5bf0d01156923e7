"""The communication and data log blocks on a CPU without a network (``nasaq.cpu.tia_comm``):
their state machines and STATUS codes, called as the CPU calls them, on an instance buffer."""

from __future__ import annotations

import struct

import pytest

from nasaq.cpu import Cpu, iec_blocks, tia_comm
from nasaq.cpu.profile import Profile
from nasaq.headless.addresses import parse_address
from nasaq.lang import tia_comm as t
from nasaq.lang.stl import SourceFile, compile_sources


class Instance:
    """One instance of system block ``number``: set inputs by name, call, read outputs."""

    def __init__(self, session: tia_comm.Session, number: int, base: int = 6) -> None:
        self.session, self.number, self.base = session, number, base
        self.buf = bytearray(base + iec_blocks.INSTANCE_BYTES[number] + 4)
        self.members = {v.name: v for v in iec_blocks.INTERFACES[number]}
        self.br = -1

    def _at(self, name: str) -> tuple[int, str]:
        v = self.members[name]
        return v.offset_bits, v.type

    def __setitem__(self, name: str, value: int) -> None:
        bits, kind = self._at(name)
        if kind == "BOOL":
            byte, mask = self.base + bits // 8, 1 << (bits % 8)
            self.buf[byte] = self.buf[byte] | mask if value else self.buf[byte] & ~mask
            return
        form = {"WORD": ">H", "INT": ">h", "UINT": ">H", "DWORD": ">I", "UDINT": ">I"}[kind]
        struct.pack_into(form, self.buf, self.base + bits // 8, value)

    def __getitem__(self, name: str) -> int:
        bits, kind = self._at(name)
        if kind == "BOOL":
            return self.buf[self.base + bits // 8] >> (bits % 8) & 1
        form = {"WORD": ">H", "INT": ">h", "UINT": ">H", "DWORD": ">I", "UDINT": ">I"}[kind]
        return int(struct.unpack_from(form, self.buf, self.base + bits // 8)[0])

    def __call__(self, **inputs: int) -> Instance:
        for name, value in inputs.items():
            self[name] = value
        self.br = self.session.bodies[self.number](self.buf, self.base, 0)
        return self

    def result(self, *names: str) -> tuple[int, ...]:
        return tuple(self[name] for name in names)


def test_every_block_has_a_body_and_leaves_the_bytes_around_its_instance_alone() -> None:
    s = tia_comm.Session()
    for number in t.NAMES:
        block = Instance(s, number)
        block.buf[: block.base] = b"\xaa" * block.base
        block.buf[-4:] = b"\x55" * 4
        block()
        assert block.buf[: block.base] == b"\xaa" * block.base
        assert block.buf[-4:] == b"\x55" * 4


# -- TCON / TDISCON -------------------------------------------------------------------------------
RESULT = ("DONE", "BUSY", "ERROR", "STATUS")


def test_tcon_without_request_reports_no_job() -> None:
    tcon = Instance(tia_comm.Session(), t.TCON)
    assert tcon(REQ=0, ID=1).result(*RESULT) == (0, 0, 0, 0x7000)
    assert tcon.br == 1


def test_tcon_keeps_establishing_because_no_partner_answers() -> None:
    s = tia_comm.Session()
    tcon = Instance(s, t.TCON)
    assert tcon(REQ=1, ID=5).result(*RESULT) == (0, 1, 0, 0x7001)
    for _ in range(50):  # REQ is irrelevant once started; it never succeeds
        assert tcon(REQ=0).result(*RESULT) == (0, 1, 0, 0x7002)
    assert s.connections == {5}


def test_tcon_refuses_id_zero_and_an_id_in_use() -> None:
    s = tia_comm.Session()
    assert Instance(s, t.TCON)(REQ=1, ID=0).result(*RESULT) == (0, 0, 1, 0x8086)
    first = Instance(s, t.TCON)
    first(REQ=1, ID=7)
    second = Instance(s, t.TCON)
    assert second(REQ=1, ID=7).result(*RESULT) == (0, 0, 1, 0x80A3)
    assert second.br == 0
    assert second(REQ=1).result(*RESULT) == (0, 0, 0, 0x7000)  # no new edge: no job


def test_tdiscon_ends_the_establishment_and_tcon_reports_it() -> None:
    s = tia_comm.Session()
    tcon, tdiscon = Instance(s, t.TCON), Instance(s, t.TDISCON)
    tcon(REQ=1, ID=3)
    assert tdiscon(REQ=1, ID=3).result(*RESULT) == (0, 1, 0, 0x7001)
    assert tdiscon(REQ=0).result(*RESULT) == (1, 0, 0, 0)
    assert tdiscon().result(*RESULT) == (0, 0, 0, 0x7000)
    assert tcon(REQ=0).result(*RESULT) == (0, 0, 1, 0x80A7)
    assert tcon(REQ=1, ID=3).result(*RESULT) == (0, 1, 0, 0x7001)  # may start again


def test_tdiscon_of_an_id_no_tcon_started() -> None:
    tdiscon = Instance(tia_comm.Session(), t.TDISCON)
    assert tdiscon(REQ=1, ID=9).result(*RESULT) == (0, 0, 1, 0x80A3)


def test_restart_ends_every_connection() -> None:
    s = tia_comm.Session()
    Instance(s, t.TCON)(REQ=1, ID=4)
    s.restart()
    assert not s.connections


# -- TSEND / TRCV ---------------------------------------------------------------------------------
def test_tsend_is_busy_then_reports_the_connection_is_not_established() -> None:
    s = tia_comm.Session()
    Instance(s, t.TCON)(REQ=1, ID=1)
    tsend = Instance(s, t.TSEND)
    assert tsend(REQ=1, ID=1, LEN=10).result(*RESULT) == (0, 1, 0, 0x7001)
    assert tsend(REQ=1).result(*RESULT) == (0, 0, 1, 0x80A1)
    assert tsend.br == 0
    assert tsend(REQ=1).result(*RESULT) == (0, 0, 0, 0x7000)  # REQ held: no new job


def test_tsend_checks_id_and_len() -> None:
    s = tia_comm.Session()
    assert Instance(s, t.TSEND)(REQ=1, ID=0, LEN=1).result(*RESULT) == (0, 0, 1, 0x8086)
    assert Instance(s, t.TSEND)(REQ=1, ID=1, LEN=-1).result(*RESULT) == (
        0,
        0,
        1,
        0x8085,
    )


def test_trcv_receives_nothing_while_enabled() -> None:
    trcv = Instance(tia_comm.Session(), t.TRCV)
    fields = ("NDR", "BUSY", "ERROR", "STATUS", "RCVD_LEN")
    trcv["RCVD_LEN"] = 77
    assert trcv(EN_R=0, ID=1, LEN=1).result(*fields) == (0, 0, 0, 0x7000, 77)
    assert trcv(EN_R=1).result(*fields) == (0, 1, 0, 0x7001, 77)
    assert trcv(EN_R=1).result(*fields) == (0, 0, 1, 0x80A1, 0)


# -- TSEND_C / TRCV_C -----------------------------------------------------------------------------
@pytest.mark.parametrize(("number", "start"), [(t.TSEND_C, "REQ"), (t.TRCV_C, "EN_R")])
def test_compact_blocks_establish_forever_and_terminate_when_cont_falls(
    number: int, start: str
) -> None:
    block = Instance(tia_comm.Session(), number)
    assert block(CONT=0).result(*RESULT) == (0, 0, 0, 0x7000)
    assert block(**{start: 1}).result(*RESULT) == (0, 0, 1, 0x80A1)
    block[start] = 0
    assert block(CONT=1).result(*RESULT) == (0, 1, 0, 0x7001)
    assert block(CONT=1).result(*RESULT) == (0, 1, 0, 0x7002)
    assert block(CONT=1, **{start: 1}).result(*RESULT) == (0, 1, 0, 0x7002)
    assert block(CONT=0, **{start: 0}).result(*RESULT) == (0, 1, 0, 0x7003)
    assert block(CONT=0).result(*RESULT) == (0, 0, 0, 0x7000)


def test_com_rst_resets_the_block_and_is_cleared() -> None:
    block = Instance(tia_comm.Session(), t.TSEND_C)
    block(CONT=1)
    assert block(CONT=0, COM_RST=1).result(*RESULT) == (0, 0, 0, 0x7000)
    assert block["COM_RST"] == 0


# -- GET / PUT ------------------------------------------------------------------------------------
@pytest.mark.parametrize(("number", "done"), [(t.GET, "NDR"), (t.PUT, "DONE")])
def test_get_put_start_then_report_communication_problems(number: int, done: str) -> None:
    block = Instance(tia_comm.Session(), number)
    fields = (done, "ERROR", "STATUS")
    assert block(REQ=0, ID=1).result(*fields) == (0, 0, 0)
    assert block(REQ=1).result(*fields) == (0, 0, 25)
    assert block(REQ=1).result(*fields) == (0, 1, 1)
    assert block.br == 0
    assert block(REQ=0).result(*fields) == (0, 0, 0)


# -- data logs ------------------------------------------------------------------------------------
def _job(block: Instance, **inputs: int) -> tuple[int, ...]:
    """A data log job: the REQ edge (busy), then its result; REQ falls after it."""
    assert block(REQ=1, **inputs).result(*RESULT) == (0, 1, 0, 0x7001)
    found = block(REQ=1).result(*RESULT)
    block(REQ=0)
    return found


def test_create_write_close_and_write_to_a_closed_log() -> None:
    s = tia_comm.Session()
    create = Instance(s, t.LOG_CREATE)
    assert _job(create, RECORDS=3, FORMAT=1, TIMESTAMP=1) == (1, 0, 0, 0)
    ident = create["ID"]
    assert ident == 1
    assert s.logs[1].open
    write = Instance(s, t.LOG_WRITE)
    write["ID"] = ident
    assert _job(write) == (1, 0, 0, 0)
    assert _job(write) == (1, 0, 0, 0)
    assert _job(write) == (1, 0, 0, 0x0001)  # the last record: the log is full
    assert _job(write) == (1, 0, 0, 0x0001)  # overwrites the oldest
    assert s.logs[1].written == 3
    close = Instance(s, t.LOG_CLOSE)
    close["ID"] = ident
    assert _job(close) == (1, 0, 0, 0)
    assert _job(write) == (0, 0, 1, 0x80B0)
    assert write.result(*RESULT) == (0, 0, 0, 0x7000)  # ERROR lasts one call


def test_open_again_and_clear_on_open() -> None:
    s = tia_comm.Session()
    create = Instance(s, t.LOG_CREATE)
    _job(create, RECORDS=10)
    write, close, opener = (Instance(s, n) for n in (t.LOG_WRITE, t.LOG_CLOSE, t.LOG_OPEN))
    for block in (write, close, opener):
        block["ID"] = create["ID"]
    _job(write)
    _job(close)
    assert _job(opener, MODE=0) == (1, 0, 0, 0)
    assert _job(write) == (1, 0, 0, 0)
    assert s.logs[1].written == 2
    assert _job(opener, MODE=1) == (1, 0, 0, 0)
    assert s.logs[1].written == 0


def test_jobs_on_an_unknown_log() -> None:
    s = tia_comm.Session()
    for number in (t.LOG_WRITE, t.LOG_CLOSE, t.LOG_OPEN, t.LOG_NEW_FILE, t.LOG_DELETE):
        block = Instance(s, number)
        block["ID"] = 42
        assert _job(block) == (0, 0, 1, 0x8092)


def test_new_file_closes_the_old_log_and_gives_a_new_id() -> None:
    s = tia_comm.Session()
    create = Instance(s, t.LOG_CREATE)
    _job(create, RECORDS=2)
    new_file = Instance(s, t.LOG_NEW_FILE)
    new_file["ID"] = create["ID"]
    assert _job(new_file, RECORDS=5) == (1, 0, 0, 0)
    assert new_file["ID"] == 2
    assert not s.logs[1].open
    assert s.logs[2].open
    assert s.logs[2].records == 5


def test_delete_and_clear() -> None:
    s = tia_comm.Session()
    create = Instance(s, t.LOG_CREATE)
    _job(create, RECORDS=4)
    write, clear, delete = (Instance(s, n) for n in (t.LOG_WRITE, t.LOG_CLEAR, t.LOG_DELETE))
    for block in (write, clear, delete):
        block["ID"] = 1
    _job(write)
    assert _job(clear) == (1, 0, 0, 0)
    assert s.logs[1].written == 0
    assert _job(delete) == (1, 0, 0, 0)
    assert _job(write) == (0, 0, 1, 0x8092)


def test_logs_belong_to_one_cpu() -> None:
    one, other = tia_comm.Session(), tia_comm.Session()
    _job(Instance(one, t.LOG_CREATE), RECORDS=1)
    write = Instance(other, t.LOG_WRITE)
    write["ID"] = 1
    assert _job(write) == (0, 0, 1, 0x8092)


# -- from STL -------------------------------------------------------------------------------------
GET_STL = """DATA_BLOCK DB6
STRUCT
  a : ARRAY[0..7] OF BYTE;
END_STRUCT
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB5
SFB 14
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
NETWORK
TITLE =
      CALL SFB 14 , DB5 (
           REQ                      := TRUE,
           ID                       := W#16#1,
           NDR                      := M 0.0,
           ERROR                    := M 0.1,
           STATUS                   := MW 2,
           ADDR_1                   := P#DB6.DBX 0.0 BYTE 4,
           RD_1                     := P#DB6.DBX 4.0 BYTE 4);
END_ORGANIZATION_BLOCK
"""


def test_get_called_from_stl_with_any_pointers_as_step7_writes_it() -> None:
    result = compile_sources([SourceFile("get.awl", GET_STL)], profile="S7-300")
    assert [d.code for d in result.diagnostics] == []
    cpu = Cpu(result.program, profile=Profile("S7-300"), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert cpu.read(parse_address("MW2")) == 25
    assert cpu.read(parse_address("M0.1")) == 0
    cpu.run(1)
    assert cpu.read(parse_address("MW2")) == 1
    assert cpu.read(parse_address("M0.1")) == 1
    assert cpu.read(parse_address("M0.0")) == 0
