"""The files of a lesson folder as models: ``unit.yaml``, ``lesson.yaml``, ``hints.yaml`` and
``quiz.yaml`` (format in ``examples/lessons/README.md``), and the problems found reading them.

A problem always names its file and, when the YAML says it, its line: a teacher who broke a
lesson finds the place, and the course outline keeps every other lesson.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal, TypeVar

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from nasaq.diagnostics import render
from nasaq.plants.runtime import PlantConfig

Texts = dict[str, str]  # language -> text
RTL_LANGUAGES = ("ar", "fa")
WorksIn = Literal["LAD", "FBD", "STL", "SCL", "none"]
Form = Literal["program", "find-the-bug", "find-the-fault", "quiz", "predict", "conversion"]


class Problem(BaseModel):
    """A problem of a lesson folder: the file (relative to the course folder), its line, a
    catalogue code (LSN) and the English message; ``key`` and ``params`` translate it."""

    file: str
    line: int | None = None
    code: str
    key: str = ""
    message: str
    params: dict[str, Any] = Field(default_factory=dict)

    @classmethod
    def of(cls, file: str, line: int | None, code: str, **params: Any) -> Problem:
        found = render(code, **params)
        return cls(
            file=file,
            line=line,
            code=code,
            key=found.key,
            message=found.message,
            params=found.params,
        )

    def text(self) -> str:
        line = f":{self.line}" if self.line is not None else ""
        return f"{self.file}{line}: {self.code}: {self.message}"


class UnitMeta(BaseModel):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1)
    order: int
    seed: str
    language: str = Field(min_length=2, max_length=3)
    title: Texts
    summary: Texts = Field(default_factory=dict)


class SourceRows(BaseModel):
    model_config = ConfigDict(extra="forbid")

    seed: str
    rows: list[str] = Field(default_factory=list)


class ConvertSpec(BaseModel):
    model_config = ConfigDict(extra="forbid")

    file: str = Field(min_length=1)
    to: Literal["LAD", "FBD", "STL", "lad", "fbd", "stl"]


class CheckSpec(BaseModel):
    model_config = ConfigDict(extra="forbid")

    scenario: str | None = None
    convert: ConvertSpec | None = None
    quiz: str | None = None

    @model_validator(mode="after")
    def _one(self) -> CheckSpec:
        if sum(x is not None for x in (self.scenario, self.convert, self.quiz)) != 1:
            raise ValueError("a check is one of scenario, convert or quiz")
        return self

    @property
    def kind(self) -> Literal["scenario", "convert", "quiz"]:
        if self.scenario is not None:
            return "scenario"
        return "convert" if self.convert is not None else "quiz"

    @property
    def name(self) -> str:
        if self.scenario is not None:
            return self.scenario
        if self.convert is not None:
            return f"{self.convert.file} -> {self.convert.to.upper()}"
        return self.quiz or ""


class LessonMeta(BaseModel):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1)
    unit: str
    order: int
    source: SourceRows | None = None
    languages: list[str] = Field(min_length=1)
    title: Texts
    summary: Texts = Field(default_factory=dict)
    prerequisites: list[str] = Field(default_factory=list)
    works_in: WorksIn
    open: str | None = None
    form: Form = "program"
    time_limit_min: int | None = Field(default=None, ge=1)
    plant: PlantConfig | None = None
    checks: list[CheckSpec] = Field(min_length=1)

    @model_validator(mode="after")
    def _open(self) -> LessonMeta:
        if self.works_in != "none" and not self.open:
            raise ValueError("open: name the start/ file the editor opens first")
        return self


class Option(BaseModel):
    model_config = ConfigDict(extra="forbid")

    id: str
    text: Texts


class NumberAnswer(BaseModel):
    model_config = ConfigDict(extra="forbid")

    value: float
    tolerance: float = Field(default=0.0, ge=0)


class Question(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True)

    id: str = Field(min_length=1)
    kind: Literal["choice", "multi", "number", "text", "predict"]
    prompt: Texts
    options: list[Option] = Field(default_factory=list)
    answer: Any = None
    explain: Texts | None = None
    program: str | None = None  # predict: the program, relative to the lesson folder
    set_: dict[str, Any] = Field(default_factory=dict, alias="set")
    scans: int = Field(default=1, ge=1, le=100_000)
    ask: list[str] = Field(default_factory=list)

    @model_validator(mode="after")
    def _answer(self) -> Question:
        ids = [option.id for option in self.options]
        answer = self.answer
        if self.kind == "choice":
            if len(ids) < 2 or answer not in ids:
                raise ValueError("a choice needs two options or more and the id of the right one")
        elif self.kind == "multi":
            if len(ids) < 2 or not isinstance(answer, list) or not set(answer) <= set(ids):
                raise ValueError("a multi needs options and the list of the right ids")
        elif self.kind == "number":
            self.answer = NumberAnswer.model_validate(
                answer if isinstance(answer, dict) else {"value": answer}
            )
        elif self.kind == "text":
            spellings = [answer] if isinstance(answer, str | int | float) else answer
            if not isinstance(spellings, list) or not spellings:
                raise ValueError("a text question needs the accepted spellings")
            self.answer = [str(item) for item in spellings]
        else:  # predict: the truth is what the program does, never typed in
            if answer is not None:
                raise ValueError("a predict question has no answer: the server runs the program")
            if not self.program or not self.ask:
                raise ValueError("a predict question needs program and ask")
        return self


class Quiz(BaseModel):
    model_config = ConfigDict(extra="forbid")

    questions: list[Question] = Field(min_length=1)

    @model_validator(mode="after")
    def _unique(self) -> Quiz:
        ids = [question.id for question in self.questions]
        if len(ids) != len(set(ids)):
            raise ValueError("question ids must be unique")
        return self


class LessonFileError(Exception):
    """A lesson file that cannot be used; ``problem`` says where and why."""

    def __init__(self, problem: Problem) -> None:
        super().__init__(problem.text())
        self.problem = problem


def line_of(node: yaml.Node | None, loc: tuple[int | str, ...]) -> int | None:
    """The 1-based line of the YAML node at ``loc`` (a pydantic error location), or the
    nearest enclosing node's line."""
    if node is None:
        return None
    line: int = node.start_mark.line + 1
    for part in loc:
        child: yaml.Node | None = None
        if isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                if isinstance(key, yaml.ScalarNode) and key.value == str(part):
                    child = value
                    break
        elif isinstance(node, yaml.SequenceNode) and isinstance(part, int) and part >= 0:
            child = node.value[part] if part < len(node.value) else None
        if child is None:
            break
        node = child
        line = node.start_mark.line + 1
    return line


