"""Communication, data logging and block information instructions called from SCL (syscomm):
TCON/TDISCON/TSEND/TRCV as multi-instances and with instance DBs, TIA's and STEP 7's forms,
GET/PUT, TSEND_C, the data logs, RD_SINFO, AG_SEND/AG_RECV and GetBlockName, compiled and run."""

from __future__ import annotations

import pytest
from scl_run import build, read

from nasaq.lang.stl import SourceFile, compile_sources

OUT = """
DATA_BLOCK "Out"
STRUCT
  w0 : WORD; w1 : WORD; w2 : WORD; w3 : WORD;
  b0 : BOOL; b1 : BOOL; b2 : BOOL; b3 : BOOL;
END_STRUCT
BEGIN
END_DATA_BLOCK
"""


def codes(source: str, profile: str = "S7-1500") -> list[str]:
    result = compile_sources([SourceFile("prog.scl", source)], profile=profile)
    return [d.code for d in result.diagnostics if d.severity == "error"]


def words(cpu: object) -> tuple[int, ...]:
    return tuple(read(cpu, f"DB1.DBW{2 * k}") & 0xFFFF for k in range(4))  # type: ignore[arg-type]


def bools(cpu: object) -> tuple[int, ...]:
    return tuple(read(cpu, f"DB1.DBX8.{k}") for k in range(4))  # type: ignore[arg-type]


OUC_TIA = (
    OUT
    + """
FUNCTION_BLOCK "Client"
{ S7_Optimized_Access := 'TRUE' }
VAR
  conn {InstructionName := 'TCON'; LibVersion := '4.0'} : TCON;
  snd : TSEND;
  rcv : TRCV;
  disc : TDISCON;
  cfg : TCON_IP_v4;
  id : CONN_OUC := 1;
  hw : HW_ANY := 64;
  buf : ARRAY[0..15] OF BYTE;
  scan : INT;
END_VAR
  #scan := #scan + 1;
  #cfg.InterfaceId := #hw;
  #cfg.ID := #id;
  #cfg.ConnectionType := 16#0B;
  #cfg.ActiveEstablished := TRUE;
  #cfg.RemoteAddress.ADDR[1] := 192;
  #cfg.RemotePort := 2000;
  #conn(REQ := #scan = 1, ID := #id, CONNECT := #cfg);
  #snd(REQ := #scan = 2, ID := #id, LEN := 4, DATA := #buf);
  #rcv(EN_R := #scan >= 2, ID := #id, LEN := 4, DATA := #buf);
  #disc(REQ := #scan = 4, ID := #id);
  "Out".w0 := #conn.STATUS;
  "Out".w1 := #snd.STATUS;
  "Out".w2 := #rcv.STATUS;
  "Out".w3 := #disc.STATUS;
  "Out".b0 := #conn.BUSY;
  "Out".b1 := #snd.ERROR;
  "Out".b2 := #rcv.ERROR;
  "Out".b3 := #disc.DONE;
END_FUNCTION_BLOCK
DATA_BLOCK "ClientDB" "Client"
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "ClientDB"();
END_ORGANIZATION_BLOCK
"""
)


def test_open_user_communication_never_connects_on_s7_1500() -> None:
    cpu = build(OUC_TIA, profile="S7-1500", scans=1)
    assert words(cpu)[:2] == (0x7001, 0x7000)
    assert bools(cpu)[0] == 1
    cpu.run(1)  # scan 2: TCON still establishing, TSEND starts, TRCV starts
    assert words(cpu)[:3] == (0x7002, 0x7001, 0x7001)
    cpu.run(1)  # scan 3: the send and the receive fail: not connected
    assert words(cpu)[:3] == (0x7002, 0x80A1, 0x80A1)
    assert bools(cpu)[:3] == (1, 1, 1)
    cpu.run(1)  # scan 4: TDISCON ends the attempt
    assert words(cpu)[3] == 0x7001
    cpu.run(1)  # scan 5: TDISCON done, TCON reports the interrupted establishment
    assert words(cpu)[0] == 0x80A7
    assert words(cpu)[3] == 0
    assert bools(cpu)[3] == 1


OUC_CLASSIC = (
    OUT
    + """
FUNCTION_BLOCK FB1
VAR
  NET_CON : TCON;
  NET_SEND : TSEND;
  NET_CONFIG : STRUCT
    block_length : WORD; id : WORD; connection_type : BYTE; active_est : BOOL;
    rest : ARRAY[1..58] OF BYTE;
  END_STRUCT;
  sendBuf : ARRAY[0..63] OF BYTE;
  connectionID : INT := 3;
  size : INT := 8;
END_VAR
  NET_CON(REQ := TRUE, ID := INT_TO_WORD(connectionID), CONNECT := NET_CONFIG);
  NET_SEND(REQ := TRUE, ID := INT_TO_WORD(connectionID), LEN := size, DATA := sendBuf);
  "Out".w0 := NET_CON.STATUS;
  "Out".w1 := NET_SEND.STATUS;
  "Out".b0 := NET_CON.DONE;
END_FUNCTION_BLOCK
DATA_BLOCK DB2 FB1
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB2();
END_ORGANIZATION_BLOCK
"""
)


