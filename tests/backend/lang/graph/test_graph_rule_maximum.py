"""SEMANTICS §1 and §2 with the maximum parameter set: EN_IL/EN_SV (TRUE by default) switch
interlock and supervision checking; HALT_SQ stops switching, HALT_TM the step times; ZERO_OP
writes every N/D/L bit 0 and runs no CALL; the outputs echo them."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, chain, cond, enter_run, make

from nasaq.lang.graph.model import Settings

MAX = Settings(parameters="MAXIMUM")


@pytest.mark.parametrize("kind", KINDS)
def test_en_il_and_en_sv_default_on_and_switch_checking(kind: str) -> None:
    ex = make(
        kind,
        chain(interlock=cond(c("I 0.5")), supervision=cond(c("I 0.6")), settings=MAX),
    )
    enter_run(ex)
    assert ex.out("IL_ENABLED") == 1
    assert ex.out("SV_ENABLED") == 1
    assert ex.step("Run", "LA") == 1
    ex.call({"EN_IL": 0, "EN_SV": 0, "I 0.6": 1})
    assert ex.step("Run", "LA") == 0
    assert ex.step("Run", "VA") == 0
    assert ex.out("IL_ENABLED") == 0
    assert ex.out("SV_ENABLED") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_halt_sq_stops_switching_and_halt_tm_the_times(kind: str) -> None:
    ex = make(kind, chain(settings=MAX))
    enter_run(ex)
    ex.call({"HALT_SQ": 1, "I 0.1": 1})
    assert ex.step("Run") == 1
    assert ex.out("SQ_HALTED") == 1
    assert ex.step("Run", "T") == 100
    ex.call({"HALT_SQ": 0, "HALT_TM": 1, "I 0.1": 0})
    ex.call()
    assert ex.step("Run", "T") == 100
    assert ex.out("TM_HALTED") == 1
    ex.call({"HALT_TM": 0})
    assert ex.step("Run", "T") == 200


@pytest.mark.parametrize("kind", KINDS)
def test_zero_op_zeroes_the_n_d_l_bits(kind: str) -> None:
    ex = make(kind, chain("N Q 5.0", "L Q 5.1, T#10S", "S Q 5.2", settings=MAX))
    enter_run(ex)
    assert (ex.bit("Q 5.0"), ex.bit("Q 5.1"), ex.bit("Q 5.2")) == (1, 1, 1)
    ex.call({"ZERO_OP": 1})
    assert (ex.bit("Q 5.0"), ex.bit("Q 5.1"), ex.bit("Q 5.2")) == (0, 0, 1)
    assert ex.out("OP_ZEROED") == 1
    ex.call({"ZERO_OP": 0})
    assert (ex.bit("Q 5.0"), ex.bit("Q 5.1")) == (1, 1)


@pytest.mark.parametrize("kind", KINDS)
def test_halt_sq_stops_man_switching_too(kind: str) -> None:
    ex = make(kind, chain(settings=MAX))
    ex.call({"SW_MAN": 1, "HALT_SQ": 1})
    ex.call({"S_SEL": 2, "S_ON": 1})
    assert ex.step("Run") == 0
    ex.call({"S_ON": 0, "HALT_SQ": 0})
    ex.call({"S_ON": 1})
    assert ex.step("Run") == 1
