"""The fuzz cases: case ``i`` of seed ``s`` is always the same text (``random.Random((s, i))``).

Languages take turns (STL, SCL, LAD/FBD). About 3 % of the cases (10 % with ``--big``) are the
issue's pathological inputs (``mutate.pathological``), a quarter random sentences of the language's
grammar (``grammar_gen``, half of them mutated further), the rest mutations of the repository's
own sources. Every other case compiles for the S7-1500 profile, the others for S7-300.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

from grammar_gen import sampler_for
from mutate import ROOT, mutate, pathological, seeds

LANGUAGES = ("stl", "scl", "lad")
SUFFIX = {"stl": ".awl", "scl": ".scl", "lad": ".lad"}
GRAMMARS = {name: str(ROOT / "grammars" / f"{name}.lark") for name in LANGUAGES}


@dataclass(frozen=True, slots=True)
class Case:
    seed: int
    index: int
    language: str
    kind: str  # pathological | grammar | mutation
    profile: str
    text: str
    conversions: bool = True  # also convert (LAD/FBD/STL views) besides compiling

    @property
    def name(self) -> str:
        return f"fuzz{self.index}{SUFFIX[self.language]}"


def excerpt(text: str, rng: random.Random) -> str:
    """A seed as it is, or (mostly, for a long one) a run of 15 to 40 of its lines: a block
    cut anywhere is what an editor holds while a user types, and it compiles fast."""
    lines = text.splitlines(keepends=True)
    if len(lines) <= 40 or rng.random() < 0.3:
        return text
    size = rng.randint(15, 40)
    start = rng.randrange(len(lines) - size)
    return "".join(lines[start : start + size])


def make_case(seed: int, index: int, big: bool = False) -> Case:
    """Case ``index`` of ``seed``; ``big`` (``make fuzz``) makes the pathological inputs
    larger and more frequent, the bounded run keeps them within its time budget."""
    rng = random.Random(seed * 1_000_003 + index)
    language = LANGUAGES[index % 3]
    profile = "S7-1500" if (index // 3) % 2 else "S7-300"
    roll = rng.random()
    donors = seeds(language)
    if roll < (0.1 if big else 0.03):
        kind, text = "pathological", pathological(language, rng, big)
    elif roll < 0.35 or not donors:
        kind = "grammar"
        text = sampler_for(GRAMMARS[language]).sentence(rng, budget=rng.choice((6, 10, 16)))
        if rng.random() < 0.5:
            text = mutate(text, rng, donors)
    else:
        kind = "mutation"
        text = mutate(excerpt(rng.choice(donors), rng), rng, donors)
    if language == "lad" and rng.random() < 0.1:
        language_line = "LANGUAGE FBD\n"
        text = text.replace("\nBEGIN", "\n" + language_line + "BEGIN", 1)
    conversions = big or index % 9 < 3  # every third case of each language
    return Case(seed, index, language, kind, profile, text, conversions)