@pytest.mark.parametrize("profile", ["S7-300", "S7-1500"])
def test_step7_form_of_tcon_and_tsend_runs_on_both_profiles(profile: str) -> None:
    cpu = build(OUC_CLASSIC, profile=profile, scans=1)
    assert words(cpu)[:2] == (0x7001, 0x7001)
    cpu.run(3)
    assert words(cpu)[:2] == (
        0x7002,
        0x7000,
    )  # REQ held: one send job, failed, then idle
    assert bools(cpu)[0] == 0  # never DONE


def test_tia_types_need_the_s7_1500_profile() -> None:
    found = codes(OUC_TIA, "S7-300")
    assert found
    assert set(found) == {"SCL500"}


def test_single_instance_db_of_tcon() -> None:
    source = (
        OUT
        + """
DATA_BLOCK "TCON_DB" TCON
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "TCON_DB"(REQ := TRUE, ID := W#16#5);
  "Out".w0 := "TCON_DB".STATUS;
  "Out".b0 := "TCON_DB".BUSY;
END_ORGANIZATION_BLOCK
"""
    )
    cpu = build(source, profile="S7-1500", scans=2)
    assert words(cpu)[0] == 0x7002
    assert bools(cpu)[0] == 1


def test_get_and_put_start_then_report_no_connection() -> None:
    source = (
        OUT
        + """
FUNCTION_BLOCK FB1
VAR
  DbGET : GET;
  DbPUT : PUT;
  rx : ARRAY[0..9] OF BYTE;
  tx : ARRAY[0..9] OF BYTE;
  remote : ARRAY[0..9] OF BYTE;
END_VAR
  DbGET(REQ := DbGET.STATUS <> 25, ID := W#16#1, ADDR_1 := remote, RD_1 := rx);
  DbPUT(REQ := TRUE, ID := W#16#1, ADDR_1 := remote, SD_1 := tx);
  "Out".w0 := DbGET.STATUS;
  "Out".w1 := DbPUT.STATUS;
  "Out".b0 := DbGET.ERROR;
  "Out".b1 := DbPUT.ERROR;
  "Out".b2 := DbGET.NDR OR DbPUT.DONE;
END_FUNCTION_BLOCK
DATA_BLOCK DB2 FB1
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB2();
END_ORGANIZATION_BLOCK
"""
    )
    cpu = build(source, profile="S7-300", scans=1)
    assert words(cpu)[:2] == (25, 25)
    assert bools(cpu)[:3] == (0, 0, 0)
    cpu.run(1)
    assert words(cpu)[:2] == (1, 1)
    assert bools(cpu)[:3] == (1, 1, 0)


def test_tsend_c_keeps_establishing_while_cont() -> None:
    source = (
        OUT
        + """
FUNCTION_BLOCK "Sender"
VAR
  snd : TSEND_C;
  cfg : TCON_IP_v4;
  data : ARRAY[0..3] OF BYTE;
  rst : BOOL;
END_VAR
  #snd(REQ := TRUE, CONT := TRUE, LEN := 4, CONNECT := #cfg, DATA := #data, COM_RST := #rst);
  "Out".w0 := #snd.STATUS;
  "Out".b0 := #snd.BUSY;
  "Out".b1 := #snd.DONE;
END_FUNCTION_BLOCK
DATA_BLOCK "SenderDB" "Sender"
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "SenderDB"();
END_ORGANIZATION_BLOCK
"""
    )
    cpu = build(source, profile="S7-1500", scans=5)
    assert words(cpu)[0] == 0x7002
    assert bools(cpu)[:2] == (1, 0)


DATA_LOG = (
    OUT
    + """
FUNCTION_BLOCK "Logger"
VAR
  create : DataLogCreate;
  write : DataLogWrite;
  close : DataLogClose;
  name : STRING[20] := 'Temperatures';
  record : STRUCT t : REAL; p : REAL; END_STRUCT;
  id : DWORD;
  step : INT;
END_VAR
  #step := #step + 1;
  #create(REQ := #step = 1, RECORDS := 2, FORMAT := 1, TIMESTAMP := 1, NAME := #name,
          ID := #id, DATA := #record);
  #write(REQ := #step = 3 OR #step = 5 OR #step = 9, ID := #id);
  #close(REQ := #step = 7, ID := #id);
  "Out".w0 := #create.STATUS;
  "Out".w1 := #write.STATUS;
  "Out".w2 := #close.STATUS;
  "Out".w3 := DWORD_TO_WORD(#id);
  "Out".b0 := #create.DONE;
  "Out".b1 := #write.DONE;
  "Out".b2 := #write.ERROR;
  "Out".b3 := #close.DONE;
END_FUNCTION_BLOCK
DATA_BLOCK "LoggerDB" "Logger"
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "LoggerDB"();
END_ORGANIZATION_BLOCK
"""
)


