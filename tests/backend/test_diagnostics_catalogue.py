import json
import re
import string
from pathlib import Path

import pytest

from nasaq.diagnostics import Severity, Span, render
from nasaq.diagnostics.catalogue import all_entries


def test_codes_are_well_formed_and_keys_unique() -> None:
    entries = all_entries()
    assert entries, "the catalogue is empty"
    assert all(re.fullmatch(r"[A-Z]{3}\d{3}", e.code) for e in entries)
    keys = [e.key for e in entries]
    assert len(keys) == len(set(keys))


def test_every_template_names_its_parameters() -> None:
    for found in all_entries():
        fields = [name for _, name, _, _ in string.Formatter().parse(found.template) if name]
        assert all(name.isidentifier() for name in fields), found.code


def test_render_fills_the_message_and_keeps_the_span() -> None:
    span = Span(file="OB1.awl", line=3, column=5)
    diagnostic = render("API104", span=span, id=7)
    assert diagnostic.message == "Project 7 does not exist."
    assert diagnostic.severity is Severity.ERROR
    assert diagnostic.params == {"id": 7}
    assert diagnostic.span == span


def test_unknown_code_is_a_programming_error() -> None:
    with pytest.raises(KeyError):
        render("XYZ999")


FRONTEND = Path(__file__).resolve().parents[2] / "frontend" / "src"


def _problems(language: str) -> dict[str, str]:
    """``problems.*`` of the main catalogue and of every feature's own (``<feature>/locales``)."""
    found: dict[str, str] = {}
    for path in sorted(FRONTEND.glob(f"*/locales*/{language}.json")):  # graph/locales-syntax too
        found.update(json.loads(path.read_text("utf-8")).get("problems", {}))
    return found


@pytest.mark.parametrize("language", ["en", "ar", "fa", "vi"])
def test_every_code_is_translated_in_the_front_end(language: str) -> None:
    """The UI shows problems by key; a key missing from a catalogue would show raw English."""
    problems = _problems(language)
    for found in all_entries():
        assert found.key in problems, f"{language}: problems.{found.key} ({found.code}) is missing"
        ours = {name for _, name, _, _ in string.Formatter().parse(found.template) if name}
        theirs = set(re.findall(r"\{\{\s*(\w+)\s*\}\}", problems[found.key]))
        assert theirs <= ours, f"{language}: problems.{found.key} uses unknown {theirs - ours}"


def test_every_code_the_code_raises_is_catalogued() -> None:
    """A code written in the sources but missing from the catalogue would crash at run time."""
    catalogued = {found.code for found in all_entries()}
    package = Path(__file__).resolve().parents[2] / "backend" / "nasaq"
    used: dict[str, str] = {}
    for source in package.rglob("*.py"):
        for code in re.findall(
            r"[\"'((](?:API|NET|STL|SCL|SIM)\d{3}[\"')]", source.read_text("utf-8")
        ):
            used.setdefault(code[1:-1], source.name)
    missing = {code: where for code, where in used.items() if code not in catalogued}
    assert used
    assert missing == {}
