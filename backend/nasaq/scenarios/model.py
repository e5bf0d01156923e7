"""The scenario file format (README.md beside this module), validated with pydantic."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, ValidationError, model_validator

from nasaq.headless.addresses import AddressError, parse_address


class ScenarioError(Exception):
    """A scenario file that cannot be used; the message names the file and what is wrong."""


class RunFor(BaseModel):
    model_config = ConfigDict(extra="forbid")

    scans: int | None = Field(default=None, ge=0, le=10_000_000)
    ms: float | None = Field(default=None, ge=0)

    @model_validator(mode="after")
    def _one_of(self) -> RunFor:
        if (self.scans is None) == (self.ms is None):
            raise ValueError("run needs exactly one of 'scans' or 'ms'")
        return self


class Step(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True)

    note: str | None = None
    set_: dict[str, Any] | None = Field(default=None, alias="set")
    run: int | RunFor | None = None
    expect: dict[str, Any] | None = None

    @model_validator(mode="after")
    def _one_action(self) -> Step:
        actions = [x for x in (self.set_, self.run, self.expect) if x is not None]
        if len(actions) > 1:
            raise ValueError("a step does one thing: set, run or expect")
        if not actions and self.note is None:
            raise ValueError("an empty step")
        for table in (self.set_, self.expect):
            for key in table or {}:
                if key != "mode":
                    try:
                        parse_address(str(key))
                    except AddressError as exc:
                        raise ValueError(str(exc)) from None
        if self.set_ and "mode" in self.set_:
            raise ValueError("the CPU mode cannot be set, only expected")
        return self

    def scans(self, cycle_ms: float) -> int:
        """How many scans this run step asks for."""
        if isinstance(self.run, int):
            return self.run
        assert self.run is not None
        if self.run.scans is not None:
            return self.run.scans
        assert self.run.ms is not None
        return int(-(-self.run.ms // cycle_ms))


class Scenario(BaseModel):
    model_config = ConfigDict(extra="forbid")

    name: str
    sources: list[str] = Field(min_length=1)
    cycle_ms: float = Field(default=10.0, gt=0, le=60_000)
    mnemonics: Literal["auto", "en", "de"] = "auto"
    profile: Literal["S7-300", "S7-400"] = "S7-300"
    steps: list[Step] = Field(min_length=1)

    _folder: Path = PrivateAttr(default=Path("."))

    def source_paths(self) -> list[Path]:
        """Sources are named relative to the scenario file."""
        return [self._folder / source for source in self.sources]


def load_scenario(path: Path) -> Scenario:
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise ScenarioError(f"{path}: {exc.strerror or exc}") from exc
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f":{mark.line + 1}:{mark.column + 1}" if mark is not None else ""
        problem = getattr(exc, "problem", exc)
        raise ScenarioError(f"{path}{where}: not valid YAML ({problem})") from None
    if not isinstance(data, dict):
        raise ScenarioError(f"{path}: a scenario is a mapping with name, sources and steps")
    try:
        scenario = Scenario.model_validate(data)
    except ValidationError as exc:
        errors = exc.errors()
        # Our own rules speak more plainly than a union's "should be a valid integer".
        first = next((e for e in errors if e["type"] == "value_error"), errors[0])
        where = ".".join(str(part) for part in first["loc"] if part not in ("int", "RunFor"))
        message = str(first["msg"]).removeprefix("Value error, ")
        raise ScenarioError(f"{path}: {where}: {message}") from None
    scenario._folder = path.parent
    return scenario
