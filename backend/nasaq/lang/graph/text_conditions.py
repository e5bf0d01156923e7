"""The quick reading of a plain condition body (``CONDITION``, ``INTERLOCK``, ``SUPERVISION``).

Almost every condition a student writes is contacts, parallel branches and comparator boxes
with plain operands: ``Contact(I 0.1) ContactNC("Stop") Box(CMP>D, IN1 := S3.T, IN2 := T#5S)``.
``plain_condition`` reads such a body straight from the text and numbers its elements
``e1, e2 ...`` as it builds them, giving exactly what the LAD reader and
``nasaq.lang.lad.text_ids.number_series`` give for it, several times faster. Whatever it is not
sure about (a comment, an ``@id``, a quoted text over a line, parentheses in an operand, another
element, a mistake to report) makes it give up (None) and the caller reads the body the general
way from the same place, so the quick way never changes a result or a diagnostic.
"""

from __future__ import annotations

import re

from nasaq.lang.graph.text_words import HOST_WORDS
from nasaq.lang.lad.model import Box, Contact, Element, Parallel, Series
from nasaq.lang.lad.text_parse import ELEMENTS, FINALS, STRUCTURE

_WORD = re.compile(r"\s*([A-Za-z_]\w*)")
# An operand as ``Scanner.operand`` reads it when nothing in it needs a closer look: no
# parentheses, brackets, comments, ``:=``/``=>``, and quotes closed on their line. It may stop
# at a line's end only before its ``,`` or ``)``.
_PLAIN = r"(?:(?!:=|=>)[^\s,()\"'\[\]/@]|\"[^\"\n]*\"|'[^'\n]*')+"
_OPERAND = re.compile(rf"\s*({_PLAIN}(?:[ \t]+{_PLAIN})*)[ \t]*")
# A whole contact with a plain operand and no @id after it, in one step (the usual element).
_CONTACT = re.compile(
    rf"\s*(?:(CONTACTNC)|CONTACT)\s*\(\s*({_PLAIN}(?:[ \t]+{_PLAIN})*)[ \t]*\s*\)(?!\s*@)",
    re.IGNORECASE,  # only C, O, N, T, A: no other letter folds to these
)
_MARK = re.compile(r"\s*(:=|=>|[(),])")
_BLANK_WORD = re.compile(r"[ \t]([A-Za-z_]\w*)")
# The words that end an operand after a blank (``LadReader``'s ``_SYNC`` and the Graph words).
_OPERAND_STOPS = STRUCTURE | ELEMENTS | frozenset(FINALS) | HOST_WORDS


class _NotPlainError(Exception):
    """The body is not plain: the general reading takes over."""


def plain_condition(text: str, pos: int, end: str) -> tuple[Series, int] | None:
    """The condition body at ``pos`` up to and including its ``end`` word (``END_CONDITION``
    ...): its numbered series and where reading goes on; None when the body is not plain."""
    reader = _Reader(text)
    try:
        elements, pos = reader.series(pos, end)
    except _NotPlainError:
        return None
    return Series(elements=elements), pos


class _Reader:
    def __init__(self, text: str) -> None:
        self.text = text
        self.count = 0  # elements numbered so far (reading order, as text_ids numbers them)

    def number(self) -> str:
        self.count += 1
        return f"e{self.count}"

    def word(self, pos: int) -> tuple[str, int]:
        found = _WORD.match(self.text, pos)
        if found is None:
            raise _NotPlainError
        return found.group(1).upper(), found.end()

    def mark(self, pos: int) -> tuple[str, int]:
        found = _MARK.match(self.text, pos)
        if found is None:
            raise _NotPlainError
        return found.group(1), found.end()

    def operand(self, pos: int) -> tuple[str, int]:
        found = _OPERAND.match(self.text, pos)
        if found is None:
            raise _NotPlainError
        value = found.group(1)
        for word in _BLANK_WORD.findall(value):
            if word.upper() in _OPERAND_STOPS:  # ends the operand: a mistake to report
                raise _NotPlainError
        return value, found.end()

    def series(self, pos: int, end: str) -> tuple[list[Element], int]:
        """Elements up to the word ``end``, which is consumed."""
        elements: list[Element] = []
        text = self.text
        while True:
            contact = _CONTACT.match(text, pos)
            if contact is not None:
                operand = contact.group(2)
                if (" " in operand or "\t" in operand) and any(
                    word.upper() in _OPERAND_STOPS for word in _BLANK_WORD.findall(operand)
                ):
                    raise _NotPlainError  # a word that ends the operand: a mistake to report
                self.count += 1
                elements.append(
                    Contact(
                        id=f"e{self.count}",
                        operand=operand,
                        negated=contact.group(1) is not None,
                    )
                )
                pos = contact.end()
                continue
            word, after = self.word(pos)
            if word == end:
                return elements, after
            if word in ("CONTACT", "CONTACTNC"):
                element_id = self.number()
                mark, pos = self.mark(after)
                if mark != "(":
                    raise _NotPlainError
                operand, pos = self.operand(pos)
                mark, pos = self.mark(pos)
                if mark != ")":
                    raise _NotPlainError
                elements.append(
                    Contact(id=element_id, operand=operand, negated=word == "CONTACTNC")
                )
            elif word == "PARALLEL":
                element_id = self.number()
                branches: list[Series] = []
                while True:
                    word, pos = self.word(after)
                    if word == "END_PARALLEL":
                        break
                    if word != "BRANCH":
                        raise _NotPlainError
                    branch, after = self.series(pos, "END_BRANCH")
                    branches.append(Series(elements=branch))
                if len(branches) < 2:
                    raise _NotPlainError
                elements.append(Parallel(id=element_id, branches=branches))
            elif word == "BOX":
                element_id = self.number()
                box, pos = self.box(after, element_id)
                elements.append(box)
            else:
                raise _NotPlainError
            self.no_id(pos)

    def box(self, pos: int, element_id: str) -> tuple[Box, int]:
        """``( name , PIN := operand , PIN => operand ... )`` with plain operands."""
        mark, pos = self.mark(pos)
        if mark != "(":
            raise _NotPlainError
        name, pos = self.operand(pos)
        inputs: dict[str, str | Series] = {}
        outputs: dict[str, str] = {}
        while True:
            mark, pos = self.mark(pos)
            if mark == ")":
                return Box(id=element_id, name=name, inputs=inputs, outputs=outputs), pos
            if mark != ",":
                raise _NotPlainError
            found = _WORD.match(self.text, pos)
            if found is None:
                raise _NotPlainError
            key = found.group(1)
            if key.upper() == "INSTANCE" or key in inputs or key in outputs:
                raise _NotPlainError
            mark, pos = self.mark(found.end())
            if mark not in (":=", "=>"):
                raise _NotPlainError
            if _WORD.match(self.text, pos) and self.word(pos)[0] == "RUNG":
                raise _NotPlainError
            value, pos = self.operand(pos)
            if mark == ":=":
                inputs[key] = value
            else:
                outputs[key] = value

    def no_id(self, pos: int) -> None:
        """An ``@id`` after an element is read the general way."""
        text = self.text
        while pos < len(text) and text[pos] in " \t\r\n":
            pos += 1
        if text.startswith("@", pos):
            raise _NotPlainError
