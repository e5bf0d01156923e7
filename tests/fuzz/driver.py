"""Nasaq's own fuzzer for the STL, SCL and LAD/FBD compilers (``make fuzz``; bounded in
``make test``).

    python tests/fuzz/driver.py --cases 21000                 # the bounded run of make test
    python tests/fuzz/driver.py --cases 300000 --seconds 3600 # make fuzz
    python tests/fuzz/driver.py --replay .fuzz/failures/1-RecursionError-scl.scl

Cases (``cases.make_case``) are deterministic: case ``i`` of seed ``s`` is the same text on every
machine with the same tree. Each runs in a worker subprocess (``worker.py``) through everything
a user's source goes through (``pipeline.run_pipeline``); one worker per core, each reused from
case to case and started again after a failure. A case fails on any exception that escapes, on
a run over ``--timeout`` seconds (5) and on memory over ``--memory`` MB (1024; the worker's
address space is capped, so the case meets ``MemoryError``). Failures are told apart by the
exception's type and the innermost frame in the ``nasaq`` package; each distinct one is printed
once with how often it happened, and its first case is shrunk (lines, then tokens, then
characters, as long as the same failure stays) and written to ``--out`` with its traceback.
The exit code is 1 when anything failed. ``--junit`` writes one test case per language and
thousand cases, so ``tests/run_suites.py`` counts them.
"""

from __future__ import annotations

import argparse
import json
import os
import queue
import subprocess
import sys
import threading
import time
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from cases import LANGUAGES, SUFFIX, Case, make_case  # noqa: E402
from mutate import tokens  # noqa: E402

ROOT = HERE.parents[1]
CHUNK = 1000  # cases per JUnit test case


@dataclass
class Outcome:
    ok: bool
    type: str = ""
    frame: str = ""
    message: str = ""
    trace: str = ""
    seconds: float = 0.0

    @property
    def signature(self) -> tuple[str, str]:
        return self.type, self.frame


