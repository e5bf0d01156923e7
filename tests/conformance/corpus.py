"""Measures how much of a corpus of real STEP 7 Classic / TIA Portal sources Nasaq compiles.

Technicians open the sources they already have; the only honest measure of "Nasaq accepts what
STEP 7 accepts" is to compile many of them. The corpus is other people's code, so it is never
committed: ``corpus_gather.py`` copies it from the public repositories in ``corpus_repos.txt``
into a folder with one subfolder per repository, and ``NASAQ_CORPUS`` names that folder.

Every source file is compiled alone (with its repository's symbol tables) under the S7-300
profile. A file refused only because it needs the S7-1200/1500 profile (SCL500/STL500) is
compiled again under S7-1500 and counts as accepted if that passes. A file whose only errors are
references to blocks, UDTs or symbols outside the file ("needs blocks from elsewhere") is the
corpus's fault, not Nasaq's; each repository is also compiled as a whole, where those are found.

Each compilation runs in a worker process with a time limit (``--timeout``, 5 s of CPU time;
a worker busy six times as long in wall time is killed) and a 1 GB address-space limit, so a
hang, a crash or a memory blow-up is counted, not fatal. Uncaught exceptions are counted with
their type and the place in Nasaq's code that raised them.

Kinds (a file is one of them; decided by extension, then content):
- ``.db/.udt``: TIA Portal's data block and PLC data type sources, by extension.
- ``STL``: ``.awl``/``.stl`` (Classic and TIA exports alike).
- ``TIA SCL``: ``.scl`` with any TIA marker: ``S7_Optimized_Access``, ``REGION``, ``#local``
  operands, ``VERSION : 0.1`` without quotes, TIA's type spellings (``: Bool;``, ``: Int;``), or
  a type STEP 7 Classic does not have (``: USINT``, ``: LREAL``, ``: WSTRING``, ``: DTL`` ...).
- ``Classic SCL``: any other ``.scl``.

The histogram groups refused files by their first refusing error (an error that is not a
reference to something outside the file): its code and its message with names replaced by
``<name>``, so one construct is one bar. A second histogram counts every refusing construct
of the refused files, not only the first: the work the first errors hide.

    NASAQ_CORPUS=~/nasaq-corpus .venv/bin/python tests/conformance/corpus.py [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import os
import queue
import re
import select
import subprocess
import sys
import threading
import time
import traceback
from collections import Counter
from collections.abc import Iterable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

SOURCE_SUFFIXES = (".scl", ".awl", ".stl", ".db", ".udt")
SYMBOL_SUFFIXES = (".sdf", ".asc", ".seq")
MEMORY_LIMIT = 1 << 30
NEEDS_1500 = frozenset({"SCL500", "STL500"})
# Errors that name something the file refers to but does not define, and the parameter that
# holds the name.
REFERENCE_CODES = {
    "SCL201": "name",
    "SCL202": "type",
    "SCL231": "block",
    "SCL923": "block",  # a DB the symbol table names but no source of the repository declares
    "STL205": "name",
    "STL213": "block",
    "STL224": "type",
}
# Message parameters that are the user's names: replaced in the histogram so one construct is
# one bar. The others (found, type, what, mnemonic ...) say what the construct is.
NAME_PARAMS = frozenset(
    {
        "name",
        "block",
        "file",
        "db",
        "label",
        "other",
        "param",
        "member",
        "line",
        "owner",
    }
)
# Errors about a value that is outside the file when it is a quoted name: a global constant
# of the PLC tag table as an array bound or an initial value ("Max_Count").
QUOTED_CODES = frozenset({"SCL209", "SCL243"})
# Parameters holding a constant as written: its digits become N (L#100 and L#2000 are one bar).
NUMBER_PARAMS = frozenset({"text", "value"})
ABSOLUTE_BLOCK = re.compile(r"^(?:FB|FC|DB|UDT|OB|DI)\s*\d+$", re.IGNORECASE)
# Instructions and types TIA Portal / STEP 7 bring along: a file that uses one is not missing
# a block of its repository, so an error about one is Nasaq's, not the corpus's.
SYSTEM_NAMES = frozenset(
    """TON TOF TP TONR CTU CTD CTUD R_TRIG F_TRIG SR RS IEC_TIMER IEC_LTIMER IEC_COUNTER
    IEC_UCOUNTER IEC_DCOUNTER IEC_SCOUNTER IEC_USCOUNTER IEC_UDCOUNTER IEC_LCOUNTER
    TON_TIME TOF_TIME TP_TIME TONR_TIME TON_LTIME TOF_LTIME TP_LTIME TONR_LTIME CTU_INT CTD_INT
    CTUD_INT CTU_DINT CTD_DINT CTUD_DINT CTU_UDINT CTUD_UDINT DTL VARIANT DB_ANY TIMER COUNTER
    SCALE_X NORM_X LIMIT MIN MAX SEL MUX MOVE_BLK FILL_BLK UMOVE_BLK MOVE_BLK_VARIANT
    RD_SYS_T RD_LOC_T WR_SYS_T TIME_TCK T_DIFF T_ADD T_SUB T_CONV T_COMBINE CONCAT LEFT RIGHT
    MID LEN FIND INSERT DELETE REPLACE SCALE UNSCALE BLKMOV FILL TSEND_C TRCV_C TSEND TRCV
    TCON TDISCON TURCV TUSEND MB_CLIENT MB_SERVER MB_MASTER MB_SLAVE PID_COMPACT PID_3STEP
    GET PUT DPRD_DAT DPWR_DAT RDREC WRREC GET_DIAG RALRM DEVICESTATES MODULESTATES
    LED GEN_DIAG RUNTIME SERIALIZE DESERIALIZE STRG_VAL VAL_STRG CHARS_TO_STRG STRG_TO_CHARS
    ATH HTA GETSYMBOLPATH GETINSTANCEPATH CTRL_PWM CTRL_PTO HSC_COUNT MC_POWER MC_HOME
    MC_MOVEABSOLUTE MC_MOVERELATIVE MC_MOVEVELOCITY MC_HALT MC_RESET MC_MOVEJOG
    PEEK POKE PEEK_BOOL POKE_BOOL ENCO DECO SWAP CTRL_HSC_EXT TCONFIG
    """.upper().split()
)
BLOCK_HEADER = re.compile(
    r"^\s*(?:FUNCTION_BLOCK|FUNCTION|DATA_BLOCK|TYPE|ORGANIZATION_BLOCK)\s+(\"[^\"]+\"|[\w ]+?)"
    r"(?=\s*(?::|$|\{|\r))",
    re.IGNORECASE | re.MULTILINE,
)
TIA_MARKERS = re.compile(
    r"S7_Optimized_Access|^\s*(?:END_)?REGION\b|#[A-Za-z_]|^\s*VERSION\s*:\s*\d|"
    r":\s*(?:Bool|Int|DInt|Real|Word|Byte|Time|String)\s*[;:]|"
    r"(?i::\s*(?:U?S?INT|U?DINT|U?LINT|LREAL|LWORD|W?STRING|WCHAR|LTIME|DTL|VARIANT|DB_ANY)"
    r"(?<!\bINT)(?<!\bDINT)(?<!\bSTRING)\b)",
    re.MULTILINE,
)


@dataclass
class Job:
    """One compilation: a file alone (``files`` has one source) or a repository."""

    repo: str
    label: str
    files: list[str]
    symbols: list[str]


@dataclass
class Outcome:
    """What became of one file (or, with kind "repository", of one repository)."""

    repo: str
    label: str
    kind: str = ""
    # accepted, accepted-1500, elsewhere, refused, exception, timeout, crash
    status: str = ""
    seconds: float = 0.0
    first: str = ""  # the first refusing error: "CODE normalised message"
    example: str = ""  # its location, file:line:column
    # every refusing error of the file, normalised like ``first``
    constructs: list[str] = field(default_factory=list)
    error_codes: list[str] = field(default_factory=list)
    exception: str = ""  # "Type at nasaq/...py:line in function: message"
    # repositories: their files without an error of their own
    clean_files: list[str] = field(default_factory=list)


# ----------------------------------------------------------------------------- the corpus


def kind_of(path: Path, text: str) -> str:
    """The file's kind for the per-kind shares (see the module docstring)."""
    suffix = path.suffix.lower()
    if suffix in (".db", ".udt"):
        return ".db/.udt"
    if suffix in (".awl", ".stl"):
        return "STL"
    return "TIA SCL" if TIA_MARKERS.search(text) else "Classic SCL"


