"""Block calls: FC parameters by reference, FB instances and multi-instances, limits."""

from __future__ import annotations

from builder import (
    DBW,
    DBX,
    INT,
    MD,
    MW,
    I,
    M,
    Q,
    after,
    block,
    db,
    ins,
    reg,
    run_ob1,
    stw_bits,
    var,
)

from nasaq.cpu import Profile
from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    CallInfo,
    Instruction,
    MultiInstance,
    ParamRef,
    RegisterIndirect,
    TimerRef,
    Width,
)

FC1 = BlockRef(BlockKind.FC, 1)
FB1 = BlockRef(BlockKind.FB, 1)


def call(blk: BlockRef, instance: object = None, **args: object) -> Instruction:
    info = CallInfo(blk, instance, tuple(CallArg(k, v) for k, v in args.items()))  # type: ignore[arg-type]
    return Instruction("CALL", call=info)


def adder_fc() -> object:
    """FC1: OUT := A + B; DONE := EN; RET_VAL := 1; IO := IO + 1."""
    return block(
        BlockKind.FC,
        1,
        [
            ins("L", ParamRef(0, "A", Width.WORD)),
            ins("L", ParamRef(1, "B", Width.WORD)),
            ins("+I"),
            ins("T", ParamRef(2, "OUT", Width.WORD)),
            ins("A", ParamRef(3, "EN", Width.BIT)),
            ins("=", ParamRef(4, "DONE", Width.BIT)),
            ins("L", ParamRef(5, "IO", Width.WORD)),
            ins("+", INT(1)),
            ins("T", ParamRef(5, "IO", Width.WORD)),
            ins("L", INT(1)),
            ins("T", ParamRef(6, "RET_VAL", Width.WORD)),
            ins("SET"),
            ins("SAVE"),
        ],
        interface=[
            var("A", "INT", "IN", 0, 16),
            var("B", "INT", "IN", 16, 16),
            var("EN", "BOOL", "IN", 32, 1),
            var("OUT", "INT", "OUT", 48, 16),
            var("DONE", "BOOL", "OUT", 64, 1),
            var("IO", "INT", "IN_OUT", 80, 16),
            var("RET_VAL", "INT", "RETURN", 96, 16),
        ],
    )


def test_fc_parameters_by_reference() -> None:
    cpu = after(
        ins("SET"),
        ins("=", M(0, 0)),
        ins("L", INT(40)),
        ins("T", MW(2)),
        ins("L", INT(5)),
        ins("T", DBW(3, 0)),
        call(
            FC1,
            A=MW(2),
            B=INT(2),
            EN=M(0, 0),
            OUT=MW(4),
            DONE=Q(0, 1),
            IO=DBW(3, 0),
            RET_VAL=MW(6),
        ),
        ins("A", __import__("nasaq.ir", fromlist=["StatusCondition"]).StatusCondition.BR),
        ins("=", M(0, 1)),
        extra=(adder_fc(), db(3, 4)),
    )
    assert cpu.read(MW(4)) == 42
    assert cpu.read(Q(0, 1)) == 1
    assert cpu.read(DBW(3, 0)) == 6
    assert cpu.read(MW(6)) == 1
    assert cpu.read(M(0, 1)) == 1  # BR from the FC's SAVE is seen after the call
    s = stw_bits(cpu.stw)
    assert (s["FC"], s["OR"]) == (0, 0)


def test_status_after_call() -> None:
    cpu = after(ins("SET"), call(FC1, A=INT(1), B=INT(1), OUT=MW(0), IO=MW(2)), extra=(adder_fc(),))
    s = stw_bits(cpu.stw)
    assert (s["FC"], s["OR"], s["STA"], s["OS"]) == (0, 0, 1, 0)


def test_fc_parameter_passed_on_to_another_fc() -> None:
    fc2 = block(
        BlockKind.FC,
        2,
        [call(FC1, A=ParamRef(0, "X", Width.WORD), B=INT(100), OUT=ParamRef(1, "Y", Width.WORD))],
        interface=[var("X", "INT", "IN", 0, 16), var("Y", "INT", "OUT", 16, 16)],
    )
    cpu = after(
        ins("L", INT(7)),
        ins("T", MW(10)),
        call(BlockRef(BlockKind.FC, 2), X=MW(10), Y=MW(12)),
        extra=(adder_fc(), fc2),
    )
    assert cpu.read(MW(12)) == 107


