"""The scenario file format (README.md beside this module), validated with pydantic."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, ValidationError, model_validator

from nasaq.headless.addresses import AddressError, parse_address, parse_number
from nasaq.plants.runtime import PlantConfig

PLANT_KEY = "plant."  # expect keys on the plant: plant.<state name>, plant.faults


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


def _check_expect_keys(table: dict[str, Any]) -> None:
    for key in table:
        text = str(key)
        if text == "mode":
            continue
        if text.startswith(PLANT_KEY):
            if len(text) == len(PLANT_KEY):
                raise ValueError("plant.: name a state of the plant, or plant.faults")
            continue
        _check_address(text)


def _check_address(text: str) -> None:
    """An address, or a DB variable (``DB1.S5.X``) resolved once the program is compiled."""
    from nasaq.scenarios.members import is_member_key  # members.py reads ScenarioError

    try:
        parse_address(text)
    except AddressError as exc:
        if not is_member_key(text):
            raise ValueError(str(exc)) from None


class Interval(BaseModel):
    """``during`` / ``within``: a span of virtual time and what must hold in it."""

    model_config = ConfigDict(extra="forbid")

    ms: float = Field(gt=0, le=86_400_000)
    expect: dict[str, Any] = Field(min_length=1)

    @model_validator(mode="after")
    def _keys(self) -> Interval:
        _check_expect_keys(self.expect)
        return self


Note = str | dict[str, str]
"""A step's note: plain text (English), or per language ``{en: "...", fa: "..."}``."""


def note_text(note: Note | None, language: str = "en") -> str | None:
    """The note in ``language``, else in English, else in any language it has."""
    if note is None or isinstance(note, str):
        return note
    return note.get(language) or note.get("en") or next(iter(note.values()), None)


class Step(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True)

    note: Note | None = None
    set_: dict[str, Any] | None = Field(default=None, alias="set")
    run: int | RunFor | None = None
    expect: dict[str, Any] | None = None
    operate: dict[str, int | str] | None = None  # panel controls (16#.. too), held until changed
    fault: dict[str, int] | None = None  # inject (1) or clear (0) injectable plant faults
    during: Interval | None = None  # must hold after every scan of the interval
    within: Interval | None = None  # must come true before the interval ends
    restart: Literal["warm", "cold"] | None = None  # STOP -> RUN with OB100 (OB102 cold)

    @model_validator(mode="after")
    def _one_action(self) -> Step:
        actions = [
            x
            for x in (
                self.set_,
                self.run,
                self.expect,
                self.operate,
                self.fault,
                self.during,
                self.within,
                self.restart,
            )
            if x is not None
        ]
        if len(actions) > 1:
            raise ValueError(
                "a step does one thing: set, run, expect, operate, fault, during, within or restart"
            )
        if not actions and self.note is None:
            raise ValueError("an empty step")
        if isinstance(self.note, dict):
            if not self.note:
                raise ValueError("note: write the text, or {en: ..., <language>: ...}")
            for language, text in self.note.items():
                if not re.fullmatch(r"[a-z]{2}", language) or not text.strip():
                    raise ValueError(f"note: {language}: a language code (en, fa ...) and a text")
        for key in self.set_ or {}:
            if key != "mode":
                _check_address(str(key))
        _check_expect_keys(self.expect or {})
        for control, value in (self.operate or {}).items():
            if isinstance(value, str):
                try:
                    parse_number(value)
                except AddressError as exc:
                    raise ValueError(f"operate {control}: {exc}") from None
        if self.set_ and "mode" in self.set_:
            raise ValueError("the CPU mode cannot be set, only expected")
        return self

    def checks(self) -> bool:
        """True for the steps that compare (what a report lists as passed or failed)."""
        return self.expect is not None or self.during is not None or self.within is not None

    def scans(self, cycle_ms: float) -> int:
        """How many scans this run step asks for."""
        if isinstance(self.run, int):
            return self.run
        assert self.run is not None
        if self.run.scans is not None:
            return self.run.scans
        assert self.run.ms is not None
        return int(-(-self.run.ms // cycle_ms))


class ExpectedDiagnostic(BaseModel):
    """A compiler diagnostic the program must produce (``expect_diagnostics``)."""

    model_config = ConfigDict(extra="forbid")

    code: str = Field(pattern=r"^[A-Z]{3}\d{3}$")
    line: int | None = Field(default=None, ge=1)
    file: str | None = None


class Scenario(BaseModel):
    model_config = ConfigDict(extra="forbid")

    name: str
    # Omitted in a lesson's checks: the caller gives the project under test (``run_scenario``).
    sources: list[str] | None = Field(default=None, min_length=1)
    cycle_ms: float = Field(default=10.0, gt=0, le=60_000)
    mnemonics: Literal["auto", "en", "de"] = "auto"
    profile: Literal["S7-300", "S7-400", "S7-1500"] = "S7-300"
    # A plant in closed loop; "none" runs without the lesson's plant; omitted: the caller's.
    plant: PlantConfig | Literal["none"] | None = None
    expect_diagnostics: list[ExpectedDiagnostic] | None = Field(default=None, min_length=1)
    steps: list[Step] = Field(default_factory=list)

    _folder: Path = PrivateAttr(default=Path("."))

    @model_validator(mode="after")
    def _has_steps(self) -> Scenario:
        if not self.steps and self.expect_diagnostics is None:
            raise ValueError("steps: a scenario needs at least one step")
        return self

    def source_paths(self) -> list[Path]:
        """Sources are named relative to the scenario file."""
        return [self._folder / source for source in self.sources or []]


_UNION_PARTS = ("int", "RunFor", "PlantConfig", "literal['none']", "str", "dict[str,str]")


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
        where = ".".join(str(part) for part in first["loc"] if part not in _UNION_PARTS)
        message = str(first["msg"]).removeprefix("Value error, ")
        raise ScenarioError(f"{path}: {where}: {message}") from None
    scenario._folder = path.parent
    return scenario