def read_text(path: Path) -> str:
    data = path.read_bytes()
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("cp1252", errors="replace")


def jobs_of(corpus: Path, only: str | None) -> tuple[list[Job], list[Job]]:
    """The per-file jobs and the per-repository jobs of the corpus."""
    files: list[Job] = []
    repos: list[Job] = []
    for folder in sorted(p for p in corpus.iterdir() if p.is_dir()):
        if only and only not in folder.name:
            continue
        sources, symbols = [], []
        for path in sorted(p for p in folder.rglob("*") if p.is_file()):
            suffix = path.suffix.lower()
            if suffix in SOURCE_SUFFIXES:
                sources.append(str(path))
            elif suffix in SYMBOL_SUFFIXES:
                symbols.append(str(path))
        files += [Job(folder.name, source, [source], symbols) for source in sources]
        if len(sources) > 1:
            repos.append(Job(folder.name, folder.name, sources, symbols))
    return files, repos


def defined_names(paths: Iterable[str]) -> set[str]:
    """The block and type names the files define (upper case, without quotes), and the names
    the files write quoted in code: global names of the project (a PLC tag or a global
    constant of a tag table the repository lacks, which TIA Portal also resolves where a
    source writes it without quotes, ``TYPE_NONE`` beside ``"TYPE_NONE"``)."""
    names: set[str] = set()
    for path in paths:
        text = read_text(Path(path))
        for match in BLOCK_HEADER.finditer(text):
            names.add(match.group(1).strip().strip('"').upper())
        code = _NOT_CODE.sub(" ", text)
        names.update(match.group(1).upper() for match in _QUOTED_NAME.finditer(code))
    return names


