"""``/api/lessons``: the course, a lesson (never its answers or solution), its figures, the
learner's project for it, Check, hints, giving up and the solution once earned.

A malformed lesson folder is listed in ``problems`` and left out; the rest of the course stays
usable. Checks compile and run a CPU (and a plant) for up to a few hundred milliseconds, so they
run in a thread, never on the event loop that serves the sockets.
"""

from __future__ import annotations

import asyncio
from typing import Any, Literal

from fastapi import APIRouter, Query, Request, Response, status
from pydantic import BaseModel, Field
from sqlalchemy.orm import Session, sessionmaker

from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.lessons import progress as progress_store
from nasaq.lessons.check import CheckOut, LessonCheck, QuizOut, Status, check_lesson
from nasaq.lessons.load import Course, Lesson, load_course
from nasaq.lessons.model import Problem, Texts
from nasaq.lessons.progress import Progress
from nasaq.plants.runtime import PlantConfig
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction
from nasaq.storage.models import LessonProgress

router = APIRouter(prefix="/lessons", tags=["lessons"])

Language = Literal["en", "ar", "fa", "vi"]

_ERRORS: dict[int | str, dict[str, Any]] = {
    404: {"model": ApiErrorBody, "description": "No such lesson (LSN101), figure or project"},
    409: {"model": ApiErrorBody, "description": "The project is not this lesson's (LSN103)"},
}


class LessonSummary(BaseModel):
    id: str
    order: int
    title: Texts
    summary: Texts
    languages: list[str]
    works_in: str
    form: str
    plant: str | None = Field(description="The plant's kind, or null")
    prerequisites: list[str]
    progress: Progress | None


class UnitOut(BaseModel):
    id: str
    order: int
    language: str
    title: Texts
    summary: Texts
    lessons: list[LessonSummary]


class CourseOut(BaseModel):
    units: list[UnitOut]
    problems: list[Problem]


class QuestionOut(BaseModel):
    """A quiz question as the learner sees it: no answer."""

    id: str
    kind: str
    prompt: Texts
    options: list[dict[str, Any]]
    set: dict[str, Any] = Field(default_factory=dict)
    scans: int | None = None
    ask: list[str] = Field(default_factory=list)
    program: str | None = Field(
        default=None, description="A predict question's program, which the learner reads"
    )


class CheckInfo(BaseModel):
    kind: str
    name: str


class LessonDetail(BaseModel):
    id: str
    unit: str
    order: int
    title: Texts
    summary: Texts
    languages: list[str]
    works_in: str
    open: str | None
    form: str
    time_limit_min: int | None
    text: dict[str, str]
    figures: list[str]
    hints_total: int
    hints: list[Texts] = Field(description="The hints revealed so far (see POST .../hint)")
    quiz: list[QuestionOut]
    plant: PlantConfig | None
    checks: list[CheckInfo]
    prerequisites: list[str]
    progress: Progress | None


class OpenRequest(BaseModel):
    reset: bool = False


class OpenOut(BaseModel):
    project_id: int
    project_name: str
    open: str | None
    progress: Progress


class CheckRequest(BaseModel):
    project_id: int
    answers: dict[str, Any] = Field(default_factory=dict)
    lang: Language = Field(
        default="en", description="The interface language: the steps' notes come in it"
    )


class CheckResult(BaseModel):
    status: Status
    checks: list[CheckOut]
    quiz: list[QuizOut]
    progress: Progress


class ProjectRequest(BaseModel):
    project_id: int


class HintsOut(BaseModel):
    index: int = Field(description="How many hints are revealed now")
    total: int
    hints: list[Texts] = Field(description="Every hint revealed so far, first first")


class SolutionFile(BaseModel):
    name: str
    text: str


class SolutionOut(BaseModel):
    files: list[SolutionFile]


def _course(request: Request) -> Course:
    return load_course(request.app.state.settings.lessons_dir)


async def _lesson(request: Request, lesson_id: str) -> Lesson:
    course = await asyncio.to_thread(_course, request)
    lesson = course.lesson(lesson_id)
    if lesson is None:
        raise ApiError("LSN101", 404, ["path", "lesson_id"], id=lesson_id)
    return lesson


def _factory(request: Request) -> sessionmaker[Session]:
    factory: sessionmaker[Session] = request.app.state.sessions
    return factory


def _progress_of(factory: sessionmaker[Session], lesson_id: str) -> Progress | None:
    with transaction(factory) as session:
        row = progress_store.row_of(session, lesson_id)
        return Progress.of(row) if row is not None else None


