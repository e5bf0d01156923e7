"""Complete sources: STEP 7 exports from the course (research notes §4.5 and Appendix 7) and
an awlsim-style self-checking program (plain lines, German mnemonics, test instructions)."""

from __future__ import annotations

from stl_helpers import block, code_of, compile_text

from nasaq.ir import Area, BlockKind, BlockRef, Direct, RegisterIndirect, Width
from nasaq.lang.stl import SourceFile

FB1 = """FUNCTION_BLOCK FB1
TITLE =
AUTHOR : IJ
VERSION : 0.1

VAR_OUTPUT
  SSL_error : BOOL ;
END_VAR
VAR
  t_lvw : INT ;
END_VAR
VAR_TEMP
  v_max_l : INT ;
  v_min_l : INT ;
END_VAR
BEGIN
NETWORK
TITLE =
  A "DO_SpLVw";
  AN "DI_SpLHinten";
  JNB _001;
  L #t_lvw;
  L "KomDB".allg.last_cycl;
  +I ;
  T #t_lvw;
_001: NOP 0;
END_FUNCTION_BLOCK
"""

KOMDB = """DATA_BLOCK "KomDB"
  STRUCT
    allg : STRUCT
      spare : BOOL;
      last_cycl : INT := 10;
    END_STRUCT;
  END_STRUCT;
BEGIN
END_DATA_BLOCK
"""

SYMBOLS = "DO_SpLVw,Q 4.0,BOOL,\nDI_SpLHinten,I 1.0,BOOL,\nKomDB,DB 20,DB 20,\n"


def test_fb1_from_the_course() -> None:
    result = compile_text(FB1 + KOMDB, SourceFile("symbols.csv", SYMBOLS))
    assert result.ok, result.diagnostics
    fb = block(result, "FB", 1)
    assert [(var.section, var.name) for var in fb.interface] == [
        ("OUT", "SSL_error"),
        ("STAT", "t_lvw"),
        ("TEMP", "v_max_l"),
        ("TEMP", "v_min_l"),
    ]
    assert fb.attributes == {"AUTHOR": "IJ", "VERSION": "0.1"}
    assert [item.op for item in fb.code] == ["A", "AN", "JNB", "L", "L", "+I", "T", "NOP"]
    assert fb.code[3].operand == RegisterIndirect(Width.WORD, Area.DI, 2, 16)
    assert fb.code[4].operand == Direct(Area.DB, Width.WORD, 2, 0, 20)
    assert block(result, "DB", 20).data == b"\x00\x00\x00\x0a"


HEATING = """DATA_BLOCK DB 36
TITLE =
AUTHOR : SIMATIC
NAME : DL_PULSE
VERSION : 1.0
SFB 49
BEGIN
  LADDR := W#16#300;
END_DATA_BLOCK

FUNCTION_BLOCK FB 32
TITLE =Heating a liquid
//An electrical heating element heats a liquid.
AUTHOR : SIMATIC
NAME : HEATING
VERSION : 1.0
VAR
  START : BOOL ;\t\t//Control signal: Heating ON
  POWER : INT ;
  PERIOD : DINT := L#1000;
  STS_DO : BOOL ;
  JOB_REQ : BOOL ;
  OUTP_VAL : INT ;
  PERIOD_LOAD : DINT ;
END_VAR
BEGIN
NETWORK
TITLE =Specify heating power
      L     DB32.DBW    2;
      L     10;
      *I    ;
      T     #OUTP_VAL;
NETWORK
TITLE =load period
      L     #PERIOD_LOAD;
      L     DB32.DBD    4;
      <>D   ;
      =     #JOB_REQ;
      T     #PERIOD_LOAD;
NETWORK
TITLE =Call of SFB PULSE
      A     DB32.DBX    0.0;
      =     L      0.0;
      BLD   103;
      CALL SFB 49 , DB 36 (
           CHANNEL                  := 0,
           SW_EN                    := L      0.0,
           OUTP_VAL                 := #OUTP_VAL,
           JOB_ID                   := W#16#1,
           JOB_VAL                  := #PERIOD,
           STS_DO                   := #STS_DO);
      NOP   0;
END_FUNCTION_BLOCK

DATA_BLOCK DB 32
AUTHOR : SIMATIC
NAME : DL_HEAT
VERSION : 1.0
FB 32
BEGIN
   START := FALSE;
   POWER := 0;
   PERIOD := L#1000;
   PERIOD_LOAD := L#0;
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
TITLE =Cycle Execution
VERSION : 1.0
VAR_TEMP
  L_BEARB : BOOL ;
END_VAR
BEGIN
NETWORK
TITLE =Call of sample "PWM 2, Heating"
      CALL FB 32 , DB 32 ;
      BE    ;
END_ORGANIZATION_BLOCK
"""


def test_heating_example_with_an_sfb_instance() -> None:
    result = compile_text(HEATING.replace("\n", "\r\n"))
    assert result.ok, result.diagnostics
    fb = block(result, "FB", 32)
    assert [net.title for net in fb.networks] == [
        "Specify heating power",
        "load period",
        "Call of SFB PULSE",
    ]
    assert fb.interface[0].comment == "Control signal: Heating ON"
    db32 = block(result, "DB", 32)
    assert db32.instance_of == 32
    assert db32.data[4:8] == (1000).to_bytes(4, "big")
    (call,) = [item for item in code_of(result) if item.op == "CALL"]
    assert call.call is not None
    assert call.call.instance == BlockRef(BlockKind.DB, 32)


SELF_CHECK = """
	// plain lines, German mnemonics, no block header: an implicit OB 1
	L		W#16#1234
	T		MW 0
	__ASSERT==	MW 0,		W#16#1234
	U		E 0.0
	SPBN		_001
	__ASSERT==	__STW VKE,	1
_001:	NOP		0
	L		__CNST_PI
	__STWRST
	CALL SFC 46 // STOP CPU
"""


def test_awlsim_style_program() -> None:
    result = compile_text(SELF_CHECK, test_ops=True)
    assert result.ok, result.diagnostics
    assert [item.op for item in code_of(result)] == [
        "L",
        "T",
        "__ASSERT==",
        "A",
        "JCN",
        "__ASSERT==",
        "NOP",
        "L",
        "__STWRST",
        "CALL",
    ]
