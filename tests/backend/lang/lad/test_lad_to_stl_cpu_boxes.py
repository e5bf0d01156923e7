"""Every box family, lowered and run on the CPU: the outputs are what the box means, ENO is false
when the operation fails, and a box whose EN is off leaves its output alone."""

from __future__ import annotations

import math

import pytest
from lad_to_stl_run import c, coil, get, net, ob1, plc, put, s, scan, where

from nasaq.lang.lad.model import Box, Coil, Jump, LadBlock, Network, OpenDb, Output, Return


def box(name: str, instance: str | None = None, **pins: str) -> Box:
    inputs = {k: v for k, v in pins.items() if k.isupper() and k not in OUT_PINS}
    outputs = {k: str(v) for k, v in pins.items() if k in OUT_PINS}
    return Box(name=name, instance=instance, inputs=inputs, outputs=outputs)


OUT_PINS = {"OUT", "ENO", "Q", "BI", "BCD", "CV", "CV_BCD"}


def ends(target: Box | Coil | Jump | Return | OpenDb) -> list[Output]:
    return [Output(target=target)]


def run_en_box(name: str, real: bool = False, **pins: str) -> tuple[int | float, int]:
    """OUT and ENO of the box in a rung ``I 0.0 -- box -- Q 4.0`` (EN on)."""
    cpu = plc(ob1(net(c("I 0.0"), box(name, OUT="MD 20", **pins))))
    put(cpu, I0_0=1)
    scan(cpu)
    return get(cpu, "MD 20", real=real), int(get(cpu, "Q 4.0"))


@pytest.mark.parametrize(
    ("name", "a", "b", "expected"),
    [("CMP>=I", 5, 5, 1), ("CMP>I", 5, 5, 0), ("CMP<>I", 4, 5, 1), ("CMP<I", -3, 2, 1)],
)
def test_compare_is_a_contact_in_the_chain(name: str, a: int, b: int, expected: int) -> None:
    cpu = plc(ob1(net(c("I 0.0"), box(name, IN1="MW 0", IN2="MW 2"))))
    put(cpu, I0_0=1, MW0=a, MW2=b)
    scan(cpu)
    assert get(cpu, "Q 4.0") == expected
    put(cpu, I0_0=0)
    scan(cpu)
    assert get(cpu, "Q 4.0") == 0


def test_real_and_dint_compares_from_the_rail() -> None:
    cpu = plc(
        ob1(
            net(box("CMP<R", IN1="MD 0", IN2="MD 4")),
            net(box("CMP==D", IN1="MD 8", IN2="L#70000"), outputs=[coil("Q 4.1")]),
        )
    )
    put(cpu, MD0=1.5, MD4=2.25, MD8=70000)
    scan(cpu)
    assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1")) == (1, 1)


def test_move_runs_only_with_en_and_passes_eno() -> None:
    cpu = plc(ob1(net(c("I 0.0"), box("MOVE", IN="MW 0", OUT="MW 2"), c("I 0.1"))))
    put(cpu, I0_0=0, I0_1=1, MW0=42, MW2=7)
    scan(cpu)
    assert (get(cpu, "MW 2"), get(cpu, "Q 4.0")) == (7, 0)
    put(cpu, I0_0=1)
    scan(cpu)
    assert (get(cpu, "MW 2"), get(cpu, "Q 4.0")) == (42, 1)


@pytest.mark.parametrize(
    ("name", "a", "b", "out", "eno"),
    [
        ("ADD_I", 30000, 2767, 32767, 1),
        ("ADD_I", 30000, 2768, None, 0),  # overflow: ENO off
        ("SUB_I", 5, 9, -4, 1),
        ("MUL_I", 300, 300, None, 0),
        ("DIV_I", 7, 2, 3, 1),
        ("ADD_DI", 70000, 5, 70005, 1),
        ("MOD_DI", 17, 5, 2, 1),
        ("DIV_DI", 17, 0, None, 0),
    ],
)
def test_integer_math_and_its_eno(name: str, a: int, b: int, out: int | None, eno: int) -> None:
    wide = name.endswith("DI")
    first, second, result = ("MD 0", "MD 4", "MD 20") if wide else ("MW 0", "MW 2", "MW 20")
    cpu = plc(ob1(net(c("I 0.0"), box(name, IN1=first, IN2=second, OUT=result))))
    put(cpu, I0_0=1, **{first.replace(" ", ""): a, second.replace(" ", ""): b})
    scan(cpu)
    assert get(cpu, "Q 4.0") == eno
    if out is not None:
        assert get(cpu, result) == out