def _linked(session: Session, lesson: Lesson, project_id: int) -> LessonProgress:
    if project_store.get_project(session, project_id) is None:
        raise ApiError("API104", 404, ["body", "project_id"], id=project_id)
    row = progress_store.linked(session, lesson.id, project_id)
    if row is None:
        raise ApiError("LSN103", 409, ["body", "project_id"], project_id=project_id, id=lesson.id)
    return row


@router.get("", response_model=CourseOut, summary="The course by unit, with progress")
async def list_lessons(request: Request, lang: Language = "en") -> CourseOut:
    """``lang`` is the interface language; every title comes in all the lesson's languages."""
    course = await asyncio.to_thread(_course, request)

    def rows() -> dict[str, Progress]:
        with transaction(_factory(request)) as session:
            return {key: Progress.of(row) for key, row in progress_store.all_rows(session).items()}

    progress = await asyncio.to_thread(rows)
    units = [
        UnitOut(
            id=unit.meta.id,
            order=unit.meta.order,
            language=unit.meta.language,
            title=unit.meta.title,
            summary=unit.meta.summary,
            lessons=[
                LessonSummary(
                    id=lesson.id,
                    order=lesson.meta.order,
                    title=lesson.meta.title,
                    summary=lesson.meta.summary,
                    languages=lesson.meta.languages,
                    works_in=lesson.meta.works_in,
                    form=lesson.meta.form,
                    plant=lesson.meta.plant.kind if lesson.meta.plant else None,
                    prerequisites=lesson.meta.prerequisites,
                    progress=progress.get(lesson.id),
                )
                for lesson in unit.lessons
            ],
        )
        for unit in course.units
    ]
    return CourseOut(units=units, problems=course.problems)


def _program_text(lesson: Lesson, name: str | None) -> str | None:
    """The program a predict question runs: the learner predicts from it, so it is shown (it is
    given with the question, never a solution)."""
    if name is None:
        return None
    try:
        return (lesson.folder / name).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None  # the lint reports a missing program; the pane shows the prompt alone


def _detail(lesson: Lesson, progress: Progress | None) -> LessonDetail:
    meta = lesson.meta
    texts = {language: lesson.text(language) for language in meta.languages}
    questions = [
        QuestionOut(
            id=question.id,
            kind=question.kind,
            prompt=question.prompt,
            options=[{"id": option.id, "text": option.text} for option in question.options],
            set=question.set_,
            scans=question.scans if question.kind == "predict" else None,
            ask=question.ask,
            program=_program_text(lesson, question.program) if question.kind == "predict" else None,
        )
        for question in (lesson.quiz.questions if lesson.quiz else [])
    ]
    return LessonDetail(
        id=meta.id,
        unit=meta.unit,
        order=meta.order,
        title=meta.title,
        summary=meta.summary,
        languages=meta.languages,
        works_in=meta.works_in,
        open=meta.open,
        form=meta.form,
        time_limit_min=meta.time_limit_min,
        text={language: text for language, text in texts.items() if text is not None},
        figures=lesson.figures(),
        hints_total=len(lesson.hints),
        hints=lesson.hints[: progress.hints_revealed] if progress is not None else [],
        quiz=questions,
        plant=meta.plant,
        checks=[CheckInfo(kind=check.kind, name=check.name) for check in meta.checks],
        prerequisites=meta.prerequisites,
        progress=progress,
    )


@router.get(
    "/{lesson_id}",
    response_model=LessonDetail,
    responses=_ERRORS,
    summary="A lesson: texts, figures, quiz questions (no answers), plant, checks, progress",
)
async def get_lesson(lesson_id: str, request: Request) -> LessonDetail:
    lesson = await _lesson(request, lesson_id)
    progress = await asyncio.to_thread(_progress_of, _factory(request), lesson.id)
    return await asyncio.to_thread(_detail, lesson, progress)


@router.get(
    "/{lesson_id}/figures/{name}",
    responses={**_ERRORS, 200: {"content": {"image/svg+xml": {}}}},
    summary="A figure of the lesson (SVG)",
)
async def get_figure(lesson_id: str, name: str, request: Request) -> Response:
    lesson = await _lesson(request, lesson_id)
    if name not in lesson.figures():  # only the listed files: no path ever leaves the folder
        raise ApiError("LSN104", 404, ["path", "name"], id=lesson_id, name=name)
    body = await asyncio.to_thread((lesson.folder / "figures" / name).read_bytes)
    return Response(body, media_type="image/svg+xml")


