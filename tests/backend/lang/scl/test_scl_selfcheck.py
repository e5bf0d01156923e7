"""The self-checking SCL programs of ``tests/selfcheck`` (its README says how they are written)
compiled with a generated OB1 that calls every ``Check_`` function, run on the CPU, and every
check TRUE."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.stl import SourceFile, compile_sources

FOLDER = Path(__file__).resolve().parents[4] / "tests" / "selfcheck"
PROGRAMS = sorted(FOLDER.rglob("*.scl"))
_CHECK = re.compile(r'^\s*FUNCTION\s+"?(Check_\w+)"?\s*:\s*BOOL', re.IGNORECASE | re.MULTILINE)
_HEADER = re.compile(r"^//\s*(profile|dialect|scans)\s*:\s*(\S+)", re.IGNORECASE | re.MULTILINE)
FIRST_RESULT = 100  # M100.0 holds the first check's result; M99.0 says OB1 ran to its end


def header(text: str) -> dict[str, str]:
    return {key.lower(): value for key, value in _HEADER.findall(text)}


def main_ob(checks: list[str]) -> str:
    lines = [f'M{FIRST_RESULT + i // 8}.{i % 8} := "{name}"();' for i, name in enumerate(checks)]
    return (
        "ORGANIZATION_BLOCK OB1\nBEGIN\nM99.0 := FALSE;\n"
        + "\n".join(lines)
        + ("\nM99.0 := TRUE;\nEND_ORGANIZATION_BLOCK\n")
    )


def test_there_are_self_checking_programs() -> None:
    assert PROGRAMS, f"no program in {FOLDER}"


@pytest.mark.parametrize("path", PROGRAMS, ids=lambda p: str(p.relative_to(FOLDER)))
def test_every_check_holds(path: Path) -> None:
    text = path.read_text(encoding="utf-8-sig")
    options = header(text)
    checks = _CHECK.findall(text)
    assert checks, "a self-checking program declares Check_ functions"
    profile = options.get("profile", "S7-300")
    result = compile_sources(
        [SourceFile(path.name, text), SourceFile("selfcheck_main.scl", main_ob(checks))],
        profile=profile,
    )
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile(profile), cycle_ms=10)
    cpu.start()
    assert cpu.mode == "RUN", cpu.stop_reason
    cpu.run(int(options.get("scans", "1")))
    assert cpu.mode == "RUN", cpu.stop_reason

    def bit(text: str) -> int:
        address = parse_address(text)
        assert isinstance(address, Direct)
        return cpu.read(address)

    assert bit("M99.0") == 1, "OB1 did not reach its end"
    failed = [
        name for i, name in enumerate(checks) if bit(f"M{FIRST_RESULT + i // 8}.{i % 8}") != 1
    ]
    assert not failed, f"checks that returned FALSE: {failed}"
