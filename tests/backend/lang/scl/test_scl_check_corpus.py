"""The diagnostics corpus of the SCL checker: the snapshot programs of the check tests, taken
together. Issue 4 asks for at least 60 erroneous programs, each with its expected code(s) and
span(s); every code the type checker reports has at least one of them."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path
from types import ModuleType

HERE = Path(__file__).parent
MODULES = (
    "test_scl_typecheck",
    "test_scl_call_checks",
    "test_scl_flow_checks",
    "test_scl_declaration_checks",
)
# The codes of the type checker (the binder's are tested in test_scl_bind.py).
CHECKER_CODES = {"SCL201", "SCL206"} | {f"SCL{number}" for number in range(211, 253)}

Expected = list[tuple[str, int, int]]


def _load(name: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(f"_corpus_{name}", HERE / f"{name}.py")
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _programs() -> list[tuple[str, Expected]]:
    found: list[tuple[str, Expected]] = []
    for name in MODULES:
        found.extend(_load(name).PROGRAMS)
    return found


def test_at_least_60_erroneous_programs_with_codes_and_spans() -> None:
    erroneous: dict[str, Expected] = {}
    for text, expected in _programs():
        if expected:
            assert erroneous.setdefault(text, expected) == expected, text
    assert len(erroneous) >= 60, len(erroneous)
    for text, expected in erroneous.items():
        for code, line, column in expected:
            assert re.fullmatch(r"SCL\d{3}", code), text
            assert 1 <= line <= text.count("\n") + 1, text
            assert column >= 1, text


def test_every_checker_code_has_an_erroneous_program() -> None:
    covered = {code for _text, expected in _programs() for code, _line, _column in expected}
    assert not CHECKER_CODES - covered, sorted(CHECKER_CODES - covered)
