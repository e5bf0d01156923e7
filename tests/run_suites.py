"""Runs every test suite of Nasaq and prints one summary line per suite.

Called by ``make test`` (and so by CI). A suite fails when its command fails, when it ran no test,
or when it skipped a test: a skipped test is a hole nobody sees. Test counts come from the JUnit
XML reports the runners write into ``.reports/``.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
REPORTS = ROOT / ".reports"
VENV_BIN = ROOT / ".venv" / "bin"


@dataclass
class Suite:
    name: str
    commands: list[list[str]]  # run in order; the suite stops at the first that fails
    junit: Path | None = None  # suites without a report are checks (lint, types), not tests
    cwd: Path = ROOT
    env: dict[str, str] = field(default_factory=dict)


@dataclass
class Outcome:
    suite: Suite
    code: int
    seconds: float
    tests: int = 0
    failures: int = 0
    skipped: int = 0

    @property
    def passed(self) -> int:
        return self.tests - self.failures - self.skipped

    @property
    def ok(self) -> bool:
        if self.code != 0:
            return False
        if self.suite.junit is None:
            return True
        return self.tests > 0 and self.failures == 0 and self.skipped == 0

    def line(self) -> str:
        verdict = "PASS" if self.ok else "FAIL"
        if self.suite.junit is None:
            detail = "clean" if self.code == 0 else f"exit code {self.code}"
        else:
            detail = f"{self.passed} passed, {self.failures} failed, {self.skipped} skipped"
            if self.tests == 0:
                detail += " (no test ran)"
            elif self.code != 0 and self.failures == 0:
                detail += f" (exit code {self.code})"
        return f"{verdict}  {self.suite.name:<11} {detail:<46} {self.seconds:6.1f} s"


def read_junit(report: Path) -> tuple[int, int, int]:
    """(tests, failures incl. errors, skipped), summed over all test cases of the report."""
    if not report.is_file():
        return 0, 0, 0
    tests = failures = skipped = 0
    for case in ET.parse(report).getroot().iter("testcase"):
        tests += 1
        if case.find("failure") is not None or case.find("error") is not None:
            failures += 1
        elif case.find("skipped") is not None:
            skipped += 1
    return tests, failures, skipped


def suites() -> list[Suite]:
    ruff = str(VENV_BIN / "ruff")
    python_paths = ["backend", "tests/backend", "tests/bench", "tests/conformance", "tests/corpus"]
    python_paths.append("tests/run_suites.py")
    ruff_config = ["--config", "backend/pyproject.toml"]
    npm = shutil.which("npm") or "npm"
    return [
        Suite(
            "ruff",
            [
                [ruff, "check", *ruff_config, *python_paths],
                [ruff, "format", "--check", *ruff_config, *python_paths],
            ],
        ),
        Suite("mypy", [[str(VENV_BIN / "mypy")]], cwd=ROOT / "backend"),
        Suite(
            "pytest",
            [[str(VENV_BIN / "pytest"), "-q", f"--junitxml={REPORTS / 'pytest.xml'}"]],
            junit=REPORTS / "pytest.xml",
            cwd=ROOT / "backend",
        ),
        Suite("tsc", [[npm, "run", "--silent", "typecheck", "-w", "frontend"]]),
        Suite(
            "vitest",
            [
                [
                    npm,
                    "run",
                    "--silent",
                    "test",
                    "-w",
                    "frontend",
                    "--",
                    "--reporter=default",
                    "--reporter=junit",
                    f"--outputFile.junit={REPORTS / 'vitest.xml'}",
                ]
            ],
            junit=REPORTS / "vitest.xml",
        ),
        Suite(
            "playwright",
            [[npm, "exec", "--", "playwright", "test", "-c", "tests/e2e/playwright.config.ts"]],
            junit=REPORTS / "e2e.xml",
            env={"PLAYWRIGHT_JUNIT_OUTPUT_FILE": str(REPORTS / "e2e.xml")},
        ),
    ]


def run(suite: Suite) -> Outcome:
    if suite.junit is not None:
        suite.junit.unlink(missing_ok=True)
    started = time.monotonic()
    code = 0
    for command in suite.commands:
        print(f"\n==> {suite.name}: {' '.join(command)}", flush=True)
        code = subprocess.call(command, cwd=suite.cwd, env={**os.environ, **suite.env})
        if code != 0:
            break
    outcome = Outcome(suite, code, time.monotonic() - started)
    if suite.junit is not None:
        outcome.tests, outcome.failures, outcome.skipped = read_junit(suite.junit)
    return outcome


def main(selected: list[str]) -> int:
    REPORTS.mkdir(exist_ok=True)
    chosen = [s for s in suites() if not selected or s.name in selected]
    unknown = set(selected) - {s.name for s in suites()}
    if unknown:
        print(f"unknown suite(s): {', '.join(sorted(unknown))}", file=sys.stderr)
        return 2
    outcomes = [run(suite) for suite in chosen]
    print("\nSummary")
    for outcome in outcomes:
        print(outcome.line())
    counted = [o for o in outcomes if o.suite.junit is not None]
    passed = sum(o.passed for o in counted)
    failed = sum(o.failures for o in counted)
    skipped = sum(o.skipped for o in counted)
    print(f"tests: {passed} passed, {failed} failed, {skipped} skipped")
    return 0 if all(o.ok for o in outcomes) else 1


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
