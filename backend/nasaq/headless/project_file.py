"""The CPU properties file (``cpu.properties``, format in ``nasaq.workbench.cpu_properties``)
of a folder of sources, for ``nasaq run`` and ``nasaq test``.

The file is found among the given sources (``nasaq run prog.awl cpu.properties``) or, as in an
exported project, beside the first source. Its properties apply where the command line (or the
scenario file) does not say otherwise; a file with errors stops the command with its problems
as ``file:line:column: code: message``, as a source that does not compile does.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from nasaq.headless.sources import SourceError, diagnostic_line, read_source
from nasaq.workbench.cpu_properties import FILE_NAME, ReadProperties, is_properties_file
from nasaq.workbench.cpu_properties import read_properties as parse


def locate(sources: Sequence[Path]) -> Path | None:
    """The properties file the sources bring, or None."""
    for path in sources:
        if is_properties_file(path.name):
            return path
    if sources:
        beside = sources[0].parent / FILE_NAME
        if beside.is_file():
            return beside
    return None


def load(sources: Sequence[Path]) -> ReadProperties | None:
    """The properties of the sources' folder (None without the file); raises SourceError for an
    unreadable file."""
    path = locate(sources)
    if path is None:
        return None
    text = read_source(path).text
    return parse(text if isinstance(text, str) else text.decode(), str(path))


def problems(found: ReadProperties) -> list[str]:
    return [diagnostic_line(problem) for problem in found.diagnostics]


def profile_of(sources: Sequence[Path]) -> str:
    """The CPU family the sources are compiled for (``nasaq compile``): the file's profile (a bad
    line keeps the default, as everywhere), S7-300 without a readable file."""
    try:
        found = load(sources)
    except SourceError:
        found = None
    return found.properties.profile.value if found is not None else "S7-300"


__all__ = ["SourceError", "load", "locate", "problems", "profile_of"]
