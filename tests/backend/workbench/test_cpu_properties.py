"""``cpu.properties``: the CPU properties file, read with its problems by line, and what it does to
the simulated CPU."""

from __future__ import annotations

import itertools

from hypothesis import given, settings
from hypothesis import strategies as st

from nasaq.cpu import Cpu, Profile, Retentive
from nasaq.ir import Area, Direct, Program, Width
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.workbench.cpu_properties import CpuProperties, properties_of, read_properties
from nasaq.workbench.names import is_valid_name, language_of

FULL = """\
# Nasaq CPU properties
profile = S7-400
cycle_monitoring_time = 300 ms
cycle_time = 20        # the scan period
clock_memory = MB 100
retentive_markers = 32
retentive_timers = 4
retentive_counters = 0
startup = cold
"""


def _problems(text: str) -> list[tuple[int | None, int | None, str]]:
    found = read_properties(text)
    return [(d.span.line, d.span.column, d.code) for d in found.diagnostics if d.span]


def test_every_property_is_read() -> None:
    found = read_properties(FULL)
    assert found.ok, found.diagnostics
    assert found.properties == CpuProperties(
        profile=Profile.S7_400,
        cycle_monitoring_ms=300,
        cycle_ms=20,
        clock_memory=100,
        retentive=Retentive(markers=32, timers=4, counters=0),
        startup="cold",
    )


def test_an_empty_file_and_no_file_mean_the_s7_300_defaults() -> None:
    assert read_properties("# nothing set\n\n").properties == CpuProperties()
    assert properties_of([("OB1.awl", "")]).properties == CpuProperties()
    defaults = CpuProperties()
    assert (defaults.cycle_monitoring_ms, defaults.cycle_ms, defaults.clock_memory) == (
        150,
        10,
        None,
    )
    assert defaults.retentive == Retentive(16, 0, 8)
    assert properties_of([("cpu.properties", "cycle_time = 7")]).properties.cycle_ms == 7


def test_keys_and_words_are_case_insensitive_and_none_switches_the_clock_off() -> None:
    found = read_properties("PROFILE = s7-400\nClock_Memory: none\nstartup = Warm restart\n")
    assert found.ok, found.diagnostics
    assert found.properties.profile is Profile.S7_400
    assert found.properties.clock_memory is None
    assert found.properties.startup == "warm"


def test_the_s7_1500_profile_is_chosen_by_its_name_or_the_s7_1200s() -> None:
    for word in ("S7-1500", "s7-1200", "S7-1200/1500"):
        found = read_properties(f"profile = {word}\nretentive_markers = 10000\n")
        assert found.ok, found.diagnostics
        assert found.properties.profile is Profile.S7_1500
        assert found.properties.retentive.markers == 10000  # 16 KB of bit memory there
    bad = read_properties("profile = S7-1600\n")
    assert [d.message for d in bad.diagnostics] == [
        "profile = S7-1600: expected S7-300 | S7-400 | S7-1500."
    ]


def test_each_bad_line_is_reported_with_its_line_and_column_and_the_rest_applies() -> None:
    text = (
        "cycle_time = 20\n"  # 1: good
        "this is no property\n"  # 2: PRJ901
        "colour = red\n"  # 3: PRJ902
        "cycle_time = 30\n"  # 4: PRJ903 (the first stays)
        "profile = S7-1600\n"  # 5: PRJ904 at the value
        "cycle_monitoring_time = 9000\n"  # 6: PRJ905
        "startup = hot\n"  # 7: PRJ906
        "retentive_counters = 257\n"  # 8: PRJ905 for the S7-300
        "clock_memory = MB100\n"  # 9: good
    )
    assert _problems(text) == [
        (2, 1, "PRJ901"),
        (3, 1, "PRJ902"),
        (4, 1, "PRJ903"),
        (5, 11, "PRJ904"),
        (6, 25, "PRJ905"),
        (7, 11, "PRJ906"),
        (8, 22, "PRJ905"),
    ]
    found = read_properties(text)
    assert not found.ok
    assert (found.properties.cycle_ms, found.properties.clock_memory) == (20, 100)
    assert found.properties.retentive.counters == 8  # the bad value keeps the default
    messages = [d.message for d in found.diagnostics]
    assert "cycle_time is already set on line 1." in messages
    assert "cycle_monitoring_time = 9000: must be from 1 to 6000." in messages


def test_the_cycle_time_must_not_exceed_the_cycle_monitoring_time() -> None:
    assert _problems("cycle_monitoring_time = 100\ncycle_time = 200\n") == [(2, 14, "PRJ907")]
    assert _problems("cycle_monitoring_time = 5\n") == [(1, 25, "PRJ907")]  # default cycle 10 ms


def test_limits_follow_the_profile() -> None:
    assert _problems("clock_memory = MB2048\n") == [(1, 16, "PRJ905")]
    assert _problems("profile = S7-400\nclock_memory = MB2048\nretentive_timers = 2048\n") == []


@settings(max_examples=300, deadline=None)
@given(
    st.text(
        alphabet=st.sampled_from("abcdeimnprstuy_=:#MB0123456789 -.\n\t\"'"),
        max_size=200,
    )
)
def test_any_text_gives_properties_and_diagnostics_never_an_exception(
    text: str,
) -> None:
    found = read_properties(text)
    assert isinstance(found.properties, CpuProperties)
    lines = text.splitlines()
    for problem in found.diagnostics:
        assert problem.span is not None
        assert problem.span.line is not None
        assert 1 <= problem.span.line <= max(1, len(lines))


def test_the_file_is_a_project_file_the_compiler_skips() -> None:
    assert language_of("cpu.properties") == "cpu"
    assert is_valid_name("cpu.properties")
    assert not is_valid_name("plc.properties")  # a project has one CPU properties file
    ob1 = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      NOP 0;\nEND_ORGANIZATION_BLOCK\n"
    result = compile_sources(
        [
            SourceFile("OB1.awl", ob1),
            SourceFile("cpu.properties", "not = valid = text\n"),
        ]
    )
    assert result.ok
    assert result.diagnostics == []


CLOCK_EDGES = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     M    100.5;
      FP    M    101.0;
      JCN   skip;
      L     MW    10;
      +     1;
      T     MW    10;
skip: NOP   0;
END_ORGANIZATION_BLOCK
"""


def _clock_bit_program() -> Program:
    """OB1 counts the rising edges of M 100.5 in MW 10 (edge memory M 101.0)."""
    result = compile_sources([SourceFile("OB1.awl", CLOCK_EDGES)])
    assert result.ok, result.diagnostics
    return result.program


def test_the_clock_memory_of_the_file_toggles_m100_5_at_1_hz_on_simulated_time() -> None:
    props = read_properties("clock_memory = MB100\ncycle_time = 10\n").properties
    cpu = Cpu(_clock_bit_program(), cycle_ms=props.cycle_ms, **props.cpu_options())
    cpu.start()
    seen = []
    for _ in range(300):  # 3 s of virtual time, in a fraction of that on the wall clock
        cpu.scan()
        seen.append(cpu.read(Direct(Area.M, Width.BIT, 100, 5)))
    rising = sum(1 for a, b in itertools.pairwise(seen) if not a and b)
    assert rising == 3  # 1 Hz: up at 0.5 s, 1.5 s and 2.5 s
    assert cpu.read(Direct(Area.M, Width.WORD, 10)) == 3
