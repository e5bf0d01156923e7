"""The example projects in Arabic, Persian and Vietnamese: same code, translated comments."""

from __future__ import annotations

import csv
import json
import re
from pathlib import Path

import pytest
import yaml
from fastapi.testclient import TestClient

from nasaq.api.app import create_app
from nasaq.scenarios.runner import run_scenario
from nasaq.settings import Settings
from nasaq.workbench.example_variants import about, variant_sources
from nasaq.workbench.examples import example_folders
from nasaq.workbench.tree import build

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "projects"
FOLDERS = example_folders(EXAMPLES)
TRANSLATED = ("ar", "fa", "vi")
VARIANTS = [(folder, lang) for folder in FOLDERS for lang in TRANSLATED]
ARABIC_SCRIPT = re.compile(r"[\u0600-\u06FF]")
COMMENT = re.compile(r"//.*$", re.MULTILINE)
TITLE = re.compile(r"^TITLE\s*=.*$", re.MULTILINE)


def _ids(item: tuple[Path, str]) -> str:
    return f"{item[0].name}-{item[1]}"


def _code(name: str, text: str) -> object:
    """What must not change between languages: the code without comments and titles, the
    symbols without their comments, the scenario without its name and notes."""
    if name.endswith(".sdf"):
        return [row[:3] for row in csv.reader(text.splitlines())]
    if name.endswith(".yaml"):
        scenario = yaml.safe_load(text)
        steps = [step for step in scenario["steps"] if "note" not in step]
        return {**scenario, "name": None, "steps": steps}
    code = TITLE.sub("", COMMENT.sub("", text)).splitlines()
    return [line.rstrip() for line in code if line.strip()]


def _files(folder: Path) -> list[Path]:
    return sorted(p for p in folder.iterdir() if p.suffix in (".awl", ".scl", ".sdf", ".yaml"))


@pytest.mark.parametrize(("folder", "lang"), VARIANTS, ids=[_ids(v) for v in VARIANTS])
def test_a_variant_has_the_english_code_and_translated_comments(folder: Path, lang: str) -> None:
    for english in _files(folder):
        translated = folder / "locales" / lang / english.name
        assert translated.is_file(), f"{translated} is missing"
        text = translated.read_text("utf-8")
        assert _code(english.name, text) == _code(english.name, english.read_text("utf-8"))
        assert text != english.read_text("utf-8"), f"{translated} is not translated"
        if lang in ("ar", "fa"):
            comments = COMMENT.findall(text) + TITLE.findall(text)
            untranslated = [c for c in comments if not ARABIC_SCRIPT.search(c)]
            assert untranslated == [], f"{translated}: English comments left"


@pytest.mark.parametrize(("folder", "lang"), VARIANTS, ids=[_ids(v) for v in VARIANTS])
def test_a_variant_compiles_and_its_scenario_passes(folder: Path, lang: str) -> None:
    assert build(variant_sources(folder, lang)).diagnostics == []
    scenarios = sorted((folder / "locales" / lang).glob("*.yaml"))
    assert scenarios
    for path in scenarios:
        result = run_scenario(path)
        assert result.passed, (result.error, [f.describe() for f in result.failures])


@pytest.mark.parametrize("folder", FOLDERS, ids=lambda folder: folder.name)
def test_every_example_has_a_title_and_description_in_every_language(
    folder: Path,
) -> None:
    texts = json.loads((folder / "about.json").read_text("utf-8"))
    assert set(texts) == {"en", *TRANSLATED}
    projects = set()
    for lang in texts:
        found = about(folder, lang)
        assert found.title
        assert found.description
        assert found.project
        projects.add(found.project)
        if lang in ("ar", "fa"):
            latin = re.findall(r"[A-Za-z]{2,}", found.title + found.description)
            assert set(latin) <= {"STL", "SCL", "S5"}, (lang, latin)
    assert about(folder, "en").project == folder.name  # the project imported on the first start
    assert len(projects) == 4  # each language its own project


def test_opening_an_example_in_persian_makes_one_persian_project(
    settings: Settings,
) -> None:
    settings = settings.model_copy(update={"examples_dir": EXAMPLES})
    with TestClient(create_app(settings)) as client:
        listed = client.get("/api/examples", params={"lang": "fa"}).json()
        motor = next(item for item in listed if item["name"] == "motor-start-stop")
        assert motor["title"] == "راه‌اندازی و توقف موتور"
        assert motor["project_id"] is None
        english = next(
            item
            for item in client.get("/api/examples").json()
            if item["name"] == "motor-start-stop"
        )
        assert english["project_id"] is not None  # imported on the first start

        opened = client.post("/api/examples/motor-start-stop/open", params={"lang": "fa"})
        assert opened.status_code == 201
        project = opened.json()
        assert project["name"] == motor["project"]
        again = client.post("/api/examples/motor-start-stop/open", params={"lang": "fa"})
        assert again.status_code == 200
        assert again.json()["id"] == project["id"]

        ob1 = client.get(f"/api/projects/{project['id']}/files/OB1.awl").json()
        assert "// زر" not in ob1["text"]
        assert "شستی راه‌اندازی" in ob1["text"]
        assert '"Motor"' in ob1["text"]
        assert '"Start"' in ob1["text"]

        missing = client.post("/api/examples/nothing/open", params={"lang": "fa"})
        assert missing.status_code == 404
        assert client.get("/api/examples", params={"lang": "de"}).status_code == 422
