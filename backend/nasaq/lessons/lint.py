"""The lesson lint: what a lesson folder must be before a learner sees it.

Rules (each problem names its file and, where it can, its line; codes LSN3xx):
- ``languages`` start with the unit's language and include English; every language has its
  ``<lang>.md`` whose first line is ``# <title>``, and every title, summary, hint and quiz text
  exists in every language of the lesson.
- Arabic and Persian texts are written in their right-to-left script: outside code, Arabic-script
  letters outnumber Latin ones (addresses and code may stay Latin).
- Links and figures (``[..](path)``, ``![..](figures/x.svg)``) name files of the lesson folder.
- The plant exists and its wiring matches its declared signals and directions (the runtime's
  own wiring check), its parameters and injectable faults exist.
- A hint never names an operand (address, timer, counter, or symbol of the lesson's symbol
  table) that neither the task section of the same language nor the ``start/`` program (which
  the learner has in front of them) names, and never contains a whole line of the solution.
  The task section is the ``## `` section whose heading says "task" in the language (see
  ``_TASK_HEADINGS``); without one, the whole text.
- Every step note of a check scenario is a mapping with every language of the lesson
  (``note: {en: "...", fa: "..."}``): the Check result shows it in the learner's language. A
  plain-text note counts as English only.
- The check files exist and load; ``open`` exists in ``start/``; ``start/`` and ``solution/``
  exist for a lesson with a program; quiz questions are complete; prerequisites are lessons.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from pathlib import Path

from nasaq.headless.addresses import AddressError
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lessons.load import Course, Lesson, load_course
from nasaq.lessons.model import (
    RTL_LANGUAGES,
    LessonFileError,
    Problem,
    Quiz,
    Texts,
    line_of,
    read_yaml,
)
from nasaq.plants.base import PlantError
from nasaq.plants.registry import plant_class
from nasaq.plants.runtime import wires_of
from nasaq.scenarios.model import Scenario, ScenarioError, load_scenario

_TASK_HEADINGS = {
    "en": ("task", "exercise", "what to do"),
    "ar": ("المهمة", "مهمة", "التمرين", "المطلوب"),
    "fa": ("تمرین", "وظیفه", "کار شما", "خواسته"),
    "vi": ("nhiệm vụ", "bài tập", "yêu cầu"),
}
_FENCE = re.compile(r"^```.*?^```", re.MULTILINE | re.DOTALL)
_INLINE_CODE = re.compile(r"`[^`\n]*`")
_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
_ARABIC = re.compile(r"[\u0600-\u06FF\u0750-\u077F\uFB50-\uFDFF\uFE70-\uFEFF]")
_LATIN = re.compile(r"[A-Za-z]")
_OPERAND = re.compile(
    r"(?<![\w.#])(?:"
    r"(?:DB\d+\.DBX|[IEQAM])\s?\d+\.[0-7]"  # bits
    r"|(?:P[IEQA]|[IEQAM]|DB\d+\.DB)[BWD]\s?\d+"  # bytes, words, doublewords
    r"|[TCZ]\s?\d+"  # timers and counters
    r")(?!\w|\.\d)"
)
_QUOTED = re.compile(r'"([^"\n]{1,40})"')
_GERMAN = {"E": "I", "A": "Q", "PE": "PI", "PA": "PQ", "Z": "C"}
_SOLUTION_KEYWORDS = re.compile(
    r"^(NETWORK|TITLE|BEGIN|END_\w+|RUNG|PARALLEL|BRANCH|VAR\w*|ORGANIZATION_BLOCK|FUNCTION\w*"
    r"|DATA_BLOCK|STRUCT|BE|BEU|\(|\)|//.*|\{.*)\b",
    re.IGNORECASE,
)


def normal_operand(text: str) -> str:
    """``E 0.1`` -> ``I0.1``, ``MW 10`` -> ``MW10``: one spelling per operand."""
    compact = text.replace(" ", "").upper()
    match = re.match(r"(PE|PA|E|A|Z)(?=[BWD]?\d)", compact)
    if match:
        compact = _GERMAN[match.group(1)] + compact[match.end() :]
    return compact


def operands(text: str, symbols: dict[str, str]) -> set[str]:
    """The operands ``text`` names, each also by its address when it is a known symbol."""
    found = {normal_operand(match.group(0)) for match in _OPERAND.finditer(text)}
    for match in _QUOTED.finditer(text):
        address = symbols.get(match.group(1).casefold())
        if address is not None:
            found.add(normal_operand(address))
    return found


_SPAN = re.compile(r"^(PI|PQ|I|Q|M|DB\d+\.DB)([XBWD]?)(\d+)(?:\.(\d))?$")
_BITS = {"": 1, "X": 1, "B": 8, "W": 16, "D": 32}


def _span(operand: str) -> tuple[str, int, int] | None:
    """(area, first bit, bits) of a memory operand, None for timers, counters, symbols."""
    match = _SPAN.match(operand)
    if match is None:
        return None
    area, size, byte, bit = match.groups()
    start = int(byte) * 8 + (int(bit) if bit is not None else 0)
    return area, start, _BITS[size]


def unnamed(used: set[str], named: set[str]) -> set[str]:
    """The operands of ``used`` that ``named`` does not name, neither itself nor as part of a
    wider operand (``IB0`` is part of a named ``IW0``: the task named that memory)."""
    spans = [span for span in map(_span, named) if span is not None]
    left: set[str] = set()
    for operand in used - named:
        span = _span(operand)
        if span is None or not any(
            area == span[0] and start <= span[1] and span[1] + span[2] <= start + bits
            for area, start, bits in spans
        ):
            left.add(operand)
    return left


def prose(markdown: str) -> str:
    """The text without fenced code and inline code."""
    return _INLINE_CODE.sub(" ", _FENCE.sub(" ", markdown))


def task_section(markdown: str, language: str) -> str:
    """The ``## `` section that states the task, or the whole text without one."""
    sections = re.split(r"^## ", markdown, flags=re.MULTILINE)
    words = _TASK_HEADINGS.get(language, ()) + _TASK_HEADINGS["en"]
    for section in sections[1:]:
        heading = section.split("\n", 1)[0].casefold()
        if any(word in heading for word in words):
            return section
    return markdown