# Comments and text constants, where a quoted word is no name; a quoted identifier in code.
_NOT_CODE = re.compile(r"//[^\n]*|\(\*.*?\*\)|/\*.*?\*/|'(?:[^'$]|\$.)*'", re.DOTALL)
_QUOTED_NAME = re.compile(r'"([A-Za-z_][A-Za-z0-9_]*)"')


# ----------------------------------------------------------------------------- the worker


def worker() -> None:
    """``corpus.py --worker``: compiles the jobs read from stdin (a JSON line each) under the
    memory limit and answers each with a JSON line; anything else the compiler prints goes to
    stderr, so the answers stay readable."""
    import resource

    answers = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    import nasaq.lang.scl.parse
    import nasaq.lang.stl.compiler  # noqa: F401 - imported before the first file is timed

    answers.write('"ready"\n')
    answers.flush()
    for line in sys.stdin:
        answers.write(json.dumps(compile_job(Job(**json.loads(line)))) + "\n")
        answers.flush()


def compile_job(job: Job) -> dict[str, Any]:
    """Compiles under S7-300, and again under S7-1500 when the profile was refused. ``seconds``
    is the compile's CPU time: on a machine shared with other work the wall time says more
    about the neighbours than about Nasaq."""
    started = time.process_time()
    try:
        first = compile_once(job, "S7-300")
        second = compile_once(job, "S7-1500") if first_needs_1500(first) else None
    except BaseException as error:  # every escape is a finding
        return {"exception": describe(error), "seconds": time.process_time() - started}
    return {
        "s7_300": first,
        "s7_1500": second,
        "seconds": time.process_time() - started,
    }


def compile_once(job: Job, profile: str) -> list[dict[str, Any]]:
    from nasaq.lang.stl.compiler import SourceFile, compile_sources

    sources = [
        SourceFile(Path(p).name if len(job.files) == 1 else p, Path(p).read_bytes())
        for p in job.files
    ]
    sources += [SourceFile(p, Path(p).read_bytes()) for p in job.symbols]
    result = compile_sources(sources, profile=profile)
    errors = []
    for item in result.diagnostics:
        if item.severity.value != "error":
            continue
        span = item.span
        errors.append(
            {
                "code": item.code,
                "message": item.message,
                "params": {k: str(v) for k, v in item.params.items()},
                "file": (span.file or "") if span else "",
                "line": span.line if span else 0,
                "column": span.column if span else 0,
            }
        )
    return errors