def test_real_math_functions_and_conversions() -> None:
    assert run_en_box("ADD_R", True, IN1="2.5", IN2="0.5") == (3.0, 1)
    assert run_en_box("SQRT", True, IN="16.0") == (4.0, 1)
    assert run_en_box("SQR", True, IN="3.0") == (9.0, 1)
    assert run_en_box("SIN", True, IN="0.5")[0] == pytest.approx(math.sin(0.5))
    assert run_en_box("LN", True, IN="-1.0")[1] == 0  # invalid: ENO off
    assert run_en_box("ROUND", IN="2.5") == (2, 1)
    assert run_en_box("TRUNC", IN="-2.7") == (-2, 1)
    assert run_en_box("CEIL", IN="2.1") == (3, 1)
    assert run_en_box("FLOOR", IN="-2.1") == (-3, 1)
    assert run_en_box("DI_R", True, IN="L#7") == (7.0, 1)
    assert run_en_box("NEG_R", True, IN="1.5") == (-1.5, 1)
    assert run_en_box("ABS", True, IN="-1.5") == (1.5, 1)


def test_integer_conversions() -> None:
    cpu = plc(
        ob1(
            net(c("I 0.0"), box("I_BCD", IN="MW 0", OUT="MW 10")),
            net(c("I 0.0"), box("BCD_I", IN="W#16#123", OUT="MW 12"), outputs=[coil("Q 4.1")]),
            net(c("I 0.0"), box("I_DI", IN="MW 0", OUT="MD 14"), outputs=[coil("Q 4.2")]),
            net(c("I 0.0"), box("NEG_I", IN="MW 2", OUT="MW 18"), outputs=[coil("Q 4.3")]),
            net(c("I 0.0"), box("INV_I", IN="MW 0", OUT="MW 20"), outputs=[coil("Q 4.4")]),
            net(c("I 0.0"), box("DI_BCD", IN="L#1234567", OUT="MD 22"), outputs=[coil("Q 4.5")]),
            net(c("I 0.0"), box("BCD_DI", IN="DW#16#99", OUT="MD 26"), outputs=[coil("Q 4.6")]),
            net(c("I 0.0"), box("NEG_DI", IN="L#5", OUT="MD 30"), outputs=[coil("Q 4.7")]),
            net(c("I 0.0"), box("INV_DI", IN="L#0", OUT="MD 34"), outputs=[coil("Q 5.0")]),
        )
    )
    put(cpu, I0_0=1, MW0=-45, MW2=-32768)
    scan(cpu)
    assert get(cpu, "MW 10") == 0xF045 - 0x10000  # sign nibble F, then 045
    assert get(cpu, "MW 12") == 123
    assert get(cpu, "MD 14") == -45
    assert get(cpu, "Q 4.3") == 0  # -(-32768) overflows
    assert get(cpu, "MW 20") == 44
    assert get(cpu, "MD 22") == 0x1234567
    assert get(cpu, "MD 26") == 99
    assert get(cpu, "MD 30") == -5
    assert get(cpu, "MD 34") == -1
    flags = [get(cpu, f"Q 4.{i}") for i in (0, 1, 2, 4, 5, 6, 7)] + [get(cpu, "Q 5.0")]
    assert flags == [1] * 8
    put(cpu, MW0=1000)  # beyond three BCD digits: ENO off
    scan(cpu)
    assert get(cpu, "Q 4.0") == 0


def test_word_logic_and_shifts() -> None:
    cpu = plc(
        ob1(
            net(box("WAND_W", IN1="MW 0", IN2="W#16#FF0", OUT="MW 10", ENO="Q 4.0")),
            net(
                box("WXOR_DW", IN1="MD 2", IN2="DW#16#FFFF0000", OUT="MD 12"),
                outputs=[coil("Q 4.1")],
            ),
            net(box("SHL_W", IN="MW 0", N="W#16#4", OUT="MW 16"), outputs=[coil("Q 4.2")]),
            net(box("SHR_I", IN="MW 6", N="W#16#2", OUT="MW 18"), outputs=[coil("Q 4.3")]),
            net(
                box("ROL_DW", IN="DW#16#80000001", N="W#16#1", OUT="MD 20"), outputs=[coil("Q 4.4")]
            ),
            net(box("WOR_W", IN1="MW 0", IN2="W#16#1", OUT="MW 24"), outputs=[coil("Q 4.5")]),
        )
    )
    put(cpu, MW0=0x1234, MD2=0x0F0F0F0F, MW6=-16)
    scan(cpu)
    assert get(cpu, "MW 10") == 0x0230
    assert int(get(cpu, "MD 12")) & 0xFFFFFFFF == 0xF0F00F0F
    assert get(cpu, "MW 16") == 0x2340
    assert get(cpu, "MW 18") == -4
    assert get(cpu, "MD 20") == 3
    assert get(cpu, "MW 24") == 0x1235
    assert [get(cpu, f"Q 4.{i}") for i in range(6)] == [1] * 6


