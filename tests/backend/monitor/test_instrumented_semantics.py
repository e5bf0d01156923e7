"""The debugger's compilation must compute exactly what the fast one does.

Every scenario of the repository (the course's STL and SCL programs) runs again with each code
block compiled instrumented, hooks before and after every instruction, and must still pass; the
hooks check what they are given.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from nasaq.cpu import loader as loader_module
from nasaq.cpu.codegen import compiler
from nasaq.scenarios.report import scenario_files
from nasaq.scenarios.runner import run_scenario

ROOT = Path(__file__).resolve().parents[3]
SCENARIOS = scenario_files([ROOT / "tests" / "scenarios"])


@pytest.fixture
def instrumented(monkeypatch: pytest.MonkeyPatch) -> dict[str, int]:
    seen = {"before": 0, "after": 0}

    def compile_instrumented(*args: Any, **kwargs: Any) -> compiler.Compiled:
        kwargs["instrumented"] = True
        compiled = compiler.compile_block(*args, **kwargs)
        size = len(compiled.block.code)

        def before(index: int, frame: bytearray, params: list[Any], *regs: Any) -> None:
            assert 0 <= index < size
            assert len(regs) == len(compiler.HOOK_REGISTERS)
            seen["before"] += 1

        def after(index: int, frame: bytearray, params: list[Any], *regs: Any) -> None:
            assert 0 <= index < size
            assert regs[3] in (0, 1)  # RLO is a bit
            seen["after"] += 1

        compiled.namespace["_B"], compiled.namespace["_H"] = before, after
        return compiled

    monkeypatch.setattr(loader_module, "compile_block", compile_instrumented)
    return seen


def test_there_are_scenarios_to_run() -> None:
    assert len(SCENARIOS) > 150


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda p: str(p.relative_to(ROOT / "tests")))
def test_scenario_passes_instrumented(path: Path, instrumented: dict[str, int]) -> None:
    result = run_scenario(path)
    assert result.passed, result.error or "\n".join(str(f) for f in result.failures)


def test_the_hooks_run(instrumented: dict[str, int]) -> None:
    path = ROOT / "tests" / "scenarios" / "course" / "ar_000" / "e01_and_gate.yaml"
    assert run_scenario(path).passed
    assert instrumented["before"] > 0
    assert instrumented["after"] == instrumented["before"]