@router.post(
    "/{lesson_id}/open",
    response_model=OpenOut,
    responses=_ERRORS,
    summary="The learner's project for the lesson (made from start/ the first time; reset)",
)
async def open_lesson(
    lesson_id: str, request: Request, response: Response, body: OpenRequest | None = None
) -> OpenOut:
    lesson = await _lesson(request, lesson_id)
    reset = body.reset if body is not None else False
    if lesson.meta.works_in != "none" and lesson.files("start") is None:
        raise ApiError("LSN105", 422, id=lesson.id, reason="it has no start/ folder")

    def run() -> tuple[OpenOut, bool]:
        with transaction(_factory(request)) as session:
            before = progress_store.row_of(session, lesson.id)
            known = before is not None and project_store.get_project(session, before.project_id)
            project, row = progress_store.open_project(session, lesson, reset)
            out = OpenOut(
                project_id=project.id,
                project_name=project.name,
                open=lesson.meta.open,
                progress=Progress.of(row),
            )
            return out, not known

    out, created = await asyncio.to_thread(run)
    if created:
        response.status_code = status.HTTP_201_CREATED
    return out


@router.post(
    "/{lesson_id}/check",
    response_model=CheckResult,
    responses=_ERRORS,
    summary="Run the lesson's checks on the project's current files (and the quiz answers)",
)
async def check(lesson_id: str, body: CheckRequest, request: Request) -> CheckResult:
    lesson = await _lesson(request, lesson_id)
    factory = _factory(request)

    def load() -> tuple[list[tuple[str, str]], bool]:
        with transaction(factory) as session:
            row = _linked(session, lesson, body.project_id)
            files = list(progress_store.project_sources(session, body.project_id))
            return files, progress_store.may_see_solution(row)

    files, earned = await asyncio.to_thread(load)
    found: LessonCheck = await asyncio.to_thread(
        check_lesson, lesson, files, body.answers, True, body.lang
    )

    def record() -> Progress:
        with transaction(factory) as session:
            row = _linked(session, lesson, body.project_id)
            if found.status in ("passed", "failed"):
                progress_store.record_check(row, found.status == "passed")
            elif found.status == "compile_error":
                progress_store.record_check(row, False)
            session.flush()
            return Progress.of(row)

    progress = await asyncio.to_thread(record)
    if not (earned or found.status == "passed"):  # right answers only once earned
        for verdict in found.quiz:
            verdict.expected_shown = None
    return CheckResult(status=found.status, checks=found.checks, quiz=found.quiz, progress=progress)


@router.post(
    "/{lesson_id}/hint",
    response_model=HintsOut,
    responses=_ERRORS,
    summary="Reveal the next hint; answers every hint revealed so far",
)
async def hint(lesson_id: str, body: ProjectRequest, request: Request) -> HintsOut:
    lesson = await _lesson(request, lesson_id)

    def run() -> int:
        with transaction(_factory(request)) as session:
            row = _linked(session, lesson, body.project_id)
            return progress_store.reveal_hint(row, len(lesson.hints))

    shown = await asyncio.to_thread(run)
    return HintsOut(index=shown, total=len(lesson.hints), hints=lesson.hints[:shown])


@router.post(
    "/{lesson_id}/give-up",
    response_model=Progress,
    responses=_ERRORS,
    summary="Give up: the solution may be shown from now on",
)
async def give_up(lesson_id: str, body: ProjectRequest, request: Request) -> Progress:
    lesson = await _lesson(request, lesson_id)

    def run() -> Progress:
        with transaction(_factory(request)) as session:
            row = _linked(session, lesson, body.project_id)
            progress_store.give_up(row)
            session.flush()
            return Progress.of(row)

    return await asyncio.to_thread(run)


@router.get(
    "/{lesson_id}/solution",
    response_model=SolutionOut,
    responses={
        **_ERRORS,
        403: {"model": ApiErrorBody, "description": "Not passed nor given up (LSN102)"},
    },
    summary="The reference solution, once the lesson is passed or given up",
)
async def solution(lesson_id: str, request: Request, project_id: int = Query(...)) -> SolutionOut:
    lesson = await _lesson(request, lesson_id)

    def allowed() -> bool:
        with transaction(_factory(request)) as session:
            return progress_store.may_see_solution(_linked(session, lesson, project_id))

    if not await asyncio.to_thread(allowed):
        raise ApiError("LSN102", 403, ["query", "project_id"], id=lesson.id)
    files = await asyncio.to_thread(lesson.files, "solution")
    return SolutionOut(files=[SolutionFile(name=name, text=text) for name, text in files or []])
