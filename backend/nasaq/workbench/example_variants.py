"""The example projects in the learner's language: titles, descriptions and commented sources.

Each example folder holds the English sources (imported on the first start, see
:mod:`nasaq.workbench.examples`), an ``about.json`` with each language's title, description and
project name, and ``locales/<lang>/`` with the sources whose comments, titles and symbol comments
are translated. The code, addresses and symbol names of a variant are those of the English files
(a test compares them, and each variant's scenario runs in ``nasaq test``): a Persian class and an
English one download the same program and can compare watch tables.

A learner opens an example in the interface language: the variant becomes a project of its own
(named in that language), so each class keeps its edits, and opening it again returns the same
project instead of a second copy — as a teacher hands out a worksheet once.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from nasaq.workbench.examples import example_folders
from nasaq.workbench.names import is_valid_name

LANGUAGES = ("en", "ar", "fa", "vi")
DEFAULT_LANGUAGE = "en"


@dataclass(frozen=True, slots=True)
class ExampleAbout:
    name: str  # the folder's name, stable across languages
    project: str  # the project's name in this language
    title: str
    description: str


def about(folder: Path, language: str) -> ExampleAbout:
    """The example's texts in ``language`` (English for a language it lacks)."""
    path = folder / "about.json"
    texts = json.loads(path.read_text("utf-8")) if path.is_file() else {}
    chosen = texts.get(language) or texts.get(DEFAULT_LANGUAGE) or {}
    return ExampleAbout(
        name=folder.name,
        project=str(chosen.get("project", folder.name)),
        title=str(chosen.get("title", folder.name)),
        description=str(chosen.get("description", "")),
    )


def find_example(root: Path, name: str) -> Path | None:
    return next((folder for folder in example_folders(root) if folder.name == name), None)


def variant_sources(folder: Path, language: str) -> list[tuple[str, str]]:
    """The project files of the example in ``language``: each English source, replaced by its
    translated copy in ``locales/<language>/`` when there is one."""
    local = folder / "locales" / language
    files = sorted(path for path in folder.iterdir() if path.is_file() and is_valid_name(path.name))
    out = []
    for path in files:
        translated = local / path.name
        chosen = translated if language != DEFAULT_LANGUAGE and translated.is_file() else path
        out.append((path.name, chosen.read_text("utf-8")))
    return out


def main_source(folder: Path) -> str | None:
    """The source a learner reads first: OB 1's (``OB1.awl``), else the first source."""
    names = [name for name, _ in variant_sources(folder, DEFAULT_LANGUAGE)]
    sources = [name for name in names if not name.endswith((".sdf", ".asc", ".seq", ".csv"))]
    return next((name for name in sources if name.upper().startswith("OB1.")), None) or next(
        iter(sources), None
    )