def _solution_line(line: str) -> str | None:
    """A solution line worth hiding: code with an operand, normalised; else None."""
    text = line.split("//", 1)[0].strip()
    if not text or (_SOLUTION_KEYWORDS.match(text) and not _OPERAND.search(text)):
        return None
    if not _OPERAND.search(text) and '"' not in text:
        return None
    return _normal_code(text)


def _normal_code(text: str) -> str:
    collapsed = " ".join(text.replace("`", " ").split()).casefold()
    return re.sub(r"\b([a-z]{1,3})\s+(\d)", r"\1\2", collapsed)


class _Lint:
    def __init__(self, course: Course) -> None:
        self.course = course
        self.problems: list[Problem] = []
        self.ids = {lesson.id for lesson in course.lessons()}
        self.unit_language = {unit.meta.id: unit.meta.language for unit in course.units}

    def add(self, file: str, line: int | None, code: str, **params: object) -> None:
        self.problems.append(Problem.of(file, line, code, **params))

    def texts(self, shown: str, field: str, texts: Texts | None, languages: list[str]) -> None:
        for language in languages:
            if not texts or not str(texts.get(language, "")).strip():
                self.add(shown, None, "LSN304", field=field, language=language)

    def lesson(self, lesson: Lesson) -> None:
        meta, shown = lesson.meta, lesson.shown
        yaml_file = f"{shown}/lesson.yaml"
        languages = meta.languages
        unit_language = self.unit_language.get(meta.unit, "en")
        if languages[0] != unit_language or "en" not in languages:
            self.add(yaml_file, None, "LSN301", language=unit_language)
        self.texts(yaml_file, "title", meta.title, languages)
        self.texts(yaml_file, "summary", meta.summary, languages)
        for prerequisite in meta.prerequisites:
            if prerequisite not in self.ids:
                self.add(yaml_file, None, "LSN315", id=prerequisite)
        markdown = self.markdown(lesson)
        symbols = self.symbols(lesson)
        self.hints(lesson, markdown, symbols)
        self.plant(lesson)
        self.folders(lesson)
        self.checks(lesson)
        if lesson.quiz is not None:
            self.quiz(lesson, lesson.quiz)

    def markdown(self, lesson: Lesson) -> dict[str, str]:
        found: dict[str, str] = {}
        for language in lesson.meta.languages:
            name = f"{language}.md"
            file = f"{lesson.shown}/{name}"
            text = lesson.text(language)
            if text is None:
                self.add(file, None, "LSN302", language=language, name=name)
                continue
            found[language] = text
            if not text.startswith("# ") or not text.split("\n", 1)[0][2:].strip():
                self.add(file, 1, "LSN303")
            if language in RTL_LANGUAGES:
                words = prose(text)
                if len(_ARABIC.findall(words)) <= len(_LATIN.findall(words)):
                    self.add(file, None, "LSN305", language=language)
            for number, line in enumerate(text.split("\n"), start=1):
                for match in _LINK.finditer(line):
                    self.link(lesson, file, number, match.group(1))
        return found

    def link(self, lesson: Lesson, file: str, line: int, target: str) -> None:
        if re.match(r"^[a-z]+:", target) or target.startswith("#"):
            return  # a web address or an anchor in the page
        path = (lesson.folder / target.split("#", 1)[0]).resolve()
        inside = lesson.folder.resolve() in path.parents
        if not inside or not path.is_file():
            self.add(file, line, "LSN306", target=target)

    def symbols(self, lesson: Lesson) -> dict[str, str]:
        """The lesson's symbols (casefolded name -> address) from start/ and solution/."""
        files: list[SourceFile] = []
        for part in ("start", "solution"):
            for name, text in lesson.files(part) or []:
                if name.lower().endswith((".sdf", ".asc", ".seq", ".csv")):
                    files.append(SourceFile(f"{part}/{name}", text))
        if not files:
            return {}
        program = compile_sources(files).program
        return {name.casefold(): address for name, address in program.symbols.items()}

    def hints(self, lesson: Lesson, markdown: dict[str, str], symbols: dict[str, str]) -> None:
        file = f"{lesson.shown}/hints.yaml"
        solution = {
            line
            for _name, text in lesson.files("solution") or []
            for raw in text.split("\n")
            if (line := _solution_line(raw)) is not None
        }
        # What the learner is given to start from names nothing new (a "change this program"
        # lesson's timers are in front of them already).
        given = {
            operand
            for _name, text in lesson.files("start") or []
            for operand in operands(text, symbols)
        }
        node = None
        if lesson.hints:
            try:
                _data, node = read_yaml(lesson.folder / "hints.yaml", file)
            except LessonFileError:
                node = None  # read once already when the course was loaded
        for number, hint in enumerate(lesson.hints, start=1):
            self.texts(file, f"hint {number}", hint, lesson.meta.languages)
            for language, text in hint.items():
                if language not in markdown:
                    continue
                where = line_of(node, (number - 1, language))
                named = given | operands(task_section(markdown[language], language), symbols)
                for operand in sorted(unnamed(operands(text, symbols), named)):
                    self.add(file, where, "LSN308", hint=number, language=language, operand=operand)
                code = _normal_code(text)
                for line in sorted(solution):
                    if re.search(rf"(?<!\w){re.escape(line)}(?!\w)", code):
                        self.add(file, where, "LSN309", hint=number, language=language, text=line)

    def plant(self, lesson: Lesson) -> None:
        config = lesson.meta.plant
        if config is None:
            return
        file = f"{lesson.shown}/lesson.yaml"
        try:
            kind = plant_class(config.kind)
            wires_of(kind, config.wiring)
            plant = kind(config.params)
            for code in config.faults:
                plant.inject(code)
        except (PlantError, AddressError) as exc:
            self.add(file, None, "LSN307", reason=str(exc))

    def folders(self, lesson: Lesson) -> None:
        meta = lesson.meta
        if meta.works_in == "none":
            return
        for part in ("start", "solution"):
            if not (lesson.folder / part).is_dir():
                self.add(f"{lesson.shown}/{part}", None, "LSN312", name=part)
        if meta.open and not (lesson.folder / "start" / meta.open).is_file():
            self.add(f"{lesson.shown}/lesson.yaml", None, "LSN311", name=meta.open)

    def checks(self, lesson: Lesson) -> None:
        file = f"{lesson.shown}/lesson.yaml"
        for check in lesson.meta.checks:
            if check.scenario is not None:
                path = lesson.folder / check.scenario
                if not path.is_file():
                    self.add(file, None, "LSN310", name=check.scenario)
                    continue
                try:
                    scenario = load_scenario(path)
                except ScenarioError as exc:
                    reason = str(exc).replace(str(path), check.scenario)
                    self.add(
                        f"{lesson.shown}/{check.scenario}",
                        None,
                        "LSN313",
                        name=check.scenario,
                        reason=reason,
                    )
                    continue
                self.notes(lesson, check.scenario, scenario)
            elif check.quiz is not None:
                if not (lesson.folder / check.quiz).is_file():
                    self.add(file, None, "LSN310", name=check.quiz)
            elif check.convert is not None:
                name = check.convert.file
                if not (lesson.folder / "solution" / name).is_file():
                    reason = f"solution/ has no file '{name}'"
                    self.add(file, None, "LSN313", name=check.name, reason=reason)

    def notes(self, lesson: Lesson, name: str, scenario: Scenario) -> None:
        """Every note in every language of the lesson (a plain-text note is English only)."""
        file = f"{lesson.shown}/{name}"
        node = None
        for index, step in enumerate(scenario.steps):
            if step.note is None:
                continue
            texts = {"en": step.note} if isinstance(step.note, str) else step.note
            missing = [x for x in lesson.meta.languages if not texts.get(x, "").strip()]
            if missing and node is None:
                try:
                    _data, node = read_yaml(lesson.folder / name, file)
                except LessonFileError:
                    node = None  # it loaded as a scenario a moment ago
            for language in missing:
                line = line_of(node, ("steps", index, "note"))
                field = f"step {index + 1} note"
                self.add(file, line, "LSN304", field=field, language=language)

    def quiz(self, lesson: Lesson, quiz: Quiz) -> None:
        name = next((c.quiz for c in lesson.meta.checks if c.quiz), "quiz.yaml")
        file = f"{lesson.shown}/{name}"
        languages = lesson.meta.languages
        for question in quiz.questions:
            self.texts(file, f"{question.id}.prompt", question.prompt, languages)
            if question.explain is not None:
                self.texts(file, f"{question.id}.explain", question.explain, languages)
            for option in question.options:
                self.texts(file, f"{question.id}.{option.id}", option.text, languages)
            program = question.program
            if program and not (lesson.folder / program).is_file():
                reason = f"the program {program} does not exist"
                self.add(file, None, "LSN314", question=question.id, reason=reason)


def lint_course(
    course: Course, only: Iterable[str] | None = None, reading: bool = True
) -> list[Problem]:
    """Every problem of the course (or of the lessons ``only`` names); with ``reading``, the
    problems of reading the folders (malformed files) first."""
    lint = _Lint(course)
    wanted = set(only) if only is not None else None
    if reading:
        lint.problems.extend(course.problems)
    for lesson in course.lessons():
        if wanted is None or lesson.id in wanted:
            lint.lesson(lesson)
    return lint.problems


def lint_root(root: Path) -> list[Problem]:
    return lint_course(load_course(root))
