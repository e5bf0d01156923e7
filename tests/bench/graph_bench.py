"""``make bench``: S7-Graph speed, as issue 18 asks.

(a) Compile: a generated sequencer of 200 steps with 20 action rows each (N, S, R, D, L, event
    rows, a few arithmetic rows, an interlock and a supervision on every tenth step), its
    transitions conditioned on inputs, compiled from ``.graph`` text to ``ir.Program`` (parse,
    check, lowering to STL, STL compile) in under 1 s.
(b) Run: one call of that FB on the CPU, with its inputs set so that every call moves the
    sequencer on by one step (one activation and one deactivation per call, the event rows
    run), against a hand-written STL FB of the same mix as generated code (bit logic, jumps,
    loads and transfers, INT arithmetic) executing about the same number of instructions. The
    Graph call must cost less than 3x per executed instruction (the CPU counts executed
    instructions: ``Cpu.instructions_executed``). A textbook STL step chain of the same
    sequencer (one step bit per step, one line per action row) is printed for context: it is
    what a user would otherwise write, not a target.
(c) Bad input: a 10,000-step source, a cycle of jumps without a condition on any transition,
    a sequencer without an initial step, a transition to a missing step: each answers with its
    diagnostic in under 1 s and without a traceback.

Run: ``python tests/bench/graph_bench.py`` (exit 1 when a target is missed).
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import TypeVar

from nasaq.cpu.api import Cpu
from nasaq.cpu.profile import Profile
from nasaq.diagnostics import Diagnostic
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.stl import SourceFile, compile_sources

STEPS = 200
ROWS = 20
COMPILE_BUDGET_S = 1.0
RATIO_BUDGET = 3.0
BAD_INPUT_BUDGET_S = 1.0
T = TypeVar("T")
CALLS = 200  # calls per measured run: one trip round the 200-step chain (ten runs, the best)

# Every transition's condition reads I 0.x (set: contact closed) and I 1.x (clear: NC contact
# closed), so with IB 0 = 16#FF and IB 1 = 0 each call moves the chain on by one step.
OB1 = """ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = the FB under test, once per scan
{body}
END_ORGANIZATION_BLOCK
"""
INSTANCE = """DATA_BLOCK DB {db}
FB {fb}
BEGIN
END_DATA_BLOCK
"""


# -- (a) the sequencer -------------------------------------------------------------------------
def _marker(step: int, row: int) -> str:
    """A marker bit per action row, spread over MB 10..209 (a step writes its own byte)."""
    return f"M {10 + (step - 1) % 200}.{row % 8}"


def _output(step: int, row: int) -> str:
    return f"Q {(step + row) % 16}.{(step * 3 + row) % 8}"


def _rows(step: int) -> list[str]:
    """Twenty action rows: plain N/S/R, D and L with times, event rows, two arithmetic rows."""
    m = _marker
    return [
        f"N {_output(step, 0)};",
        f"N {m(step, 1)};",
        f"S {m(step, 2)};",
        f"R {m(step, 3)};",
        f"D {m(step, 4)}, T#2S;",
        f"L {m(step, 5)}, T#1S;",
        f"S1 N {m(step, 6)};",
        f"S0 R {m(step, 7)};",
        "S1 N #count := #count + 1;",
        f"NC {_output(step, 9)};",
        f"N {m(step + 1, 0)};",
        f"S {m(step + 1, 1)};",
        f"R {m(step + 1, 2)};",
        f"S1 S {m(step + 1, 3)};",
        f"S0 N {m(step + 1, 4)};",
        f"D {_output(step, 15)}, T#500MS;",
        f"L {_output(step, 16)}, T#3S;",
        f"N {m(step + 1, 5)};",
        f"S1 R {m(step + 1, 6)};",
        "S1 N #total := #total + #count;",
    ]


def _condition(number: int) -> str:
    bit = number % 8
    if number % 5 == 0:  # a parallel branch now and then
        return (
            f"Parallel Branch Contact(I 0.{bit}) END_BRANCH "
            f"Branch Contact(I 2.{bit}) END_BRANCH END_PARALLEL ContactNC(I 1.{bit})"
        )
    return f"Contact(I 0.{bit}) ContactNC(I 1.{bit})"


def sequencer(steps: int = STEPS, rows: int = ROWS, fb: int = 1) -> str:
    """The ``.graph`` text of FB ``fb``: a chain of ``steps`` steps, the last jumping back."""
    lines = [
        f"FUNCTION_BLOCK FB {fb}",
        f"TITLE = Bench chain of {steps} steps",
        "VAR",
        "  count : INT;",
        "  total : INT;",
        "END_VAR",
        "BEGIN",
        "SEQUENCER Chain",
    ]
    for k in range(1, steps + 1):
        lines.append(f"{'INITIAL_STEP' if k == 1 else 'STEP'} Step{k} ({k})")
        if k % 10 == 0:
            lines.append(f"INTERLOCK ContactNC(I 3.{k % 8}) END_INTERLOCK")
            lines.append(f"SUPERVISION Box(CMP>D, IN1 := Step{k}.T, IN2 := T#100S) END_SUPERVISION")
        lines.append("ACTIONS")
        lines += [f"  {row}" for row in _rows(k)[:rows]]
        lines.append("END_ACTIONS")
        lines.append("END_STEP")
        to = "JUMP Step1" if k == steps else f"TO Step{k + 1}"
        lines.append(f"TRANSITION Tr{k} ({k}) FROM Step{k} {to}")
        lines.append(f"CONDITION {_condition(k)} END_CONDITION")
        lines.append("END_TRANSITION")
    lines += ["END_SEQUENCER", "END_FUNCTION_BLOCK", ""]
    return "\n".join(lines)


# -- (b) hand-written STL ----------------------------------------------------------------------
def _label(letter: str, number: int) -> str:
    """A jump label of STL's four characters: the letter and ``number`` in base 36."""
    digits = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ"
    return letter + "".join(digits[number // 36**p % 36] for p in (2, 1, 0))


def hand_mix(repeats: int, fb: int) -> str:
    """An FB of straight STL in the mix generated code has: bit logic on statics and markers,
    a conditional jump, loads and transfers, INT arithmetic. ``repeats`` blocks of 16 lines."""
    body: list[str] = []
    for k in range(repeats):
        byte = 10 + k % 200
        body += [
            f"      A     #b{k % 16}",
            f"      AN    I 1.{k % 8}",
            f"      O     M {byte}.{k % 8}",
            f"      =     #b{(k + 1) % 16}",
            f"      A     #b{(k + 2) % 16}",
            f"      JCN   {_label('H', k)}",
            "      L     #w0",
            "      L     1",
            "      +I    ",
            "      T     #w0",
            f"{_label('H', k)}: L     #w1",
            "      L     #w0",
            "      >I    ",
            f"      S     M {byte}.{(k + 1) % 8}",
            f"      A     I 0.{k % 8}",
            f"      R     #b{(k + 3) % 16}",
        ]
    statics = [f"  b{k} : BOOL;" for k in range(16)] + ["  w0 : INT;", "  w1 : INT;"]
    head = [f"FUNCTION_BLOCK FB {fb}", "VAR", *statics, "END_VAR", "BEGIN", "NETWORK"]
    return "\n".join([*head, *body, "END_FUNCTION_BLOCK", ""])


def hand_chain(steps: int, fb: int) -> str:
    """The textbook step chain of the same sequencer: a step bit per step (the initial one set
    on the first call), each transition ``A X(k); A cond; R X(k); S X(k+1)`` evaluated from the
    last step back (so a step activated in this call is not left in it), event rows on an edge
    flag per step, D and L rows on one S5 timer per step (T k-1)."""
    out = [f"FUNCTION_BLOCK FB {fb}", "VAR"]
    out += [f"  X{k} : BOOL;" for k in range(1, steps + 1)]
    out += [f"  E{k} : BOOL;" for k in range(1, steps + 1)]
    out += ["  started : BOOL;", "  count : INT;", "  total : INT;", "END_VAR", "BEGIN"]
    out += ["NETWORK", "      AN    #started", "      S     #X1", "      S     #started"]
    order = [*range(steps - 1, 0, -1), steps]
    for k in order:
        bit = k % 8
        nxt = 1 if k == steps else k + 1
        if k % 5 == 0:
            cond = ["      A(    ", f"      O     I 0.{bit}", f"      O     I 2.{bit}", "      )"]
        else:
            cond = [f"      A     I 0.{bit}"]
        out += ["NETWORK", f"      A     #X{k}", *cond, f"      AN    I 1.{bit}"]
        out += [f"      R     #X{k}", f"      S     #X{nxt}"]
    for k in range(1, steps + 1):
        x = f"#X{k}"
        m = _marker
        timer = f"T {k - 1}"
        rows = [
            f"      A     {x}",
            f"      =     {_output(k, 0)}",
            f"      =     {m(k, 1)}",
            f"      S     {m(k, 2)}",
            f"      R     {m(k, 3)}",
            f"      =     {_output(k, 9)}",
            f"      =     {m(k + 1, 0)}",
            f"      S     {m(k + 1, 1)}",
            f"      R     {m(k + 1, 2)}",
            f"      =     {m(k + 1, 5)}",
            "      L     S5T#2S",
            f"      SD    {timer}",
            f"      A     {timer}",
            f"      =     {m(k, 4)}",
            f"      =     {_output(k, 15)}",
            f"      A     {x}",
            f"      AN    {timer}",
            f"      =     {m(k, 5)}",
            f"      =     {_output(k, 16)}",
            f"      A     {x}",
            f"      FP    #E{k}",
            f"      JCN   {_label('A', k)}",
            f"      S     {m(k, 6)}",
            f"      S     {m(k + 1, 3)}",
            f"      R     {m(k + 1, 6)}",
            "      L     #count",
            "      L     1",
            "      +I    ",
            "      T     #count",
            "      L     #total",
            "      +I    ",
            "      T     #total",
            f"{_label('A', k)}: AN    {x}",
            f"      R     {m(k, 7)}",
            f"      S     {m(k + 1, 4)}",
        ]
        out += ["NETWORK", *rows]
    out += ["END_FUNCTION_BLOCK", ""]
    return "\n".join(out)


# -- measuring ---------------------------------------------------------------------------------
def _errors(diagnostics: list[Diagnostic]) -> list[str]:
    return [f"{d.code} {d.message}" for d in diagnostics if d.severity == "error"]


def _program(name: str, text: str, fb: int | None) -> Cpu:
    """A CPU on ``text`` with an OB 1 calling FB ``fb`` with DB ``fb`` (none: an empty OB 1)."""
    body = f"      CALL  FB {fb} , DB {fb}" if fb is not None else "      NOP   0"
    sources = [SourceFile("ob1.awl", OB1.format(body=body))]
    if fb is not None:
        sources += [SourceFile(name, text), SourceFile("db.awl", INSTANCE.format(db=fb, fb=fb))]
    result = compile_sources(sources)
    errors = _errors(result.diagnostics)
    if errors:
        raise SystemExit(f"graph bench: {name} does not compile: {errors[:5]}")
    cpu = Cpu(result.program, profile=Profile.S7_300, watchdog_ms=60_000)
    for address, value in (("IB 0", 0xFF), ("IB 1", 0), ("IB 2", 0), ("IB 3", 0)):
        target = parse_address(address)
        assert isinstance(target, Direct)
        cpu.set_input(target, value)
    cpu.start()
    cpu.scan()  # compiles the blocks to Python, first call
    if cpu.mode != "RUN":
        raise SystemExit(f"graph bench: {name} stopped the CPU: {cpu.stop_reason}")
    return cpu


def per_scan(cpu: Cpu, scans: int, runs: int = 10) -> tuple[float, float]:
    """(seconds, executed instructions) per scan, the best of ``runs`` runs of ``scans`` scans
    (short runs, so that another process taking the core spoils a few of them, not all)."""
    best = float("inf")
    executed = 0
    for _ in range(runs):
        before = cpu.instructions_executed
        started = time.perf_counter()
        cpu.run(scans)
        best = min(best, time.perf_counter() - started)
        executed = cpu.instructions_executed - before
    if cpu.mode != "RUN":
        raise SystemExit(f"graph bench: the CPU stopped: {cpu.stop_reason}")
    return best / scans, executed / scans


def timed(action: Callable[[], T]) -> tuple[float, T]:
    started = time.perf_counter()
    value = action()
    return time.perf_counter() - started, value


def bench_compile(source: str) -> tuple[bool, bool]:
    """(within the budget, compiles without errors)."""
    from nasaq.lang.graph.compile import lower_file
    from nasaq.lang.graph.text import parse_graph

    compile_sources([SourceFile("warm.graph", sequencer(3, 4))])  # imports, grammar tables
    parse_s = min(timed(lambda: parse_graph(source, "chain.graph"))[0] for _ in range(3))
    lower_s = min(timed(lambda: lower_file("chain.graph", source))[0] for _ in range(3))
    whole_s = float("inf")
    for _ in range(3):
        seconds, result = timed(lambda: compile_sources([SourceFile("chain.graph", source)]))
        whole_s = min(whole_s, seconds)
    errors = _errors(result.diagnostics)
    if errors:
        print(f"graph bench: the 200-step sequencer does not compile: {errors[:5]}")
        return False, False
    stl_lines = lower_file("chain.graph", source).stl.count("\n")
    ok = whole_s < COMPILE_BUDGET_S
    print(
        f"Graph compile, {STEPS} steps x {ROWS} action rows ({source.count(chr(10))} lines, "
        f"{stl_lines} lines of STL): {whole_s * 1000:.0f} ms (parse {parse_s * 1000:.0f} ms, "
        f"parse+check+lower {lower_s * 1000:.0f} ms) (budget {COMPILE_BUDGET_S * 1000:.0f} ms) "
        f"{'ok' if ok else 'TOO SLOW'}"
    )
    return ok, True


def bench_run(source: str) -> bool:
    empty_s, empty_n = per_scan(_program("empty", "", None), CALLS)
    graph_s, graph_n = per_scan(_program("chain.graph", source, 1), CALLS)
    graph_s, graph_n = graph_s - empty_s, graph_n - empty_n
    # Size the hand-written FB to the Graph FB's count: measure one block of 16 lines first.
    _, probe_n = per_scan(_program("probe.awl", hand_mix(10, 2), 2), 20, runs=1)
    repeats = max(1, round(graph_n / max(1.0, (probe_n - empty_n) / 10)))
    hand_s, hand_n = per_scan(_program("mix.awl", hand_mix(repeats, 2), 2), CALLS)
    hand_s, hand_n = hand_s - empty_s, hand_n - empty_n
    chain_s, chain_n = per_scan(_program("chain.awl", hand_chain(STEPS, 3), 3), CALLS)
    chain_s, chain_n = chain_s - empty_s, chain_n - empty_n
    ratio = (graph_s / graph_n) / (hand_s / hand_n)
    ok = ratio < RATIO_BUDGET
    print(
        f"Graph FB call, {STEPS} steps, one step on per call: {graph_s * 1e6:.0f} us, "
        f"{graph_n:.0f} STL instructions ({graph_n / graph_s / 1e6:.2f} M/s)"
    )
    print(
        f"hand-written STL, same mix: {hand_s * 1e6:.0f} us, {hand_n:.0f} instructions "
        f"({hand_n / hand_s / 1e6:.2f} M/s)"
    )
    print(
        f"Graph / hand-written STL per instruction: {ratio:.2f}x (budget < {RATIO_BUDGET:.0f}x) "
        f"{'ok' if ok else 'TOO SLOW'}"
    )
    print(
        f"for context, a textbook STL step chain of the same sequencer: {chain_s * 1e6:.0f} us "
        f"per call, {chain_n:.0f} instructions; the Graph FB costs {graph_s / chain_s:.1f}x it"
    )
    return ok


def bad_sources() -> list[tuple[str, str, str]]:
    """(what, source, the catalogue code that must be among its diagnostics)."""
    huge = sequencer(10_000, 2)
    cycle = ["FUNCTION_BLOCK FB 1", "BEGIN", "SEQUENCER Loop"]
    for k in range(1, 51):
        cycle.append(f"{'INITIAL_STEP' if k == 1 else 'STEP'} L{k} ({k})")
        cycle.append("END_STEP")
        target = "L1" if k == 50 else f"L{k + 1}"
        cycle.append(f"TRANSITION J{k} ({k}) FROM L{k} JUMP {target}")
        cycle.append("END_TRANSITION")
    cycle += ["END_SEQUENCER", "END_FUNCTION_BLOCK", ""]
    settings = "SETTINGS\n  SKIP_STEPS := TRUE;\nEND_SETTINGS\n"
    skipping = "\n".join(cycle).replace("FUNCTION_BLOCK FB 1\n", f"FUNCTION_BLOCK FB 1\n{settings}")
    no_initial = sequencer(20, 4).replace("INITIAL_STEP", "STEP")
    missing = sequencer(20, 4).replace("FROM Step7 TO Step8", "FROM Step7 TO Step99")
    return [
        ("a 10,000-step source", huge, "GRA208"),
        ("cyclic jumps, no condition on any transition", "\n".join(cycle), "GRA212"),
        ("the same cycle with skip steps on", skipping, "GRA212"),
        ("no initial step", no_initial, "GRA206"),
        ("a transition to a missing step", missing, "GRA203"),
    ]


def bench_bad_input() -> bool:
    ok = True
    for what, text, expected in bad_sources():
        try:
            seconds, result = timed(
                lambda text=text: compile_sources([SourceFile("bad.graph", text)])
            )
        except Exception as error:  # the point of the bench: this must never happen
            print(f"bad input, {what}: TRACEBACK {type(error).__name__}: {error}")
            ok = False
            continue
        found = [d for d in result.diagnostics if d.code == expected]
        good = bool(found) and seconds < BAD_INPUT_BUDGET_S
        shown = f"{expected}: {found[0].message[:80]}" if found else f"NO {expected}"
        others = len(result.diagnostics) - len(found)
        print(
            f"bad input, {what}: {seconds * 1000:.0f} ms, {shown} (+{others} more) "
            f"{'ok' if good else 'FAILED'}"
        )
        ok = ok and good
    return ok


def main() -> int:
    source = sequencer()
    fast, compiles = bench_compile(source)
    ran = bench_run(source) if compiles else False
    bad = bench_bad_input()
    return 0 if fast and ran and bad else 1


if __name__ == "__main__":
    sys.exit(main())
