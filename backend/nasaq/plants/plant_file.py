"""A project's plant file, ``<name>.plant``: a PlantConfig in YAML, read with its lines.

::

    kind: tank
    wiring: {pump_pb: I0.0, stop_pb: I0.1, ls_low: I0.2, level: IW64, pump: Q4.0}
    params: {pump_rate: 5}
    faults: []

A project attaches at most one plant (one process per simulated CPU, as one Factory I/O scene
per PLCSIM instance). Every problem is a ``PLT###`` diagnostic naming the file and the line of
the key at fault (the wire, the parameter, the fault), so the editor and the download say
where to correct it; the configuration is checked the way the session builds it
(``PlantRuntime``), so a file that reads here also runs.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import yaml
from pydantic import ValidationError

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.diagnostics.validation import validation_reason
from nasaq.plants.base import PlantError
from nasaq.plants.runtime import PlantConfig, PlantRuntime

SUFFIX = ".plant"
MAX_PLANT_CHARS = 64 * 1024


def is_plant_file(name: str) -> bool:
    return name.lower().endswith(SUFFIX)


class PlantFileError(Exception):
    """A plant file that cannot run; ``diagnostic`` says what and where (code ``PLT###``)."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message)
        self.diagnostic = diagnostic

    @property
    def code(self) -> str:
        return self.diagnostic.code

    @property
    def params(self) -> dict[str, Any]:
        return dict(self.diagnostic.params)


@dataclass(slots=True)
class _Lines:
    """Line (1-based) of each key of the file: the top-level keys and the entries of
    ``wiring``, ``params`` and ``faults``."""

    top: dict[str, int]
    inner: dict[tuple[str, str], int]

    def of(self, subject: tuple[str, ...]) -> int:
        if len(subject) >= 2 and (subject[0], subject[1]) in self.inner:
            return self.inner[(subject[0], subject[1])]
        if subject and subject[0] in self.top:
            return self.top[subject[0]]
        return 1


def _lines(node: yaml.Node | None) -> _Lines:
    lines = _Lines({}, {})
    if not isinstance(node, yaml.MappingNode):
        return lines
    for key, value in node.value:
        name = str(key.value)
        lines.top[name] = key.start_mark.line + 1
        if isinstance(value, yaml.MappingNode):
            for inner_key, _ in value.value:
                lines.inner[(name, str(inner_key.value))] = inner_key.start_mark.line + 1
        elif isinstance(value, yaml.SequenceNode):
            for item in value.value:
                if isinstance(item, yaml.ScalarNode):
                    lines.inner[(name, str(item.value))] = item.start_mark.line + 1
    return lines


def _problem(code: str, file: str, line: int, **params: Any) -> PlantFileError:
    return PlantFileError(
        render(code, Span(file=file, line=line, column=1), file=file, line=line, **params)
    )


def read_plant_file(name: str, text: str) -> PlantConfig:
    """The configuration in ``text``, checked against its plant; raises ``PlantFileError``."""
    if len(text) > MAX_PLANT_CHARS:
        raise _problem(
            "PLT013", name, 1, field="-", reason=f"more than {MAX_PLANT_CHARS} characters"
        )
    try:
        node = yaml.compose(text, Loader=yaml.SafeLoader)
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        line = mark.line + 1 if mark is not None else 1
        reason = str(getattr(exc, "problem", None) or exc).strip()
        raise _problem("PLT001", name, line, reason=reason) from None
    lines = _lines(node)
    if not isinstance(data, dict):
        raise _problem(
            "PLT013", name, 1, field="kind", reason=validation_reason({"type": "dict_type"})
        )
    try:
        config = PlantConfig.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = tuple(str(part) for part in first.get("loc", ()))
        field = ".".join(where) or "-"
        raise _problem(
            "PLT013", name, lines.of(where), field=field, reason=validation_reason(first)
        ) from None
    check(config, name, lines)
    return config


def check(config: PlantConfig, name: str, lines: _Lines | None = None) -> PlantRuntime:
    """A runtime for ``config`` or the ``PlantFileError`` of its first problem."""
    try:
        return PlantRuntime(config)
    except PlantError as error:
        line = (lines or _Lines({}, {})).of(error.subject)
        raise _problem(error.code, name, line, **error.params) from None


def find_plant_file(sources: list[tuple[str, str]]) -> tuple[str, str] | None:
    """The project's plant file (name, text); ``PlantFileError`` PLT015 if there are two."""
    found = [(n, t) for n, t in sources if is_plant_file(n)]
    if len(found) > 1:
        raise _problem("PLT015", found[1][0], 1, other=found[0][0])
    return found[0] if found else None


def plant_file_problems(sources: list[tuple[str, str]]) -> list[Diagnostic]:
    """The problems of the project's plant file(s), for the project's list of problems (the
    editor marks the line before the user downloads); [] when there is none or it is fine."""
    if not any(is_plant_file(name) for name, _ in sources):
        return []
    try:
        found = find_plant_file(sources)
        if found is not None:
            read_plant_file(*found)
    except PlantFileError as error:
        return [error.diagnostic]
    return []
