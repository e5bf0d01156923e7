"""What a user's source goes through, run on one fuzz case; any exception is a finding.

``compile_sources`` with the file (parse, bind, check, lower, build: SCL and LAD/FBD files go
through the STL compiler's front door as in the IDE and ``nasaq compile``), then where the parse
succeeded the formatter the editor's Format Document runs on the server side (STL's
``format_source``, SCL's ``format.source``), and for LAD/FBD files the conversions to STL, LAD
and FBD (``nasaq.lang.lad.convert``); an STL source is also lifted to LAD as the View: LAD/FBD
does. The bounded run converts every third case (``Case.conversions``), to keep its budget.
"""

from __future__ import annotations

from nasaq.lang.lad.convert import convert
from nasaq.lang.scl import format as scl_format
from nasaq.lang.scl.parse import parse_source as parse_scl
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_source
from nasaq.lang.stl.parse import parse_source as parse_stl


def run_pipeline(
    name: str, language: str, text: str, profile: str, conversions: bool = True
) -> None:
    """Compiles, formats and (with ``conversions``) converts ``text``; raises what escapes."""
    result = compile_sources([SourceFile(name, text)], profile=profile)
    parsed_ok = not any(d.code.endswith(("101", "102", "103", "104")) for d in result.diagnostics)
    if language == "stl":
        if parsed_ok:
            parsed = parse_stl(name, text)
            if not parsed.diagnostics:
                format_source(parsed.source)
        if conversions:
            convert(name, text, "lad")
    elif language == "scl":
        if parsed_ok:
            scl = parse_scl(name, text)
            if not scl.diagnostics:
                scl_format.source(scl.source)
    elif conversions:
        for target in ("stl", "fbd", "lad"):
            convert(name, text, target)  # type: ignore[arg-type]