def test_fc_timer_parameter() -> None:
    fc = block(
        BlockKind.FC,
        3,
        [
            ins("A", ParamRef(0, "S", Width.BIT)),
            ins("L", __import__("builder").S5T(50)),
            ins("SD", ParamRef(1, "T", None)),
            ins("A", ParamRef(1, "T", None)),
            ins("=", ParamRef(2, "Q", Width.BIT)),
        ],
        interface=[
            var("S", "BOOL", "IN", 0, 1),
            var("T", "TIMER", "IN", 16, 16),
            var("Q", "BOOL", "OUT", 32, 1),
        ],
    )
    cpu = run_ob1(
        call(BlockRef(BlockKind.FC, 3), S=I(0, 0), T=TimerRef(4), Q=Q(0, 0)), extra=(fc,), scans=0
    )
    cpu.set_input(I(0, 0), 1)
    cpu.run(5)
    assert cpu.read(Q(0, 0)) == 0
    cpu.run(1)
    assert cpu.read(Q(0, 0)) == 1
    assert cpu.timer(4)[0] == 1


def counter_fb() -> object:
    """FB1: IN RUN (bit 0.0), STAT COUNT (word 2), OUT OUT (word 4): if RUN, COUNT += 1."""
    stat = RegisterIndirect(Width.WORD, Area.DI, 2, 16)
    return block(
        BlockKind.FB,
        1,
        [
            ins("A", RegisterIndirect(Width.BIT, Area.DI, 2, 0)),
            ins("JCN", __import__("builder").lbl("SKIP")),
            ins("L", stat),
            ins("+", INT(1)),
            ins("T", stat),
            ins("L", stat, label="SKIP"),
            ins("T", RegisterIndirect(Width.WORD, Area.DI, 2, 32)),
            ins("L", __import__("nasaq.ir", fromlist=["Register"]).Register("DINO")),
            ins("T", RegisterIndirect(Width.WORD, Area.DI, 2, 48)),
        ],
        interface=[
            var("RUN", "BOOL", "IN", 0, 1),
            var("COUNT", "INT", "STAT", 16, 16),
            var("OUT", "INT", "OUT", 32, 16),
            var("SEEN_DI", "INT", "STAT", 48, 16),
        ],
    )


def test_fb_instance_data_persists() -> None:
    cpu = run_ob1(
        ins("SET"),
        ins("=", M(0, 0)),
        call(FB1, BlockRef(BlockKind.DB, 10), RUN=M(0, 0), OUT=MW(20)),
        call(FB1, BlockRef(BlockKind.DB, 11), RUN=INT(0), OUT=MW(22)),
        extra=(counter_fb(), db(10, 8, instance_of=1), db(11, 8, instance_of=1)),
        scans=3,
    )
    assert cpu.read(MW(20)) == 3
    assert cpu.read(MW(22)) == 0
    assert cpu.read(DBW(10, 2)) == 3
    assert cpu.read(DBW(10, 6)) == 10
    assert cpu.read(DBX(10, 0, 0)) == 1


def test_multi_instances_use_ar2_offsets() -> None:
    outer = block(
        BlockKind.FB,
        2,
        [
            call(FB1, MultiInstance(64, "first"), RUN=M(0, 0), OUT=MW(30)),
            call(FB1, MultiInstance(128, "second"), RUN=M(0, 1), OUT=MW(32)),
            ins("TAR2"),
            ins("T", RegisterIndirect(Width.DWORD, Area.DI, 2, 0)),
        ],
        interface=[
            var("AR2_SEEN", "DWORD", "STAT", 0, 32),
            var("first", "FB1", "STAT", 64, 64),
            var("second", "FB1", "STAT", 128, 64),
        ],
    )
    cpu = run_ob1(
        ins("SET"),
        ins("=", M(0, 0)),
        call(BlockRef(BlockKind.FB, 2), BlockRef(BlockKind.DB, 20)),
        extra=(counter_fb(), outer, db(20, 24, instance_of=2)),
        scans=2,
    )
    assert cpu.read(MW(30)) == 2
    assert cpu.read(MW(32)) == 0
    assert cpu.read(DBW(20, 8 + 2)) == 2  # first.COUNT
    assert cpu.read(DBW(20, 16 + 2)) == 0
    assert cpu.read(DBW(20, 8 + 6)) == 20  # the DI register stayed DB20
    assert cpu.db_bytes(20)[0:4] == bytes([0x84, 0, 0, 0])  # AR2 restored after the calls


def test_db_registers_restored_after_call() -> None:
    fc = block(BlockKind.FC, 5, [ins("OPN", BlockRef(BlockKind.DB, 4))])
    cpu = after(
        ins("OPN", BlockRef(BlockKind.DB, 3)),
        ins("UC", BlockRef(BlockKind.FC, 5)),
        ins("L", __import__("nasaq.ir", fromlist=["Register"]).Register("DBNO")),
        extra=(fc, db(3, 2), db(4, 2)),
    )
    assert cpu.accu1 == 3


