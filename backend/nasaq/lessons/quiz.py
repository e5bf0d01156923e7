"""Quiz answers checked on the server (the browser never gets ``answer``).

- ``choice``: the option id; ``multi``: the set of option ids.
- ``number``: within the tolerance; the learner may type Arabic-Indic or Persian digits and a
  decimal comma (``۲٫۵``, ``2,5``), as the keyboards of the course's languages give them.
- ``text``: one of the accepted spellings, ignoring letter case, spaces and underscores.
- ``predict``: ``{address: value}`` for every asked address; the truth is what the program does
  after ``set`` and ``scans`` on a fresh CPU (warm restart first), never a typed-in answer.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from nasaq.cpu import Cpu
from nasaq.headless.addresses import (
    AddressError,
    address_text,
    encode_value,
    parse_address,
    parse_number,
    signed,
)
from nasaq.headless.sources import diagnostic_line
from nasaq.ir import Area, Direct, Width
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lessons.load import Lesson, project_files
from nasaq.lessons.model import NumberAnswer, Question, Quiz, Texts

_DIGITS = str.maketrans("٠١٢٣٤٥٦٧٨٩۰۱۲۳۴۵۶۷۸۹٫،", "01234567890123456789.,")


class QuizError(Exception):
    """A predict question whose program cannot run (a broken lesson, not a wrong answer)."""


@dataclass(frozen=True, slots=True)
class Verdict:
    id: str
    correct: bool
    answered: bool
    expected: str  # the truth as text (shown only once the lesson is passed or given up)
    explain: Texts | None


def _number(value: Any) -> float | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float):
        return float(value)
    if not isinstance(value, str):
        return None
    text = value.translate(_DIGITS).strip().replace(" ", "").replace(",", ".")
    try:
        return float(parse_number(text))
    except AddressError:
        return None


def _text(value: Any) -> str:
    return "".join(str(value).split()).replace("_", "").casefold()


def predict_truth(lesson: Lesson, question: Question) -> dict[str, int]:
    """The values of the asked addresses after the question's scans (unsigned patterns)."""
    assert question.program is not None
    path = lesson.folder / question.program
    folder = project_files(path.parent) or []
    files = [SourceFile(name, text) for name, text in folder if name == path.name]
    files += [
        SourceFile(name, text)
        for name, text in folder
        if name.lower().endswith((".sdf", ".asc", ".seq", ".csv"))
    ]
    if not files:
        raise QuizError(f"{question.program}: no such program")
    compiled = compile_sources(files)
    if not compiled.ok:
        first = next(d for d in compiled.diagnostics if d.severity == "error")
        raise QuizError(diagnostic_line(first))
    cpu = Cpu(compiled.program)
    cpu.start()
    try:
        for key, value in question.set_.items():
            address = parse_address(str(key))
            if not isinstance(address, Direct):
                raise QuizError(f"{key}: only addresses can be set")
            number = parse_number(value) if isinstance(value, str) else value
            pattern = encode_value(address, number)
            if address.area is Area.I:
                cpu.set_input(address, pattern)
            else:
                cpu.write(address, pattern)
        cpu.run(question.scans)
        truth: dict[str, int] = {}
        for key in question.ask:
            address = parse_address(str(key))
            if not isinstance(address, Direct):
                raise QuizError(f"{key}: ask for addresses")
            truth[str(key)] = cpu.read(address)
    except AddressError as exc:
        raise QuizError(str(exc)) from None
    return truth


def _shown_value(address: Direct, pattern: int) -> str:
    return str(pattern) if address.width is Width.BIT else str(signed(pattern, address.width))


def _predict(lesson: Lesson, question: Question, given: Any) -> tuple[bool, str]:
    truth = predict_truth(lesson, question)
    shown = ", ".join(
        f"{key} = {_shown_value(_direct(key), value)}" for key, value in truth.items()
    )
    if not isinstance(given, dict):
        return False, shown
    lookup = {"".join(str(k).split()).upper(): v for k, v in given.items()}
    for key, value in truth.items():
        answer = lookup.get("".join(key.split()).upper())
        number = _number(answer)
        if number is None or number != int(number):
            return False, shown
        try:
            if encode_value(_direct(key), int(number)) != value:
                return False, shown
        except AddressError:
            return False, shown
    return True, shown


def _direct(key: str) -> Direct:
    address = parse_address(key)
    assert isinstance(address, Direct)
    return address


def grade_question(lesson: Lesson, question: Question, given: Any) -> Verdict:
    answer = question.answer
    answered = given is not None and given != "" and given != []
    correct = False
    if question.kind == "choice":
        correct = given == answer
        expected = str(answer)
    elif question.kind == "multi":
        correct = isinstance(given, list) and {str(x) for x in given} == set(answer)
        expected = ", ".join(sorted(answer))
    elif question.kind == "number":
        assert isinstance(answer, NumberAnswer)
        number = _number(given)
        correct = number is not None and abs(number - answer.value) <= answer.tolerance + 1e-12
        expected = f"{answer.value:g}"
    elif question.kind == "text":
        correct = answered and _text(given) in {_text(item) for item in answer}
        expected = str(answer[0])
    else:
        correct, expected = _predict(lesson, question, given)
    return Verdict(question.id, bool(correct and answered), answered, expected, question.explain)


def grade(lesson: Lesson, quiz: Quiz, answers: dict[str, Any]) -> list[Verdict]:
    return [grade_question(lesson, q, answers.get(q.id)) for q in quiz.questions]


def right_answers(lesson: Lesson, quiz: Quiz) -> dict[str, Any]:
    """The answers that pass (what ``nasaq lessons check`` gives for the solution)."""
    found: dict[str, Any] = {}
    for question in quiz.questions:
        if question.kind == "predict":
            found[question.id] = {
                key: signed(value, _direct(key).width)
                if _direct(key).width is not Width.BIT
                else value
                for key, value in predict_truth(lesson, question).items()
            }
        elif question.kind == "number":
            assert isinstance(question.answer, NumberAnswer)
            found[question.id] = question.answer.value
        elif question.kind == "text":
            found[question.id] = question.answer[0]
        else:
            found[question.id] = question.answer
    return found


__all__ = ["QuizError", "Verdict", "address_text", "grade", "predict_truth", "right_answers"]
