"""The code generator's substitution of single-use temporaries (``codegen.compiler``)."""

from __future__ import annotations

from nasaq.cpu.codegen.compiler import _BB, _inline_temps
from nasaq.cpu.codegen.model import Stmt, Term


def _stmt(line: str, defs: tuple[str, ...] = (), uses: tuple[str, ...] = ()) -> Stmt:
    return Stmt([line], frozenset(defs), frozenset(uses), False, 0)


def _lines(bb: _BB) -> list[str]:
    return [line for stmt in _inline_temps(bb) for line in stmt.lines]


def test_a_temporary_used_once_by_the_next_statement_is_substituted() -> None:
    bb = _BB(0, 2, [_stmt("_t1 = a + 1", ("_t1",), ("a",)), _stmt("b = _t1 * 2", ("b",), ("_t1",))])
    assert _lines(bb) == ["b = (a + 1) * 2"]
    assert _inline_temps(bb)[0].uses == frozenset({"a"})


def test_chains_collapse_into_one_statement() -> None:
    bb = _BB(
        0,
        3,
        [
            _stmt("_t1 = a + 1", ("_t1",)),
            _stmt("_t2 = _t1 * 2", ("_t2",)),
            _stmt("b = _t2 - c", ("b",)),
        ],
    )
    assert _lines(bb) == ["b = ((a + 1) * 2) - c"]


def test_a_temporary_read_again_later_or_twice_or_by_the_branch_stays() -> None:
    later = _BB(
        0,
        3,
        [_stmt("_t1 = a + 1", ("_t1",)), _stmt("b = _t1", ("b",)), _stmt("c = _t1", ("c",))],
    )
    assert _lines(later) == ["_t1 = a + 1", "b = _t1", "c = _t1"]
    twice = _BB(0, 2, [_stmt("_t1 = a + 1", ("_t1",)), _stmt("b = _t1 * _t1", ("b",))])
    assert _lines(twice) == ["_t1 = a + 1", "b = _t1 * _t1"]
    branch = _BB(
        0,
        2,
        [_stmt("_t1 = a + 1", ("_t1",)), _stmt("b = _t1", ("b",))],
        Term("cond", cond="_t1 > 0"),
    )
    assert _lines(branch) == ["_t1 = a + 1", "b = _t1"]


def test_names_that_only_share_a_prefix_are_not_confused() -> None:
    bb = _BB(
        0,
        3,
        [_stmt("_t1 = a", ("_t1",)), _stmt("b = _t1 + _t10", ("b",)), _stmt("c = _t10", ("c",))],
    )
    assert _lines(bb) == ["b = (a) + _t10", "c = _t10"]


def test_a_long_straight_block_keeps_every_statement_in_order() -> None:
    """Thousands of statements in one basic block (a long SCL function without branches)."""
    stmts: list[Stmt] = []
    for k in range(3000):
        stmts += [_stmt(f"_t{k} = x + {k}", (f"_t{k}",)), _stmt(f"m[{k}] = _t{k}", (f"m{k}",))]
    lines = _lines(_BB(0, len(stmts), stmts))
    assert lines == [f"m[{k}] = (x + {k})" for k in range(3000)]