def test_uc_and_cc() -> None:
    fc = block(BlockKind.FC, 5, [ins("L", MW(0)), ins("+", INT(1)), ins("T", MW(0))])
    cpu = after(
        ins("UC", BlockRef(BlockKind.FC, 5)),
        ins("CLR"),
        ins("CC", BlockRef(BlockKind.FC, 5)),
        ins("SET"),
        ins("CC", BlockRef(BlockKind.FC, 5)),
        extra=(fc,),
    )
    assert cpu.read(MW(0)) == 2


def test_endless_recursion_stops_at_the_nesting_limit() -> None:
    fc = block(BlockKind.FC, 1, [ins("UC", FC1)])
    cpu = run_ob1(ins("UC", FC1), extra=(fc,))
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM508"
    assert "16" in (cpu.stop_reason or "")
    assert cpu.stop_reason.startswith("FC1")
    cpu = run_ob1(ins("UC", FC1), extra=(fc,), profile=Profile.S7_400)
    assert cpu.stop_code == "SIM508"
    assert "24" in (cpu.stop_reason or "")


def test_local_stack_overflow() -> None:
    fc = block(BlockKind.FC, 1, [ins("UC", BlockRef(BlockKind.FC, 2))], temp_bytes=1500)
    fc2 = block(BlockKind.FC, 2, [ins("L", INT(1))], temp_bytes=1000)
    cpu = run_ob1(ins("UC", FC1), extra=(fc, fc2))
    assert cpu.stop_code == "SIM509"


def test_missing_block_and_stop_sfc() -> None:
    cpu = run_ob1(ins("UC", BlockRef(BlockKind.FC, 77)))
    assert cpu.stop_code == "SIM506"
    assert "FC 77" in (cpu.stop_reason or "")
    cpu = run_ob1(ins("L", INT(1)), call(BlockRef(BlockKind.SFC, 46)), ins("T", MW(0)))
    assert cpu.mode == "STOP"
    assert cpu.stopped_by_program
    assert cpu.stop_code == "SIM502"
    assert cpu.read(MW(0)) == 0


def test_time_tck() -> None:
    cpu = run_ob1(call(BlockRef(BlockKind.SFC, 64), RET_VAL=__import__("builder").MD(0)), scans=3)
    assert cpu.read(__import__("builder").MD(0)) == 20


def test_call_fb_with_instance_db_swaps_db_and_di_like_the_call_macro() -> None:
    """CALL FB n, DB m is STEP 7's TDB / OPN DI m / UC FB n / TDB: the FB starts with DB = the
    caller's DI and DI = DB m; afterwards the caller has DB = DB m and its DI back."""
    fb = block(
        BlockKind.FB,
        3,
        [
            ins("L", reg("DBNO")),
            ins("T", MW(0)),
            ins("L", reg("DINO")),
            ins("T", MW(2)),
            ins("OPN", BlockRef(BlockKind.DB, 1)),
            ins("OPN", BlockRef(BlockKind.DI, 2)),
        ],
    )
    cpu = after(
        ins("OPN", BlockRef(BlockKind.DB, 12)),
        ins("OPN", BlockRef(BlockKind.DI, 13)),
        call(BlockRef(BlockKind.FB, 3), BlockRef(BlockKind.DB, 11)),
        ins("L", reg("DBNO")),
        ins("T", MW(4)),
        ins("L", reg("DINO")),
        ins("T", MW(6)),
        extra=(fb, db(1, 2), db(2, 2), db(11, 2, instance_of=3), db(12, 2), db(13, 2)),
    )
    assert [cpu.read(MW(k)) for k in (0, 2, 4, 6)] == [13, 11, 11, 13]


def test_fb_keeps_its_ar2_over_fc_calls() -> None:
    """Inside an FB, AR2 is the instance base: CALL keeps it whatever the FC does with AR2."""
    from builder import P

    fc = block(BlockKind.FC, 4, [ins("LAR2", P(84))])
    fb = block(
        BlockKind.FB,
        3,
        [
            call(BlockRef(BlockKind.FC, 4)),
            ins("TAR2"),
            ins("T", MD(0)),
            ins("UC", BlockRef(BlockKind.FC, 4)),  # UC is no macro: AR2 comes back changed
            ins("TAR2"),
            ins("T", MD(4)),
        ],
    )
    cpu = after(
        call(BlockRef(BlockKind.FB, 3), BlockRef(BlockKind.DB, 11)),
        extra=(fc, fb, db(11, 2, instance_of=3)),
    )
    assert cpu.read(MD(0)) == 0x84000000
    assert cpu.read(MD(4)) == P(84).pattern