def test_data_log_create_write_close_and_write_to_the_closed_log() -> None:
    cpu = build(DATA_LOG, profile="S7-1500", scans=1)
    assert words(cpu)[0] == 0x7001  # create: busy
    cpu.run(1)
    assert words(cpu)[0] == 0
    assert words(cpu)[3] == 1
    assert bools(cpu)[0] == 1
    cpu.run(2)  # write, 1st record
    assert words(cpu)[1] == 0
    assert bools(cpu)[1:3] == (1, 0)
    cpu.run(2)  # write, 2nd record: the log is full
    assert words(cpu)[1] == 0x0001
    assert bools(cpu)[1:3] == (1, 0)
    cpu.run(2)  # close
    assert words(cpu)[2] == 0
    assert bools(cpu)[3] == 1
    cpu.run(2)  # write to the closed log
    assert words(cpu)[1] == 0x80B0
    assert bools(cpu)[1:3] == (0, 1)


def test_data_logs_need_the_s7_1500_profile() -> None:
    assert "SCL500" in codes(DATA_LOG, "S7-300")


RD_SINFO = (
    OUT
    + """
FUNCTION_BLOCK FB1
VAR
  TOP_SI : STRUCT
    EV_CLASS : BYTE; EV_NUM : BYTE; PRIORITY : BYTE; NUM : BYTE;
    TYP2_3 : BYTE; TYP1 : BYTE; ZI1 : WORD; ZI2_3 : DWORD;
  END_STRUCT;
  START_UP_SI : STRUCT
    EV_CLASS : BYTE; EV_NUM : BYTE; PRIORITY : BYTE; NUM : BYTE;
    TYP2_3 : BYTE; TYP1 : BYTE; ZI1 : WORD; ZI2_3 : DWORD;
  END_STRUCT;
  ret : INT;
END_VAR
  ret := RD_SINFO(TOP_SI := TOP_SI, START_UP_SI := START_UP_SI);
  "Out".w0 := BYTE_TO_WORD(TOP_SI.NUM);
  "Out".w1 := BYTE_TO_WORD(TOP_SI.EV_NUM);
  "Out".w2 := BYTE_TO_WORD(START_UP_SI.NUM);
  "Out".w3 := INT_TO_WORD(ret);
  "Out".b0 := TOP_SI.EV_CLASS = B#16#11;
END_FUNCTION_BLOCK
DATA_BLOCK DB2 FB1
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB2();
END_ORGANIZATION_BLOCK
ORGANIZATION_BLOCK OB100
BEGIN
END_ORGANIZATION_BLOCK
"""
)


@pytest.mark.parametrize("profile", ["S7-300", "S7-1500"])
def test_rd_sinfo_reads_the_start_information(profile: str) -> None:
    cpu = build(RD_SINFO, profile=profile, scans=1)
    assert words(cpu) == (1, 1, 100, 0)
    assert bools(cpu)[0] == 1
    cpu.run(1)
    assert words(cpu)[1] == 3  # a later cycle


def test_rd_sinfo_refuses_a_variable_of_another_layout() -> None:
    source = RD_SINFO.replace(
        "  ret := RD_SINFO(TOP_SI := TOP_SI, START_UP_SI := START_UP_SI);",
        "  ret := RD_SINFO(TOP_SI := TOP_SI, START_UP_SI := ret);",
    )
    assert codes(source, "S7-300") == ["SCL950"]


def test_ag_send_and_ag_recv_report_the_connection_is_not_established() -> None:
    source = (
        OUT
        + """
FUNCTION_BLOCK FB1
VAR
  buf : ARRAY[0..9] OF BYTE;
  n : INT;
  done, err, ndr, rerr : BOOL;
  status, rstatus : WORD;
  len : INT;
END_VAR
  n := n + 1;
  AG_SEND(ACT := n = 1, ID := 1, LADDR := W#16#100, SEND := buf, LEN := 10,
          DONE := done, ERROR := err, STATUS := status);
  AG_RECV(ID := 1, LADDR := W#16#100, RECV := buf, NDR => ndr, ERROR => rerr,
          STATUS => rstatus, LEN => len);
  "Out".w0 := status;
  "Out".w1 := rstatus;
  "Out".w2 := INT_TO_WORD(len);
  "Out".b0 := err;
  "Out".b1 := rerr;
  "Out".b2 := done OR ndr;
END_FUNCTION_BLOCK
DATA_BLOCK DB2 FB1
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB2();
END_ORGANIZATION_BLOCK
"""
    )
    cpu = build(source, profile="S7-300", scans=1)
    assert words(cpu)[:3] == (0x8181, 0x8304, 0)
    assert bools(cpu)[:3] == (0, 1, 0)
    cpu.run(1)
    assert words(cpu)[:2] == (0x8304, 0x8304)
    assert bools(cpu)[:3] == (1, 1, 0)
    cpu.run(1)
    assert words(cpu)[0] == 0
    assert bools(cpu)[0] == 0