def test_timer_box_on_delay_with_reset_and_values() -> None:
    timer = box("S_ODT", "T 1", TV="S5T#100MS", R="I 0.1", BI="MW 10", Q="Q 4.1")
    cpu = plc(ob1(net(c("I 0.0"), timer, c("I 0.2"))))
    put(cpu, I0_0=1, I0_1=0, I0_2=1)
    scan(cpu, 2)
    assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1")) == (0, 0)
    assert 0 < get(cpu, "MW 10") < 10
    scan(cpu, 12)
    assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1")) == (1, 1)
    put(cpu, I0_1=1)
    scan(cpu)
    assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1")) == (0, 0)


def test_timer_coil_and_pulse_box_from_the_rail() -> None:
    cpu = plc(
        ob1(
            net(c("I 0.0"), outputs=ends(Coil(coil="SE", operand="T 2", value="S5T#50MS"))),
            net(c("T 2"), outputs=[coil("Q 4.0")]),
            net(box("S_PULSE", "T 3", TV="S5T#50MS", Q="Q 4.1")),
        )
    )
    put(cpu, I0_0=1)
    scan(cpu)
    put(cpu, I0_0=0)
    scan(cpu)
    assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1")) == (1, 1)  # extended pulse runs on
    scan(cpu, 10)
    assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1")) == (0, 0)


def test_counter_boxes_and_coils() -> None:
    up_down = box("S_CUD", "C 1", CD="I 0.1", S="I 0.2", PV="C#5", R="I 0.3", CV="MW 10")
    cpu = plc(
        ob1(
            net(c("I 0.0"), up_down, outputs=[coil("Q 4.0")]),
            net(
                box("S_CU", "C 2", CU="I 0.0", CV_BCD="MW 12", Q="Q 4.1"),
                outputs=ends(box("MOVE", IN="0", OUT="MW 30")),
            ),
            net(c("I 0.4"), outputs=ends(Coil(coil="SC", operand="C 3", value="C#7"))),
            net(c("I 0.0"), outputs=ends(Coil(coil="CD", operand="C 3"))),
            net(c("C 3"), outputs=[coil("Q 4.2")]),
        )
    )
    put(cpu, I0_2=1, I0_4=1)
    scan(cpu)
    put(cpu, I0_2=0, I0_4=0)
    assert (get(cpu, "MW 10"), get(cpu, "Q 4.0")) == (5, 1)
    for _ in range(3):
        put(cpu, I0_0=1)
        scan(cpu)
        put(cpu, I0_0=0)
        scan(cpu)
    assert get(cpu, "MW 10") == 8
    assert get(cpu, "MW 12") == 3  # BCD of 3
    assert get(cpu, "Q 4.1") == 1
    assert cpu.counter(3)[1] == 4
    put(cpu, I0_1=1)
    scan(cpu)
    assert get(cpu, "MW 10") == 7
    put(cpu, I0_3=1)
    scan(cpu)
    assert (get(cpu, "MW 10"), get(cpu, "Q 4.0")) == (0, 0)


@pytest.mark.parametrize(("name", "second", "both"), [("SR", "R1", 0), ("RS", "S1", 1)])
def test_flip_flops_and_their_priority(name: str, second: str, both: int) -> None:
    first = "S" if name == "SR" else "R"
    cpu = plc(ob1(net(c("I 0.0"), box(name, "M 0.0", **{second: "I 0.1"}))))
    put(cpu, I0_0=1, I0_1=1)
    scan(cpu)
    assert (get(cpu, "M 0.0"), get(cpu, "Q 4.0")) == (both, both)
    put(cpu, I0_0=int(first == "S"), I0_1=int(first != "S"))
    scan(cpu)
    assert get(cpu, "Q 4.0") == 1
    put(cpu, I0_0=0, I0_1=0)
    scan(cpu)
    assert get(cpu, "Q 4.0") == 1  # it keeps its state


def test_address_edge_boxes() -> None:
    cpu = plc(
        ob1(
            net(c("I 0.0"), box("POS", "I 0.1", M_BIT="M 1.0")),
            net(
                box("NEG", "I 0.1", M_BIT="M 1.1", Q="Q 4.1"),
                outputs=ends(box("MOVE", IN="1", OUT="MW 2")),
            ),
        )
    )
    trace = []
    for i1 in (0, 1, 1, 0, 0):
        put(cpu, I0_0=1, I0_1=i1)
        scan(cpu)
        trace.append((get(cpu, "Q 4.0"), get(cpu, "Q 4.1")))
    assert trace == [(0, 0), (1, 0), (0, 0), (0, 1), (0, 0)]