class Worker:
    """One worker subprocess and the thread that reads its answers."""

    def __init__(self, memory_mb: int) -> None:
        self.memory = memory_mb * 1024 * 1024
        self.process: subprocess.Popen[str] | None = None
        self.answers: queue.Queue[str | None] = queue.Queue()

    def start(self) -> None:
        env = {**os.environ, "PYTHONHASHSEED": "0", "PYTHONIOENCODING": "utf-8"}
        self.process = subprocess.Popen(
            [sys.executable, str(HERE / "worker.py"), str(self.memory)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
            encoding="utf-8",
            env=env,
        )
        self.answers = queue.Queue()
        out = self.process.stdout
        answers = self.answers

        def read() -> None:
            assert out is not None
            for line in out:
                answers.put(line)
            answers.put(None)

        threading.Thread(target=read, daemon=True).start()
        ready = self.answers.get(timeout=120)
        if ready is None:
            raise RuntimeError("the fuzz worker did not start (run it alone to see why)")

    def stop(self) -> None:
        if self.process is not None:
            self.process.kill()
            self.process.wait()
            self.process = None

    def run(self, case: Case, timeout: float) -> Outcome:
        if self.process is None:
            self.start()
        assert self.process is not None
        assert self.process.stdin is not None
        request = {
            "name": case.name,
            "language": case.language,
            "text": case.text,
            "profile": case.profile,
            "conversions": case.conversions,
        }
        started = time.monotonic()
        try:
            self.process.stdin.write(json.dumps(request) + "\n")
            self.process.stdin.flush()
            line = self.answers.get(timeout=timeout)
        except queue.Empty:
            self.stop()
            return Outcome(False, "Timeout", f"over {timeout:g} s", seconds=timeout)
        except (BrokenPipeError, OSError):
            line = None
        seconds = time.monotonic() - started
        if line is None:
            code = self.process.wait() if self.process else None
            self.process = None
            return Outcome(False, "WorkerDied", f"exit code {code}", seconds=seconds)
        answer = json.loads(line)
        if answer["ok"]:
            return Outcome(True, seconds=seconds)
        self.stop()  # a fresh process for the next case: nothing half-done carries over
        return Outcome(
            False,
            answer["type"],
            answer["frame"],
            answer.get("message", ""),
            answer.get("trace", ""),
            seconds,
        )


@dataclass
class Failure:
    outcome: Outcome
    case: Case
    count: int = 0
    languages: set[str] = field(default_factory=set)


@dataclass
class Run:
    cases: int = 0
    slowest: tuple[float, int] = (0.0, -1)
    failures: dict[tuple[str, str], Failure] = field(default_factory=dict)
    failed_chunks: dict[tuple[str, int], str] = field(default_factory=dict)
    lock: threading.Lock = field(default_factory=threading.Lock)

    def record(self, case: Case, outcome: Outcome) -> None:
        with self.lock:
            self.cases += 1
            if outcome.seconds > self.slowest[0]:
                self.slowest = (outcome.seconds, case.index)
            if outcome.ok:
                return
            key = outcome.signature
            failure = self.failures.get(key)
            if failure is None:
                failure = self.failures[key] = Failure(outcome, case)
                print(
                    f"  new failure: {outcome.type} at {outcome.frame} (case {case.index}, "
                    f"{case.language}, {case.kind})",
                    flush=True,
                )
            failure.count += 1
            failure.languages.add(case.language)
            chunk = (case.language, case.index // CHUNK)
            self.failed_chunks.setdefault(chunk, f"{outcome.type} at {outcome.frame}")


def fuzz(
    seed: int, count: int, seconds: float, jobs: int, timeout: float, memory: int, big: bool
) -> Run:
    run = Run()
    counter = iter(range(count))
    counter_lock = threading.Lock()
    deadline = time.monotonic() + seconds if seconds > 0 else None

    def next_index() -> int | None:
        with counter_lock:
            if deadline is not None and time.monotonic() > deadline:
                return None
            return next(counter, None)

    def lane() -> None:
        worker = Worker(memory)
        try:
            while (index := next_index()) is not None:
                case = make_case(seed, index, big)
                try:
                    outcome = worker.run(case, timeout)
                except RuntimeError as error:  # the worker did not even start
                    worker.stop()
                    outcome = Outcome(False, "WorkerDidNotStart", str(error))
                run.record(case, outcome)
        finally:
            worker.stop()

    threads = [threading.Thread(target=lane) for _ in range(jobs)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return run


def shrink(case: Case, outcome: Outcome, worker: Worker, timeout: float, budget: float) -> str:
    """The smallest text found (lines, then tokens, then characters) that fails the same way."""
    deadline = time.monotonic() + budget

    def fails(text: str) -> bool:
        if time.monotonic() > deadline:
            return False
        probe = Case(
            case.seed, case.index, case.language, case.kind, case.profile, text, case.conversions
        )
        try:
            return worker.run(probe, timeout).signature == outcome.signature
        except RuntimeError:  # the worker did not start: keep what was found so far
            return False

    def ddmin(parts: list[str], join: Callable[[list[str]], str]) -> list[str]:
        size = max(1, len(parts) // 2)
        while size >= 1 and time.monotonic() < deadline:
            start = 0
            removed = False
            while start < len(parts):
                trial = parts[:start] + parts[start + size :]
                if trial and fails(join(trial)):
                    parts = trial
                    removed = True
                else:
                    start += size
            if not removed:
                size //= 2
        return parts

    text = case.text
    lines = ddmin(text.splitlines(keepends=True), "".join)
    text = "".join(lines)
    text = "".join(ddmin(tokens(text), "".join))
    if len(text) < 2000:
        text = "".join(ddmin(list(text), "".join))
    return text


def report(run: Run, args: argparse.Namespace, elapsed: float) -> None:
    print(
        f"{run.cases} cases ({', '.join(LANGUAGES)}) in {elapsed:.1f} s with {args.jobs} "
        f"worker(s); slowest case {run.slowest[0]:.2f} s (#{run.slowest[1]}); "
        f"{len(run.failures)} distinct failure(s)"
    )
    if not run.failures:
        return
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    worker = Worker(args.memory)
    try:
        for n, (key, failure) in enumerate(sorted(run.failures.items()), start=1):
            case = failure.case
            text = case.text
            if args.shrink_seconds > 0:
                text = shrink(case, failure.outcome, worker, args.timeout, args.shrink_seconds)
            stem = f"{n}-{failure.outcome.type}-{case.language}"
            path = out / f"{stem}{SUFFIX[case.language]}"
            path.write_text(text, encoding="utf-8", errors="surrogatepass", newline="")
            (out / f"{stem}.txt").write_text(
                f"{key[0]} at {key[1]}\ncase {case.index} of seed {case.seed} ({case.kind}), "
                f"profile {case.profile}, {failure.count} case(s), "
                f"languages {sorted(failure.languages)}\n{failure.outcome.message}\n\n"
                f"{failure.outcome.trace}",
                encoding="utf-8",
                errors="replace",
            )
            shown = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
            print(
                f"FAIL {key[0]} at {key[1]}: {failure.count} case(s) "
                f"{sorted(failure.languages)}; reproducer {shown} ({len(text)} chars)"
            )
    finally:
        worker.stop()


def write_junit(run: Run, args: argparse.Namespace, elapsed: float) -> None:
    suite = ET.Element("testsuite", name="fuzz", time=f"{elapsed:.1f}")
    chunks = (run.cases + CHUNK - 1) // CHUNK
    for language in LANGUAGES:
        for chunk in range(chunks):
            name = f"{language} cases {chunk * CHUNK}-{(chunk + 1) * CHUNK - 1}"
            element = ET.SubElement(suite, "testcase", classname="fuzz", name=name)
            found = run.failed_chunks.get((language, chunk))
            if found is not None:
                ET.SubElement(element, "failure", message=found)
    suite.set("tests", str(len(suite)))
    suite.set("failures", str(len(run.failed_chunks)))
    Path(args.junit).parent.mkdir(parents=True, exist_ok=True)
    ET.ElementTree(suite).write(args.junit, encoding="utf-8", xml_declaration=True)


def replay(path: Path, profile: str) -> int:
    """Runs one file through the pipeline in this process, so its traceback shows."""
    from pipeline import run_pipeline

    language = {".awl": "stl", ".stl": "stl", ".scl": "scl"}.get(path.suffix.lower(), "lad")
    text = path.read_text(encoding="utf-8", errors="surrogateescape")
    started = time.monotonic()
    run_pipeline(path.name, language, text, profile)
    print(f"{path}: no exception, {time.monotonic() - started:.2f} s")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", type=int, default=21000)
    parser.add_argument("--seconds", type=float, default=0, help="stop after this long (0: no)")
    parser.add_argument("--seed", type=int, default=20)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--timeout", type=float, default=5.0)
    parser.add_argument("--memory", type=int, default=1024, help="MB per worker")
    parser.add_argument("--out", default=str(ROOT / ".fuzz" / "failures"))
    parser.add_argument("--shrink-seconds", type=float, default=60.0)
    parser.add_argument("--junit", default="")
    parser.add_argument("--replay", type=Path)
    parser.add_argument("--profile", default="S7-300")
    parser.add_argument("--big", action="store_true", help="larger pathological inputs")
    args = parser.parse_args(argv)
    if args.replay is not None:
        return replay(args.replay, args.profile)
    started = time.monotonic()
    run = fuzz(args.seed, args.cases, args.seconds, args.jobs, args.timeout, args.memory, args.big)
    elapsed = time.monotonic() - started
    report(run, args, elapsed)
    if args.junit:
        write_junit(run, args, elapsed)
    return 1 if run.failures else 0


if __name__ == "__main__":
    raise SystemExit(main())