Model = TypeVar("Model", bound=BaseModel)


def read_yaml(path: Path, shown: str) -> tuple[Any, yaml.Node | None]:
    """The data and the node tree of a YAML file; LessonFileError with the line if it cannot
    be read or parsed."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        reason = getattr(exc, "strerror", None) or str(exc)
        raise LessonFileError(Problem.of(shown, None, "LSN201", reason=reason)) from None
    try:
        node = yaml.compose(text, Loader=yaml.SafeLoader)
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line = mark.line + 1 if mark is not None else None
        reason = str(getattr(exc, "problem", None) or exc)
        raise LessonFileError(Problem.of(shown, line, "LSN202", reason=reason)) from None
    return data, node


def validate(model: type[Model], data: Any, node: yaml.Node | None, shown: str) -> Model:
    """``data`` as ``model``; LessonFileError naming the field and its line."""
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        errors = exc.errors()
        first = next((e for e in errors if e["type"] == "value_error"), errors[0])
        loc = tuple(part for part in first["loc"] if isinstance(part, int | str))
        field = ".".join(str(part) for part in loc) or "(file)"
        reason = str(first["msg"]).removeprefix("Value error, ")
        line = line_of(node, loc)
        raise LessonFileError(
            Problem.of(shown, line, "LSN203", field=field, reason=reason)
        ) from None


def load_model(model: type[Model], path: Path, shown: str) -> Model:
    data, node = read_yaml(path, shown)
    if model is not Quiz and not isinstance(data, dict):
        raise LessonFileError(
            Problem.of(shown, 1, "LSN203", field="(file)", reason="not a mapping")
        )
    return validate(model, data, node, shown)


def load_hints(path: Path, shown: str) -> list[Texts]:
    """``hints.yaml``: a list of ``{language: text}``; a missing file is no hints."""
    if not path.is_file():
        return []
    data, node = read_yaml(path, shown)
    if data is None:
        return []
    if not isinstance(data, list):
        raise LessonFileError(
            Problem.of(shown, 1, "LSN203", field="(file)", reason="a list of hints")
        )
    hints: list[Texts] = []
    for index, item in enumerate(data):
        if not (
            isinstance(item, dict)
            and item
            and all(isinstance(v, str) and v.strip() for v in item.values())
        ):
            line = line_of(node, (index,))
            reason = "a hint is {language: text}, with a text in every language"
            raise LessonFileError(
                Problem.of(shown, line, "LSN203", field=str(index), reason=reason)
            )
        hints.append({str(key): value for key, value in item.items()})
    return hints
