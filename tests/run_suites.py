"""Runs every test suite of Nasaq and prints one summary line per suite.

Called by ``make test`` (and so by CI). A suite fails when its command fails, when it ran no test,
or when it skipped a test: a skipped test is a hole nobody sees. Test counts come from the JUnit
XML reports the runners write into ``.reports/``.

Two lanes keep a 2-core machine's cores busy: pytest (one process, one core) runs beside ruff,
mypy, tsc, vitest (one worker on 2 cores) and then pytest's ``tests/backend/lang`` folder
(``pytest-lang``); the two lanes take about as long. Playwright runs alone once both are done:
its flows wait on a real server and browser, which must not be starved. A suite run beside the
others writes its output to ``.reports/<suite>.log``, shown when it ends.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from concurrent.futures import Future, ThreadPoolExecutor
from contextlib import nullcontext
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
    beside: bool = False  # starts at once and runs beside the other suites, output to a log
    alone: bool = False  # waits until every suite run beside the others is done
    group: str = ""  # also run when this name is asked for (``run_suites.py pytest``)


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


# The pytest folder run in the second lane, after vitest, so that both lanes take about as long
# (lint, types and vitest about 4 minutes on the 2-core machine; pytest 5 to 6 without it).
PYTEST_SECOND_LANE = "../tests/backend/lang"


def suites() -> list[Suite]:
    ruff = str(VENV_BIN / "ruff")
    pytest = [str(VENV_BIN / "pytest"), "-q"]
    python_paths = ["backend", "tests/backend", "tests/bench", "tests/conformance", "tests/corpus"]
    python_paths.append("tests/fuzz")
    python_paths.append("tests/run_suites.py")
    ruff_config = ["--config", "backend/pyproject.toml"]
    npm = shutil.which("npm") or "npm"
    return [
        Suite(
            "pytest",
            [[*pytest, f"--junitxml={REPORTS / 'pytest.xml'}", f"--ignore={PYTEST_SECOND_LANE}"]],
            junit=REPORTS / "pytest.xml",
            cwd=ROOT / "backend",
            beside=True,
        ),
        Suite(
            "ruff",
            [
                [ruff, "check", *ruff_config, *python_paths],
                [ruff, "format", "--check", *ruff_config, *python_paths],
            ],
        ),
        Suite("mypy", [[str(VENV_BIN / "mypy")]], cwd=ROOT / "backend"),
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
            "pytest-lang",
            [[*pytest, f"--junitxml={REPORTS / 'pytest-lang.xml'}", PYTEST_SECOND_LANE]],
            junit=REPORTS / "pytest-lang.xml",
            cwd=ROOT / "backend",
            group="pytest",
        ),
        # The compilers' own fuzzer, bounded (tests/fuzz/driver.py): 21,000 cases, one worker,
        # about three minutes at the end of the second lane: a third process beside the two lanes
        # starves the live-server tests of the first.
        Suite(
            "fuzz",
            [
                [
                    str(VENV_BIN / "python"),
                    "tests/fuzz/driver.py",
                    "--cases=21000",
                    "--jobs=1",
                    f"--junit={REPORTS / 'fuzz.xml'}",
                    f"--out={REPORTS / 'fuzz-failures'}",
                ]
            ],
            junit=REPORTS / "fuzz.xml",
        ),
        Suite(
            "playwright",
            [[npm, "exec", "--", "playwright", "test", "-c", "tests/e2e/playwright.config.ts"]],
            junit=REPORTS / "e2e.xml",
            env={"PLAYWRIGHT_JUNIT_OUTPUT_FILE": str(REPORTS / "e2e.xml")},
            alone=True,
        ),
    ]


def run(suite: Suite, log: Path | None = None) -> Outcome:
    """Runs ``suite``, its output on the console, or in ``log`` when it runs beside others."""
    if suite.junit is not None:
        suite.junit.unlink(missing_ok=True)
    started = time.monotonic()
    code = 0
    with open(log, "w", encoding="utf-8") if log is not None else nullcontext() as out:
        for command in suite.commands:
            print(f"\n==> {suite.name}: {' '.join(command)}", file=out or sys.stdout, flush=True)
            env = {**os.environ, **suite.env}
            code = subprocess.call(command, cwd=suite.cwd, env=env, stdout=out, stderr=out)
            if code != 0:
                break
    outcome = Outcome(suite, code, time.monotonic() - started)
    if suite.junit is not None:
        outcome.tests, outcome.failures, outcome.skipped = read_junit(suite.junit)
    return outcome


def _finish(running: dict[str, Future[Outcome]], outcomes: dict[str, Outcome]) -> None:
    """Waits for the suites run beside the others and shows their output."""
    for name, future in running.items():
        outcomes[name] = future.result()
        log = REPORTS / f"{name}.log"
        print(f"\n==> {name} (ran beside the others; its output, also in {log}):", flush=True)
        print(log.read_text(encoding="utf-8", errors="replace").strip(), flush=True)
    running.clear()


def main(selected: list[str]) -> int:
    REPORTS.mkdir(exist_ok=True)
    chosen = [s for s in suites() if not selected or {s.name, s.group} & set(selected)]
    unknown = set(selected) - {name for s in suites() for name in (s.name, s.group)}
    if unknown:
        print(f"unknown suite(s): {', '.join(sorted(unknown))}", file=sys.stderr)
        return 2
    outcomes: dict[str, Outcome] = {}
    running: dict[str, Future[Outcome]] = {}
    with ThreadPoolExecutor() as pool:
        for suite in chosen:
            if suite.beside:
                log = REPORTS / f"{suite.name}.log"
                print(f"\n==> {suite.name}: started beside the others, output in {log}", flush=True)
                running[suite.name] = pool.submit(run, suite, log)
        for suite in chosen:
            if suite.beside:
                continue
            if suite.alone:
                _finish(running, outcomes)
            outcomes[suite.name] = run(suite)
        _finish(running, outcomes)
    print("\nSummary")
    ordered = [outcomes[s.name] for s in chosen]
    for outcome in ordered:
        print(outcome.line())
    counted = [o for o in ordered if o.suite.junit is not None]
    passed = sum(o.passed for o in counted)
    failed = sum(o.failures for o in counted)
    skipped = sum(o.skipped for o in counted)
    print(f"tests: {passed} passed, {failed} failed, {skipped} skipped")
    return 0 if all(o.ok for o in ordered) else 1


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