def test_ag_cntrl_reports_the_cp_running_and_the_connection_down() -> None:
    source = (
        OUT
        + """
FUNCTION_BLOCK FB1
VAR
  done, err : BOOL;
  status : WORD;
  res1, res2 : DWORD;
END_VAR
  AG_CNTRL(ACT := TRUE, ID := 1, LADDR := W#16#100, CMD := 1, DONE => done, ERROR => err,
           STATUS => status, RESULT1 => res1, RESULT2 => res2);
  "Out".w0 := status;
  "Out".w1 := DWORD_TO_WORD(SHR(IN := res1, N := 16));
  "Out".w2 := DWORD_TO_WORD(res1);
  "Out".b0 := done;
  "Out".b1 := err;
END_FUNCTION_BLOCK
DATA_BLOCK DB2 FB1
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB2();
END_ORGANIZATION_BLOCK
"""
    )
    cpu = build(source, profile="S7-300", scans=1)
    assert words(cpu)[:3] == (0, 0, 0x4000)
    assert bools(cpu)[:2] == (1, 0)


def test_a_program_fc5_is_its_own_next_to_ag_send() -> None:
    source = (
        OUT
        + """
FUNCTION FC5 : INT
  FC5 := 42;
END_FUNCTION
ORGANIZATION_BLOCK OB1
VAR_TEMP
  buf : ARRAY[0..3] OF BYTE; d, e : BOOL; s : WORD;
END_VAR
BEGIN
  "Out".w0 := INT_TO_WORD(FC5());
  AG_SEND(ACT := TRUE, ID := 1, LADDR := W#16#100, SEND := buf, LEN := 4, DONE => d,
          ERROR => e, STATUS => s);
  "Out".w1 := s;
END_ORGANIZATION_BLOCK
"""
    )
    cpu = build(source, profile="S7-300", scans=1)
    assert words(cpu)[:2] == (42, 0x8181)


GET_BLOCK_NAME = (
    OUT
    + """
FUNCTION_BLOCK "Unit_Test_Valve"
VAR
  me : WSTRING;
  short : WSTRING[10];
END_VAR
  #me := GetBlockName(SIZE := 100);
  #short := GetBlockName(UINT#4);
  "Out".w0 := INT_TO_WORD(LEN(#me));
  "Out".b0 := #me = WSTRING#'Unit_Test_Valve';
  "Out".b1 := #short = WSTRING#'Unit';
END_FUNCTION_BLOCK
DATA_BLOCK "TestDB" "Unit_Test_Valve"
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "TestDB"();
END_ORGANIZATION_BLOCK
"""
)


def test_get_block_name_gives_the_calling_block_name() -> None:
    cpu = build(GET_BLOCK_NAME, profile="S7-1500", scans=1)
    assert words(cpu)[0] == len("Unit_Test_Valve")
    assert bools(cpu)[:2] == (1, 1)


def test_get_block_name_needs_the_s7_1500_profile() -> None:
    assert "SCL500" in codes(GET_BLOCK_NAME, "S7-300")


def test_a_data_parameter_takes_a_variable_not_a_value() -> None:
    source = """FUNCTION_BLOCK FB1
VAR
  d : BOOL;
  r : INT;
  s : WORD;
END_VAR
  AG_RECV(ID := 1, LADDR := W#16#1, RECV := 5, NDR => d, ERROR => d, STATUS => s, LEN => r);
  AG_SEND(ACT := d, ID := 1, LADDR := W#16#1, SEND := r + 1, LEN := 2, DONE => d, ERROR => d,
          STATUS => s);
END_FUNCTION_BLOCK
"""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-300")
    found = [(d.code, d.span.line, d.span.column) for d in result.diagnostics]
    assert found == [("SCL951", 7, 45), ("SCL951", 8, 55)]
    assert result.diagnostics[0].message.startswith("RECV of AG_RECV points at the data")


def test_get_block_name_without_size_is_named_as_tia_spells_it() -> None:
    source = GET_BLOCK_NAME.replace("GetBlockName(SIZE := 100)", "GetBlockName()")
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    messages = [d.message for d in result.diagnostics if d.code == "SCL227"]
    assert messages == ["The call of GetBlockName must supply SIZE."]
