"""Jumps, LOOP, JL: control flow and the status bits jumps write."""

from __future__ import annotations

from builder import INT, MW, M, after, ins, lbl, run_ob1, stw_bits

from nasaq.ir import StatusCondition


def test_jc_and_jcn_set_rlo_whether_or_not_they_jump() -> None:
    for op, rlo_before, jumps in (
        ("JC", 1, True),
        ("JC", 0, False),
        ("JCN", 0, True),
        ("JCN", 1, False),
    ):
        cpu = after(
            ins("SET" if rlo_before else "CLR"),
            ins(op, lbl("END")),
            ins("L", INT(1)),
            ins("T", MW(0)),
            ins("NOP", INT(0), label="END"),
        )
        assert cpu.read(MW(0)) == (0 if jumps else 1), op
        s = stw_bits(cpu.stw)
        assert (s["RLO"], s["STA"], s["OR"], s["FC"]) == (1, 1, 0, 0)


def test_jcb_copies_rlo_to_br() -> None:
    s = stw_bits(after(ins("SET"), ins("JCB", lbl("E")), ins("NOP", INT(0), label="E")).stw)
    assert s["BR"] == 1
    s = stw_bits(after(ins("CLR"), ins("JNB", lbl("E")), ins("NOP", INT(0), label="E")).stw)
    assert s["BR"] == 0
    assert s["RLO"] == 1


def test_jbi_jnbi() -> None:
    cpu = after(
        ins("SET"),
        ins("SAVE"),
        ins("JBI", lbl("E")),
        ins("L", INT(1)),
        ins("T", MW(0)),
        ins("NOP", INT(0), label="E"),
    )
    assert cpu.read(MW(0)) == 0


def test_result_jumps() -> None:
    def jumped(op: str, x: int, y: int) -> bool:
        cpu = after(
            ins("L", INT(x)),
            ins("L", INT(y)),
            ins("-I"),
            ins(op, lbl("E")),
            ins("L", INT(1)),
            ins("T", MW(0)),
            ins("NOP", INT(0), label="E"),
        )
        return cpu.read(MW(0)) == 0

    assert jumped("JZ", 3, 3)
    assert not jumped("JZ", 3, 2)
    assert jumped("JN", 3, 2)
    assert not jumped("JN", 2, 2)
    assert jumped("JP", 3, 2)
    assert not jumped("JP", 2, 3)
    assert jumped("JM", 2, 3)
    assert not jumped("JM", 3, 2)
    assert jumped("JPZ", 3, 3)
    assert jumped("JPZ", 4, 3)
    assert not jumped("JPZ", 2, 3)
    assert jumped("JMZ", 3, 3)
    assert jumped("JMZ", 2, 3)
    assert not jumped("JMZ", 4, 3)
    assert jumped("JO", 32767, -1)
    assert not jumped("JO", 1, 1)
    assert not jumped("JUO", 1, 1)


def test_jos_resets_os() -> None:
    cpu = after(
        ins("L", INT(32767)),
        ins("L", INT(1)),
        ins("+I"),
        ins("L", INT(0)),
        ins("L", INT(0)),
        ins("+I"),
        ins("JOS", lbl("E")),
        ins("L", INT(1)),
        ins("T", MW(0)),
        ins("NOP", INT(0), label="E"),
    )
    assert cpu.read(MW(0)) == 0
    assert stw_bits(cpu.stw)["OS"] == 0


def test_loop_sums() -> None:
    cpu = after(
        ins("L", INT(10)),
        ins("T", MW(0), label="NEXT"),
        ins("L", MW(2)),
        ins("L", MW(0)),
        ins("+I"),
        ins("T", MW(2)),
        ins("L", MW(0)),
        ins("LOOP", lbl("NEXT")),
    )
    assert cpu.read(MW(2)) == 55
    assert cpu.instructions_executed == 1 + 10 * 7


def test_backward_jump_loop_and_nested_loops() -> None:
    cpu = after(
        ins("L", INT(3)),
        ins("T", MW(0), label="OUT"),
        ins("L", INT(4)),
        ins("T", MW(4), label="IN"),
        ins("L", MW(6)),
        ins("+", INT(1)),
        ins("T", MW(6)),
        ins("L", MW(4)),
        ins("LOOP", lbl("IN")),
        ins("L", MW(0)),
        ins("LOOP", lbl("OUT")),
    )
    assert cpu.read(MW(6)) == 12


def test_jump_list() -> None:
    def pick(index: int) -> int:
        cpu = after(
            ins("L", INT(index)),
            ins("JL", lbl("LEND")),
            ins("JU", lbl("C0")),
            ins("JU", lbl("C1")),
            ins("JU", lbl("C2")),
            ins("L", INT(99), label="LEND"),
            ins("JU", lbl("DONE")),
            ins("L", INT(10), label="C0"),
            ins("JU", lbl("DONE")),
            ins("L", INT(11), label="C1"),
            ins("JU", lbl("DONE")),
            ins("L", INT(12), label="C2"),
            ins("T", MW(0), label="DONE"),
        )
        return cpu.read(MW(0))

    assert [pick(k) for k in range(5)] == [10, 11, 12, 99, 99]


def test_ju_skips_code_and_crossing_backward_jumps() -> None:
    cpu = after(
        ins("JU", lbl("B")),
        ins("L", INT(1), label="A"),
        ins("T", MW(0)),
        ins("JU", lbl("C")),
        ins("L", MW(2), label="B"),
        ins("+", INT(5)),
        ins("T", MW(2)),
        ins("JU", lbl("A")),
        ins("NOP", INT(0), label="C"),
    )
    assert cpu.read(MW(0)) == 1
    assert cpu.read(MW(2)) == 5


def test_status_condition_jump_on_a_unordered_compare() -> None:
    s = StatusCondition.UO
    cpu = after(ins("A", s), ins("=", M(0, 0)))
    assert cpu.read(M(0, 0)) == 0


def test_endless_loop_stops_on_watchdog_quickly() -> None:
    import time

    started = time.perf_counter()
    cpu = run_ob1(ins("L", INT(1), label="X"), ins("JU", lbl("X")))
    assert time.perf_counter() - started < 2
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM501"
    assert cpu.stop_reason is not None
    assert cpu.stop_reason.startswith("OB1 network 1, line 1")