def first_needs_1500(errors: list[dict[str, Any]]) -> bool:
    return any(error["code"] in NEEDS_1500 for error in errors)


def describe(error: BaseException) -> str:
    """The exception's type, the innermost place in Nasaq's code, and its message."""
    import nasaq

    package = Path(nasaq.__file__).resolve().parent
    place = "outside nasaq"
    for frame in reversed(traceback.extract_tb(error.__traceback__)):
        path = Path(frame.filename).resolve()
        if path.is_relative_to(package):
            where = path.relative_to(package.parent).as_posix()
            place = f"{where}:{frame.lineno} in {frame.name}"
            break
    message = str(error).replace("\n", " ")[:160]
    return f"{type(error).__name__} at {place}: {message}"


# ----------------------------------------------------------------------------- the pool


def run_jobs(jobs: list[Job], count: int, timeout: float) -> list[tuple[Job, dict[str, Any]]]:
    """Runs the jobs on ``count`` worker processes; a worker that hangs or dies is replaced."""
    pending: queue.Queue[Job] = queue.Queue()
    for job in jobs:
        pending.put(job)
    results: list[tuple[Job, dict[str, Any]]] = []
    lock = threading.Lock()
    threads = [
        threading.Thread(target=drive, args=(pending, results, lock, timeout))
        for _ in range(max(1, count))
    ]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return results


def drive(
    pending: queue.Queue[Job],
    results: list[tuple[Job, dict[str, Any]]],
    lock: threading.Lock,
    timeout: float,
) -> None:
    """One worker's loop: send a job, wait for the answer, replace the worker if it hung or
    died."""
    process: subprocess.Popen[bytes] | None = None
    while True:
        try:
            job = pending.get_nowait()
        except queue.Empty:
            break
        try:
            if process is None or process.poll() is not None:
                process = start_worker()
            answer = ask(process, job, timeout * (1 if len(job.files) == 1 else 12))
        except (
            OSError,
            RuntimeError,
            ValueError,
        ) as error:  # the worker broke between jobs
            answer = {"crash": f"the worker broke: {error}", "seconds": 0.0}
        if "timeout" in answer or "crash" in answer:
            stop(process)
            process = None
        with lock:
            results.append((job, answer))
            progress(len(results), job)
    stop(process)


def start_worker() -> subprocess.Popen[bytes]:
    """A fresh worker, once it has imported Nasaq (that time is not a file's)."""
    command = [sys.executable, str(Path(__file__).resolve()), "--worker"]
    process = subprocess.Popen(
        command,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
    )
    assert process.stdout is not None
    ready, _, _ = select.select([process.stdout], [], [], 120)
    if not ready or process.stdout.readline().strip() != b'"ready"':
        stop(process)
        raise RuntimeError("a corpus worker did not start within 120 s")
    return process


def ask(process: subprocess.Popen[bytes], job: Job, timeout: float) -> dict[str, Any]:
    """The worker's answer to one job; a worker still busy after six times the limit (in wall
    time: a loaded machine is slower) is stopped and the job counts as a timeout."""
    assert process.stdin is not None
    assert process.stdout is not None
    process.stdin.write(json.dumps(asdict(job)).encode() + b"\n")
    process.stdin.flush()
    started = time.monotonic()
    ready, _, _ = select.select([process.stdout], [], [], 6 * timeout)
    if not ready:
        return {"timeout": True, "seconds": time.monotonic() - started}
    line = process.stdout.readline()
    if not line:
        code = process.wait(5)
        return {"crash": f"the worker died (exit code {code})", "seconds": 0.0}
    answer: dict[str, Any] = json.loads(line)
    return answer


def stop(process: subprocess.Popen[bytes] | None) -> None:
    if process is not None and process.poll() is None:
        process.kill()
        process.wait()


def progress(done: int, job: Job) -> None:
    if done % 100 == 0:
        print(f"{done} compiled ({job.repo})", file=sys.stderr, flush=True)


