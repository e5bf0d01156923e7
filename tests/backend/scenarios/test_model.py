from pathlib import Path

import pytest

from nasaq.scenarios.model import ScenarioError, load_scenario, note_text


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "case.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_a_full_scenario_loads_with_sources_relative_to_the_file(tmp_path: Path) -> None:
    scenario = load_scenario(
        _write(
            tmp_path,
            """
name: latch
sources: [latch.awl]
cycle_ms: 20
steps:
  - note: press start
  - set: {I0.0: 1, MW10: 16#FF}
  - run: 2
  - run: {ms: 50}
  - run: {scans: 3}
  - expect: {Q4.0: 1, mode: RUN, T1: {q: 1}, DB1.DBD0: {real: 2.5, tolerance: 0.01}}
""",
        )
    )
    assert scenario.source_paths() == [tmp_path / "latch.awl"]
    assert [step.scans(scenario.cycle_ms) for step in scenario.steps[2:5]] == [2, 3, 3]
    assert scenario.steps[1].set_ == {"I0.0": 1, "MW10": "16#FF"}


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("name: x\nsources: [a.awl]\nsteps: [{set: {I0: 1}}]\n", "bit number"),
        ("name: x\nsources: [a.awl]\nsteps: [{set: {I0.0: 1}, run: 1}]\n", "one thing"),
        ("name: x\nsources: [a.awl]\nsteps: [{run: {scans: 1, ms: 5}}]\n", "exactly one"),
        ("name: x\nsources: [a.awl]\nsteps: [{set: {mode: RUN}}]\n", "cannot be set"),
        ("name: x\nsources: []\nsteps: [{run: 1}]\n", "sources"),
        ("name: x\nsources: [a.awl]\nsteps: [{wait: 1}]\n", "wait"),
        ("name: [unclosed\n", ":1:"),
        ("- just a list\n", "mapping"),
    ],
)
def test_invalid_files_name_file_and_problem(tmp_path: Path, text: str, message: str) -> None:
    with pytest.raises(ScenarioError, match=r"case\.yaml") as error:
        load_scenario(_write(tmp_path, text))
    assert message in str(error.value)


def test_a_note_is_text_or_a_text_per_language(tmp_path: Path) -> None:
    scenario = load_scenario(
        _write(
            tmp_path,
            """
name: notes
sources: [a.awl]
steps:
  - note: plain English
  - note: {en: "overflow: network 1", fa: "سرریز در شبکهٔ 1"}
  - note: {fa: "فقط فارسی"}
""",
        )
    )
    plain, both, persian = (step.note for step in scenario.steps)
    assert note_text(plain, "fa") == "plain English"
    assert note_text(both, "fa") == "سرریز در شبکهٔ 1"
    assert note_text(both, "vi") == "overflow: network 1"  # then English
    assert note_text(persian, "en") == "فقط فارسی"  # then any language it has
    assert note_text(None, "fa") is None


@pytest.mark.parametrize(
    ("note", "message"),
    [
        ("{}", "note: write the text"),
        ("{english: x}", "english: a language code"),
        ('{en: "  "}', "en: a language code"),
        ("{en: [a, b]}", "note"),
    ],
)
def test_a_bad_note_mapping_is_refused(tmp_path: Path, note: str, message: str) -> None:
    text = f"name: x\nsources: [a.awl]\nsteps:\n  - note: {note}\n  - run: 1\n"
    with pytest.raises(ScenarioError, match=r"case\.yaml") as error:
        load_scenario(_write(tmp_path, text))
    assert message in str(error.value)
