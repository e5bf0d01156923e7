"""The conversion check ("draw this STL as LAD"): the learner's block converts to the target
language with every network drawn (no network kept as STL, i.e. no LAD3xx reason), and the
drawing survives the way back: converted back and drawn again, it is the same drawing.

The way back is compared as drawings, not as STL text: STEP 7 itself writes ``O( A A ) O( A
AN )`` back as ``A A O A AN`` (the same logic), so demanding the learner's exact STL would fail
correct programs.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic, Severity
from nasaq.lang.lad.convert import Target, convert
from nasaq.lessons.model import ConvertSpec
from nasaq.workbench.names import language_of

_SUFFIX = {"stl": ".awl", "lad": ".lad", "fbd": ".fbd"}


@dataclass(slots=True)
class ConversionResult:
    passed: bool
    error: str | None = None
    diagnostics: list[Diagnostic] = field(default_factory=list)


def check_conversion(files: Sequence[tuple[str, str]], spec: ConvertSpec) -> ConversionResult:
    texts = dict(files)
    name = spec.file
    text = texts.get(name)
    if text is None:
        return ConversionResult(False, f"the project has no file {name}")
    language = language_of(name)
    to: Target = spec.to.lower()  # type: ignore[assignment]
    if language not in _SUFFIX or language == to:
        return ConversionResult(False, f"{name} cannot be converted to {spec.to}")
    converted = convert(name, text, to)
    problems = [
        d
        for d in converted.diagnostics
        if d.severity is not Severity.INFO or d.code.startswith("LAD3")
    ]
    if any(d.severity is Severity.ERROR for d in problems):
        return ConversionResult(False, f"{name} does not convert", problems)
    if converted.kept:
        reason = f"{converted.kept} network(s) of {name} stay STL: they have no {spec.to} form"
        return ConversionResult(False, reason, problems)
    new_name = name[: name.rfind(".")] + _SUFFIX[to]
    back = convert(new_name, converted.text, language)  # type: ignore[arg-type]
    again = convert(name, back.text, to)
    if again.kept or _drawing(again.text) != _drawing(converted.text):
        return ConversionResult(False, f"{name} does not come back unchanged from {spec.to}")
    return ConversionResult(True)


def _drawing(text: str) -> list[str]:
    """The converted text without titles and comments, which a round trip may move."""
    return [
        line.strip()
        for line in text.split("\n")
        if line.strip() and not line.strip().upper().startswith(("TITLE", "//", "COMMENT"))
    ]