# ----------------------------------------------------------------------------- judging


def is_outside_reference(error: dict[str, Any], text_lines: list[str], defined: set[str]) -> bool:
    """Whether an error only says the file refers to a block, UDT or symbol it does not
    define: quoted names, absolute block names (FB 10, UDT 5) or names another file of the
    repository defines, and not an instruction or type TIA Portal itself provides."""
    if error["code"] in QUOTED_CODES:
        return quoted_at(text_lines, error["line"], error["column"])
    key = REFERENCE_CODES.get(error["code"])
    if key is None:
        return False
    name = error["params"].get(key, "")
    bare = name.strip().strip('"').upper()
    if not bare or bare in SYSTEM_NAMES:
        return False
    if name.startswith('"') or ABSOLUTE_BLOCK.match(bare) or bare in defined:
        return True
    return quoted_at(text_lines, error["line"], error["column"])


def quoted_at(lines: list[str], line: int, column: int) -> bool:
    """Whether the source has a quoted name at the error's place (the checker drops quotes)."""
    if not 1 <= line <= len(lines):
        return False
    text = lines[line - 1]
    return '"' in text[max(0, column - 2) : column]


def judge_file(job: Job, answer: dict[str, Any], defined: set[str]) -> Outcome:
    """The file's status and its first refusing error."""
    path = Path(job.files[0])
    text = read_text(path)
    outcome = Outcome(job.repo, job.label, kind=kind_of(path, text))
    outcome.seconds = round(answer.get("seconds", 0.0), 3)
    if failed(outcome, answer):
        return outcome
    errors = answer["s7_300"]
    if answer.get("s7_1500") is not None:
        if all(e["code"] in NEEDS_1500 for e in errors) and not answer["s7_1500"]:
            outcome.status = "accepted-1500"
            return outcome
        errors = answer["s7_1500"]
    outcome.error_codes = sorted({e["code"] for e in errors})
    if not errors:
        outcome.status = "accepted"
        return outcome
    lines = text.split("\n")
    own = [e for e in errors if not is_outside_reference(e, lines, defined)]
    if not own:
        outcome.status = "elsewhere"
        return outcome
    outcome.status = "refused"
    outcome.first = normalise(own[0])
    outcome.example = f"{job.label}:{own[0]['line']}:{own[0]['column']}"
    outcome.constructs = sorted({normalise(error) for error in own})
    return outcome


def failed(outcome: Outcome, answer: dict[str, Any]) -> bool:
    """Records an exception, a timeout or a crashed worker; False when the compiler answered."""
    if "exception" in answer:
        outcome.status, outcome.exception = "exception", answer["exception"]
    elif "timeout" in answer:
        outcome.status = "timeout"
    elif "crash" in answer:
        outcome.status, outcome.exception = "crash", answer["crash"]
    else:
        return False
    return True


def judge_repo(job: Job, answer: dict[str, Any], defined: set[str]) -> Outcome:
    """A repository compiled as a whole: accepted when every error is an outside reference."""
    outcome = Outcome(job.repo, job.label, kind="repository")
    outcome.seconds = round(answer.get("seconds", 0.0), 3)
    if failed(outcome, answer):
        return outcome
    errors = answer["s7_1500"] if answer.get("s7_1500") is not None else answer["s7_300"]
    lines_of: dict[str, list[str]] = {}
    own = []
    for error in errors:
        file = error["file"]
        if file and file not in lines_of and Path(file).is_file():
            lines_of[file] = read_text(Path(file)).split("\n")
        if not is_outside_reference(error, lines_of.get(file, []), defined):
            own.append(error)
    dirty = {e["file"] for e in own}
    outcome.clean_files = [p for p in job.files if p not in dirty]
    outcome.error_codes = sorted({e["code"] for e in own})
    outcome.status = "accepted" if not own else "refused"
    if own:
        outcome.first = normalise(own[0])
    return outcome


def normalise(error: dict[str, Any]) -> str:
    """``CODE message`` with the user's names replaced by ``<name>``."""
    message = error["message"]
    keep = REFERENCE_CODES.get(error["code"])  # what is missing is the construct: WString
    for key, value in error["params"].items():
        if key == keep:
            continue
        if key in NAME_PARAMS and value:
            message = message.replace(value, "<name>")
        elif key in NUMBER_PARAMS and value:
            message = message.replace(value, re.sub(r"\d+", "N", value))
    return f"{error['code']} {message}"[:140]


