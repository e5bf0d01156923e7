"""Compiling a whole project for the workbench (the live check, the tree, outline, cross
references, rename, symbols): for the CPU family its ``cpu.properties`` names.

One helper, so that what the editor reports is what the download (``nasaq.monitor.download``)
and ``nasaq run`` compile: an S7-1500 project's LREAL is no error in the editor either. A
properties file with a bad line keeps the default profile for that line, as everywhere.
"""

from __future__ import annotations

from collections.abc import Sequence

from nasaq.lang.profiles import DEFAULT_PROFILE
from nasaq.lang.stl import CompileResult, SourceFile, compile_sources
from nasaq.workbench.cpu_properties import find, read_properties


def project_profile(sources: Sequence[tuple[str, str]]) -> str:
    """The profile the project's ``cpu.properties`` chooses, S7-300 without one."""
    found = find(sources)
    if found is None:
        return DEFAULT_PROFILE
    return read_properties(found[1], found[0]).properties.profile.value


def compile_project(sources: Sequence[tuple[str, str]]) -> CompileResult:
    """Every file of the project compiled together for the project's profile."""
    return compile_sources(
        (SourceFile(name, text) for name, text in sources), profile=project_profile(sources)
    )
