"""``/api/cpu-properties``: the CPU properties file (``nasaq.workbench.cpu_properties``) checked
for the properties page, and how a download applies it.

The page writes the file through the files API (version check, autosave) and asks this route
what the text means: the values and the PRJ9xx problems with their lines, so the page and the
simulator read the file with one parser. A download refuses a file with errors (PRJ908) rather
than run with values the user did not choose; options a client sends explicitly win over the
file, as command-line options win in ``nasaq run``.
"""

from __future__ import annotations

from typing import Any, TypeVar

from fastapi import APIRouter
from pydantic import BaseModel, Field

from nasaq.api.errors import ApiError
from nasaq.diagnostics import Diagnostic
from nasaq.workbench.cpu_properties import FILE_NAME, find, read_properties
from nasaq.workbench.names import MAX_TEXT_CHARS

router = APIRouter(prefix="/cpu-properties", tags=["workbench"])

Options = TypeVar("Options", bound=BaseModel)


class PropertiesText(BaseModel):
    text: str = Field(max_length=MAX_TEXT_CHARS, description="The text of cpu.properties")


class PropertiesCheck(BaseModel):
    properties: dict[str, Any] = Field(
        description="The values the CPU would run with (a bad line keeps its key's default)"
    )
    diagnostics: list[Diagnostic]


@router.post(
    "/check",
    response_model=PropertiesCheck,
    summary="What a cpu.properties text means: the values and the problems by line",
)
async def check(body: PropertiesText) -> PropertiesCheck:
    found = read_properties(body.text, FILE_NAME)
    return PropertiesCheck(properties=found.properties.as_json(), diagnostics=found.diagnostics)


def checked(sources: list[tuple[str, str]]) -> None:
    """Raises PRJ908 (422) when the sources' CPU properties file has an error."""
    found = find(sources)
    if found is None:
        return
    read = read_properties(found[1], found[0])
    for problem in read.diagnostics:
        line = problem.span.line if problem.span is not None else 1
        raise ApiError("PRJ908", 422, file=found[0], line=line, problem=problem.code)


def with_properties(sources: list[tuple[str, str]], options: Options) -> Options:
    """``options`` with the profile and cycle time of the sources' CPU properties where the
    client did not send them; raises PRJ908 for a file with errors."""
    checked(sources)
    found = find(sources)
    if found is None:
        return options
    properties = read_properties(found[1], found[0]).properties
    update: dict[str, Any] = {}
    if "profile" not in options.model_fields_set:
        update["profile"] = properties.profile.value
    if "cycle_ms" not in options.model_fields_set:
        update["cycle_ms"] = properties.cycle_ms
    return options.model_copy(update=update)