# ----------------------------------------------------------------------------- the report


ACCEPTED = ("accepted", "accepted-1500", "elsewhere")
# Refusals that say the source is valid but Nasaq cannot compile or simulate it (yet): still
# refusals, counted apart from syntax and type errors.
CANNOT_RUN = frozenset({"SCL301", "SCL501", "SCL800", "SCL920"})
KINDS = ("Classic SCL", "TIA SCL", "STL", ".db/.udt")


def share(outcomes: list[Outcome], statuses: Iterable[str] = ACCEPTED) -> str:
    wanted = set(statuses)
    hits = sum(1 for o in outcomes if o.status in wanted)
    return f"{hits}/{len(outcomes)} ({100 * hits / max(1, len(outcomes)):.1f} %)"


def report(files: list[Outcome], repos: list[Outcome], timeout: float) -> str:
    lines = [f"Corpus: {len(files)} files in {len({o.repo for o in files})} repositories"]
    counts = Counter(o.status for o in files)
    lines.append(f"Accepted: {share(files)}  ({', '.join(f'{k} {v}' for k, v in counts.items())})")
    lines.append(f"Accepted without 'elsewhere': {share(files, ('accepted', 'accepted-1500'))}")
    for kind in KINDS:
        chosen = [o for o in files if o.kind == kind]
        if chosen:
            lines.append(f"  {kind:<12} {share(chosen)}")
    lines.append(f"Mean of the repositories' accepted shares: {mean_share(files):.1f} %")
    honest = [o for o in files if o.status == "refused" and o.first[:6] in CANNOT_RUN]
    lines.append(
        f"Refused with a code saying Nasaq cannot run it ({', '.join(sorted(CANNOT_RUN))}):"
        f" {len(honest)}"
    )
    lines += failures(files + repos)
    lines += slowest(files, timeout)
    lines += per_repository(files, repos)
    lines += by_code(files)
    lines += histogram(files)
    lines += anywhere(files)
    return "\n".join(lines)


def anywhere(files: list[Outcome], shown: int = 40) -> list[str]:
    """How many refused files contain each refusing construct anywhere, not only first: the
    work behind the first errors."""
    bars = Counter(c for o in files if o.status == "refused" for c in o.constructs)
    lines = [f"\nRefused files containing each construct anywhere (top {shown}):"]
    lines += [f"  {count:4}  {construct}" for construct, count in bars.most_common(shown)]
    return lines


def mean_share(files: list[Outcome]) -> float:
    """The accepted share averaged over repositories, so that one large repository does not
    decide the figure alone."""
    shares = []
    for repo in {o.repo for o in files}:
        mine = [o for o in files if o.repo == repo]
        shares.append(100 * sum(1 for o in mine if o.status in ACCEPTED) / len(mine))
    return sum(shares) / max(1, len(shares))


def failures(outcomes: list[Outcome]) -> list[str]:
    """Exceptions (grouped by type and place), timeouts and crashes, files and repositories."""
    bad = [o for o in outcomes if o.status in ("exception", "timeout", "crash")]
    lines = [f"\nUncaught exceptions, timeouts, crashes: {len(bad)}"]
    places = Counter(o.exception.split(": ", 1)[0] or o.status for o in bad)
    lines += [f"  {count:4}  {place}" for place, count in places.most_common()]
    lines += [f"    {o.status}: {o.label}  {o.exception}" for o in bad[:40]]
    return lines


def slowest(files: list[Outcome], timeout: float) -> list[str]:
    ranked = sorted(files, key=lambda o: -o.seconds)[:10]
    over = sum(1 for o in files if o.seconds > timeout or o.status == "timeout")
    lines = [f"\nSlowest files ({over} over {timeout:g} s):"]
    lines += [f"  {o.seconds:7.2f} s  {o.label}" for o in ranked]
    return lines