def test_jumps_return_and_labels() -> None:
    block = ob1(
        net(c("I 0.0"), outputs=ends(Jump(label="SKIP"))),
        net(outputs=[coil("Q 4.0")]),
        net(c("I 0.1"), outputs=ends(Jump(label="ENDE", negated=True)), label="SKIP"),
        net(outputs=[coil("Q 4.1")]),
        net(c("I 0.2"), outputs=ends(Return()), label="ENDE"),
        net(outputs=[coil("Q 4.2")]),
    )
    cpu = plc(block)
    expected = {(0, 0, 0): (1, 0, 1), (1, 1, 0): (0, 1, 1), (1, 1, 1): (0, 1, 0)}
    for (i0, i1, i2), outs in expected.items():
        cpu.write(where("QB 4"), 0)
        put(cpu, I0_0=i0, I0_1=i1, I0_2=i2)
        scan(cpu)
        assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1"), get(cpu, "Q 4.2")) == outs


def test_open_db_then_data_bits() -> None:
    data = "DATA_BLOCK DB 5\nSTRUCT\n  x : BOOL;\nEND_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
    cpu = plc(
        ob1(
            net(outputs=ends(OpenDb(block="DB 5"))),
            net(c("I 0.0"), outputs=[coil("DBX 0.0")]),
            net(c("DB5.DBX 0.0"), outputs=[coil("Q 4.0")]),
        ),
        data,
    )
    put(cpu, I0_0=1)
    scan(cpu)
    assert get(cpu, "Q 4.0") == 1


FC = """FUNCTION FC 10 : VOID
VAR_INPUT
  a : BOOL;
  n : INT;
END_VAR
VAR_OUTPUT
  y : INT;
END_VAR
BEGIN
      A     #a
      JC    neg
      L     #n
      T     #y
      BEU
neg:  L     #n
      NEGI
      T     #y
      CLR
      SAVE
END_FUNCTION
"""

FB = """FUNCTION_BLOCK FB 5
VAR_INPUT
  step : INT;
END_VAR
VAR
  total : INT;
END_VAR
VAR_OUTPUT
  out : INT;
END_VAR
BEGIN
      L     #total
      L     #step
      +I
      T     #total
      T     #out
END_FUNCTION_BLOCK

DATA_BLOCK DB 10 FB 5
BEGIN
END_DATA_BLOCK
"""


def test_calls_with_en_eno_logic_pins_and_instances() -> None:
    call = Box(
        name="FC 10", inputs={"a": s(c("I 0.1"), c("I 0.2")), "n": "MW 0"}, outputs={"y": "MW 2"}
    )
    fb = Box(name="FB 5", instance="DB 10", inputs={"step": "3"}, outputs={"out": "MW 4"})
    cpu = plc(ob1(net(c("I 0.0"), call), net(c("I 0.3"), outputs=ends(fb))), FC, FB)
    put(cpu, I0_0=0, MW0=9, MW2=1)
    scan(cpu)
    assert (get(cpu, "MW 2"), get(cpu, "Q 4.0")) == (1, 0)  # EN off: not called
    put(cpu, I0_0=1)
    scan(cpu)
    assert (get(cpu, "MW 2"), get(cpu, "Q 4.0")) == (9, 1)
    put(cpu, I0_1=1, I0_2=1)
    scan(cpu)
    assert (get(cpu, "MW 2"), get(cpu, "Q 4.0")) == (-9, 0)  # the FC cleared BR: ENO off
    put(cpu, I0_3=1)
    scan(cpu, 2)
    assert get(cpu, "MW 4") == 6


def test_a_block_with_its_own_declarations_and_a_call_from_the_rail() -> None:
    declarations = "VAR_TEMP\n  t : INT;\nEND_VAR"
    block = LadBlock(
        kind="OB",
        name="OB 1",
        declarations=declarations,
        networks=[
            Network(outputs=ends(box("MOVE", IN="MW 0", OUT="#t"))),
            Network(
                outputs=[
                    Output(
                        target=Box(
                            name="FC 10", inputs={"a": "FALSE", "n": "#t"}, outputs={"y": "MW 2"}
                        )
                    )
                ]
            ),
        ],
    )
    cpu = plc(block, FC)
    put(cpu, MW0=12)
    scan(cpu)
    assert get(cpu, "MW 2") == 12
