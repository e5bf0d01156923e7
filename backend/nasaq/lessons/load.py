"""Finding the course on disk: units (``<root>/<unit>/unit.yaml``) and their lessons
(``<root>/<unit>/<lesson>/lesson.yaml``), with their hints and quiz.

The root is ``settings.lessons_dir`` (``examples/lessons`` of a clone; ``NASAQ_LESSONS_DIR`` in
an installed server, e.g. the Docker image). A folder whose files cannot be read is left out of
the course and reported in ``problems`` with its file and line: one broken lesson never hides
the others. The course is read again only when a file under the root changed.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from threading import Lock

from nasaq.lessons.model import (
    LessonFileError,
    LessonMeta,
    Problem,
    Quiz,
    Texts,
    UnitMeta,
    load_hints,
    load_model,
)
from nasaq.workbench.names import is_valid_name

PLANT_SUFFIX = ".plant"


@dataclass(slots=True)
class Lesson:
    meta: LessonMeta
    folder: Path
    shown: str  # the folder relative to the course root: "vi4/vi4-07"
    hints: list[Texts] = field(default_factory=list)
    quiz: Quiz | None = None

    @property
    def id(self) -> str:
        return self.meta.id

    def text(self, language: str) -> str | None:
        path = self.folder / f"{language}.md"
        try:
            return path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            return None

    def figures(self) -> list[str]:
        folder = self.folder / "figures"
        if not folder.is_dir():
            return []
        return sorted(path.name for path in folder.iterdir() if path.suffix.lower() == ".svg")

    def files(self, part: str) -> list[tuple[str, str]] | None:
        """The project files of ``start``, ``solution`` or ``wrong`` as (name, text); None
        when the folder does not exist."""
        return project_files(self.folder / part)


@dataclass(slots=True)
class Unit:
    meta: UnitMeta
    folder: Path
    lessons: list[Lesson] = field(default_factory=list)


@dataclass(slots=True)
class Course:
    root: Path
    units: list[Unit] = field(default_factory=list)
    problems: list[Problem] = field(default_factory=list)

    def lessons(self) -> list[Lesson]:
        return [lesson for unit in self.units for lesson in unit.lessons]

    def lesson(self, lesson_id: str) -> Lesson | None:
        return next((item for item in self.lessons() if item.id == lesson_id), None)


def project_files(folder: Path) -> list[tuple[str, str]] | None:
    """Files of a project folder a project may hold (sources, symbols, properties, plants)."""
    if not folder.is_dir():
        return None
    found: list[tuple[str, str]] = []
    for path in sorted(folder.iterdir()):
        if path.is_file() and (is_valid_name(path.name) or path.suffix == PLANT_SUFFIX):
            found.append((path.name, path.read_text(encoding="utf-8")))
    return found


def _relative(path: Path, root: Path) -> str:
    try:
        return path.relative_to(root).as_posix()
    except ValueError:
        return path.as_posix()


def load_lesson(folder: Path, root: Path) -> Lesson:
    """One lesson folder; LessonFileError for the first file that cannot be used."""
    shown = _relative(folder, root)
    meta = load_model(LessonMeta, folder / "lesson.yaml", f"{shown}/lesson.yaml")
    if meta.id != folder.name:
        problem = Problem.of(f"{shown}/lesson.yaml", 1, "LSN204", id=meta.id, folder=folder.name)
        raise LessonFileError(problem)
    hints = load_hints(folder / "hints.yaml", f"{shown}/hints.yaml")
    quiz: Quiz | None = None
    for check in meta.checks:
        if check.quiz is not None and (folder / check.quiz).is_file():
            quiz = load_model(Quiz, folder / check.quiz, f"{shown}/{check.quiz}")
    return Lesson(meta, folder, shown, hints, quiz)


def _unit(folder: Path, root: Path, problems: list[Problem]) -> Unit | None:
    shown = _relative(folder, root)
    try:
        meta = load_model(UnitMeta, folder / "unit.yaml", f"{shown}/unit.yaml")
    except LessonFileError as exc:
        problems.append(exc.problem)
        return None
    if meta.id != folder.name:
        problems.append(
            Problem.of(f"{shown}/unit.yaml", 1, "LSN204", id=meta.id, folder=folder.name)
        )
        return None
    unit = Unit(meta, folder)
    for child in sorted(folder.iterdir()):
        if not child.is_dir() or not (child / "lesson.yaml").is_file():
            continue
        try:
            lesson = load_lesson(child, root)
        except LessonFileError as exc:
            problems.append(exc.problem)
            continue
        if lesson.meta.unit != meta.id:
            problems.append(
                Problem.of(
                    f"{lesson.shown}/lesson.yaml",
                    1,
                    "LSN205",
                    unit=lesson.meta.unit,
                    folder=meta.id,
                )
            )
            continue
        unit.lessons.append(lesson)
    unit.lessons.sort(key=lambda item: (item.meta.order, item.id))
    return unit


def read_course(root: Path) -> Course:
    """The whole course below ``root`` (an empty course when the folder does not exist)."""
    course = Course(root)
    if not root.is_dir():
        return course
    for folder in sorted(root.iterdir()):
        if folder.is_dir() and (folder / "unit.yaml").is_file():
            unit = _unit(folder, root, course.problems)
            if unit is not None:
                course.units.append(unit)
    course.units.sort(key=lambda unit: (unit.meta.order, unit.meta.id))
    seen: dict[str, str] = {}
    for lesson in course.lessons():
        if lesson.id in seen:
            course.problems.append(
                Problem.of(
                    f"{lesson.shown}/lesson.yaml", 1, "LSN206", id=lesson.id, other=seen[lesson.id]
                )
            )
        seen.setdefault(lesson.id, lesson.shown)
    return course


def _signature(root: Path) -> tuple[tuple[str, int, int], ...]:
    """Every file's path, size and time of change: the course changed when this did."""
    found: list[tuple[str, int, int]] = []
    for folder, _dirs, names in os.walk(root):
        for name in names:
            stat = os.stat(os.path.join(folder, name))
            found.append((os.path.join(folder, name), stat.st_size, stat.st_mtime_ns))
    return tuple(sorted(found))


_cache: dict[Path, tuple[tuple[tuple[str, int, int], ...], Course]] = {}
_lock = Lock()


def load_course(root: Path) -> Course:
    """``read_course``, read again only when a file under ``root`` changed."""
    signature = _signature(root) if root.is_dir() else ()
    with _lock:
        cached = _cache.get(root)
        if cached is not None and cached[0] == signature:
            return cached[1]
    course = read_course(root)
    with _lock:
        _cache[root] = (signature, course)
    return course