def per_repository(files: list[Outcome], repos: list[Outcome]) -> list[str]:
    whole = {o.repo: o for o in repos}
    ok = sum(1 for o in repos if o.status == "accepted")
    total = sum(1 for o in files if o.repo in whole)
    clean = sum(len(o.clean_files) for o in repos)
    share_clean = f"{clean}/{total} ({100 * clean / max(1, total):.1f} %)"
    heading = f"\nRepositories compiled as a whole: {ok}/{len(repos)} accepted"
    lines = [f"{heading}; their files without an error of their own there: {share_clean}"]
    for repo in sorted({o.repo for o in files}):
        mine = [o for o in files if o.repo == repo]
        together = whole.get(repo)
        text = ""
        if together is not None:
            text = f"; together {together.status}, {len(together.clean_files)} files clean"
            text += f" ({together.first})" if together.first else ""
        lines.append(f"  {repo:<50} {share(mine)}{text}")
    return lines


def by_code(files: list[Outcome]) -> list[str]:
    """The refused files per code of their first refusing error."""
    codes = Counter(o.first.split(" ", 1)[0] for o in files if o.status == "refused")
    listed = ", ".join(f"{code} {count}" for code, count in codes.most_common())
    return [f"\nFirst refusing code: {listed or 'none'}"]


def histogram(files: list[Outcome]) -> list[str]:
    refused = [o for o in files if o.status == "refused"]
    bars = Counter(o.first for o in refused)
    lines = [f"\nFirst refusing construct ({len(refused)} files):"]
    for first, count in bars.most_common():
        kinds = Counter(o.kind for o in refused if o.first == first)
        example = next(o.example for o in refused if o.first == first)
        lines.append(f"  {count:4}  {first}")
        lines.append(f"        {dict(kinds)}  e.g. {example}")
    return lines


# ----------------------------------------------------------------------------- main


def measure(
    corpus: Path, only: str | None, jobs: int, timeout: float, whole: bool
) -> tuple[list[Outcome], list[Outcome]]:
    file_jobs, repo_jobs = jobs_of(corpus, only)
    defined = {job.repo: defined_names(job.files) for job in repo_jobs}
    answers = run_jobs(file_jobs + (repo_jobs if whole else []), jobs, timeout)
    files, repos = [], []
    for job, answer in answers:
        names = defined.get(job.repo, set())
        if job.label == job.repo:
            repos.append(judge_repo(job, answer, names))
        else:
            files.append(judge_file(job, answer, names))
    files.sort(key=lambda o: o.label)
    return files, repos


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", default=os.environ.get("NASAQ_CORPUS"))
    parser.add_argument("--json", type=Path, help="write every file's outcome here")
    parser.add_argument("--repo", help="only repositories whose folder name contains this")
    parser.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1))
    parser.add_argument("--timeout", type=float, default=5.0, help="seconds per file")
    parser.add_argument("--no-whole", action="store_true", help="skip the per-repository runs")
    parser.add_argument(
        "--fail-under",
        type=float,
        default=0.0,
        help="exit 1 below this accepted share (%%)",
    )
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        worker()
        return 0
    if not args.corpus or not Path(args.corpus).is_dir():
        print("Set NASAQ_CORPUS to the corpus folder (see tests/conformance/README.md).")
        return 2
    files, repos = measure(Path(args.corpus), args.repo, args.jobs, args.timeout, not args.no_whole)
    print(report(files, repos, args.timeout))
    if args.json:
        data = {
            "files": [asdict(o) for o in files],
            "repositories": [asdict(o) for o in repos],
        }
        args.json.write_text(json.dumps(data, indent=1), encoding="utf-8")
    return verdict(files + repos, args.fail_under)


def verdict(outcomes: list[Outcome], fail_under: float) -> int:
    """1 when a compilation raised, hung or crashed (the compilers must never do that), or
    when the accepted share of the files is below ``fail_under`` percent; else 0."""
    if any(o.status in ("exception", "timeout", "crash") for o in outcomes):
        return 1
    files = [o for o in outcomes if o.kind != "repository"]
    accepted = sum(1 for o in files if o.status in ACCEPTED)
    return 1 if 100 * accepted < fail_under * len(files) else 0


if __name__ == "__main__":
    sys.exit(main())
