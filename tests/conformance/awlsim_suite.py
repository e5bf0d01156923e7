"""Conformance against an outside suite: awlsim's self-checking STL test programs.

awlsim (a Python S7 simulator) ships STL programs that check themselves with pseudo-instructions
(``__ASSERT==`` ...) and end with ``CALL SFC 46``. This script downloads the awlsim 0.77.1 source
distribution from PyPI into a temporary folder (nothing of it is kept or committed), picks the
plain-STL programs, runs each through ``nasaq run --test-ops`` and prints ``K/N passed``.

Run it with ``make conformance``; it is not part of ``make test`` because it needs the network.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import tarfile
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

VERSION = "0.77.1"
ROOT = Path(__file__).resolve().parents[2]
NASAQ = ROOT / ".venv" / "bin" / "nasaq"
PIP = ROOT / ".venv" / "bin" / "pip"

# Folders of plain STL programs; the rest test awlsim itself (GUI, core server, FUP, hardware).
FOLDERS = (
    "tc000_base",
    "tc100_instructions",
    "tc150_startup",
    "tc200_datatypes",
    "tc300_cpu",
    "tc400_convenience",
    "tc900_bugs",
)
# System blocks other than SFC 46 (STP) and the IEC counters and timers SFB 0-5 (which the CPU
# has, nasaq.cpu.iec_blocks) are outside plain STL. tc100_instructions/insn_CALL_multiinstance
# calls SFB 0 as a multi-instance and checks the DB register inside the called FB: the CPU
# follows STEP 7 there (cpu/COMPATIBILITY.md, "Multi-instance calls"), as awlsim does.
SYSTEM_BLOCK = re.compile(r"\b(?:SFC\s*(?!46\b)\d+|SFB\s*(?![0-5]\b)-?\d+)", re.IGNORECASE)


@dataclass
class Outcome:
    name: str
    ok: bool
    detail: str
    seconds: float


def download(folder: Path) -> Path:
    command = [str(PIP), "download", "--quiet", "--no-deps", "--no-binary", ":all:"]
    subprocess.run([*command, "--dest", str(folder), f"awlsim=={VERSION}"], check=True)
    archive = next(folder.glob(f"awlsim-{VERSION}.tar.gz"))
    with tarfile.open(archive) as tar:
        tar.extractall(folder, filter="data")
    return folder / f"awlsim-{VERSION}" / "tests"


def expected_exit(program: Path) -> int:
    """awlsim's per-test .conf may expect a non-zero exit; such tests check awlsim's own errors."""
    conf = program.with_name(program.name + ".conf")
    if not conf.is_file():
        return 0
    match = re.search(r"^exit_code\s*=\s*(\d+)", conf.read_text(errors="replace"), re.MULTILINE)
    return int(match[1]) if match else 0


def select(tests: Path) -> tuple[list[Path], list[tuple[Path, str]]]:
    chosen: list[Path] = []
    skipped: list[tuple[Path, str]] = []
    for folder in FOLDERS:
        for program in sorted((tests / folder).glob("*.awl")):
            text = program.read_text(encoding="latin-1")
            if SYSTEM_BLOCK.search(text):
                skipped.append((program, "uses system blocks"))
            elif expected_exit(program) != 0:
                skipped.append((program, "checks an awlsim error exit code"))
            else:
                chosen.append(program)
    return chosen, skipped


def symbol_tables(program: Path) -> list[str]:
    """The program's symbol table: a same-named .asc beside it, or the one a same-named awlsim
    project (.awlpro) embeds, written next to it as .asc (all inside the temporary folder)."""
    table = program.with_suffix(".asc")
    if table.is_file():
        return [str(table)]
    project = program.with_suffix(".awlpro")
    if not project.is_file():
        return []
    found = re.search(
        r"<symbols>(?:(?!</symbols>).)*?<source[^>]*type=\"3\"[^>]*><!\[CDATA\[(.*?)\]\]>",
        project.read_text(encoding="utf-8", errors="replace"),
        re.DOTALL,
    )
    if found is None or not found[1].strip():
        return []
    table.write_text(found[1].lstrip("\r\n"), encoding="latin-1", errors="replace")
    return [str(table)]


def cpu_options(program: Path) -> list[str]:
    """The CPU a same-named awlsim project asks for: its clock memory byte (``--clock-memory``),
    and ``nr_accus="4"`` is an S7-400. awlsim starts such a CPU with a cold restart when OB 102
    is loaded (a real S7-400 does so when its startup parameter says cold restart), so that is
    passed on too."""
    project = program.with_suffix(".awlpro")
    if not project.is_file():
        return []
    config = project.read_text(errors="replace")
    options: list[str] = []
    # The clock memory byte of the CPU configuration (-1: none), as in STEP 7's CPU properties.
    clock = re.search(r'clock_memory_byte\s*=\s*"?(-?\d+)', config)
    if clock is not None and int(clock[1]) >= 0:
        options += ["--clock-memory", clock[1]]
    found = re.search(r'nr_accus\s*=\s*"?(\d+)', config)
    if found is None or found[1] != "4":
        return options
    options += ["--profile", "S7-400"]
    text = program.read_text(encoding="latin-1")
    if re.search(r"^\s*ORGANIZATION_BLOCK\s+OB\s*102\b", text, re.IGNORECASE | re.MULTILINE):
        options += ["--restart", "cold"]
    return options


def run(program: Path, tests: Path) -> Outcome:
    name = str(program.relative_to(tests))
    # A symbol table that belongs to the program (awlsim projects pair them) is part of it.
    symbols = symbol_tables(program)
    started = time.monotonic()
    try:
        result = subprocess.run(
            [
                *(str(NASAQ), "run", "--test-ops", "--cycles", "1000"),
                *cpu_options(program),
                *(str(program), *symbols),
            ],
            capture_output=True,
            text=True,
            timeout=60,
        )
    except subprocess.TimeoutExpired:
        return Outcome(name, False, "timed out after 60 s", time.monotonic() - started)
    seconds = time.monotonic() - started
    try:
        state = json.loads(result.stdout)
    except json.JSONDecodeError:  # exit 1 without JSON: the program does not compile
        first = (result.stderr.strip().splitlines() or ["does not compile"])[0]
        verdict = f"compile: {first}" if result.returncode == 1 else f"exit {result.returncode}"
        return Outcome(name, False, verdict, seconds)
    if result.returncode != 0:
        return Outcome(name, False, f"STOP: {state.get('stop_reason')}", seconds)
    return Outcome(name, True, f"{state['cycles']} scan(s)", seconds)


def main() -> int:
    if not NASAQ.exists():
        print("run `make install` first", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory(prefix="nasaq-awlsim-") as folder:
        tests = download(Path(folder))
        chosen, skipped = select(tests)
        outcomes = [run(program, tests) for program in chosen]
    for outcome in outcomes:
        verdict = "PASS" if outcome.ok else "FAIL"
        print(f"{verdict}  {outcome.name:<45} {outcome.detail}  ({outcome.seconds:.1f} s)")
    for program, reason in skipped:
        print(f"skip  {program.relative_to(tests)!s:<45} {reason}")
    passed = sum(outcome.ok for outcome in outcomes)
    print(f"awlsim {VERSION} conformance: {passed}/{len(outcomes)} passed")
    return 0 if passed == len(outcomes) else 1


if __name__ == "__main__":
    raise SystemExit(main())
