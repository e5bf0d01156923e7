"""The example projects of ``examples/projects/``, imported once, on the first start.

"Once" is kept in the database (an ``app_state`` row), not in the data folder: with PostgreSQL
several servers share one database and no data folder, and a user who deleted the examples must
not get them back at the next start. A database that already holds projects (one upgraded from an
older Nasaq) is only marked, never seeded. A missing folder (an image built without the examples)
imports nothing and leaves no mark.
"""

from __future__ import annotations

import logging
from datetime import UTC, datetime
from pathlib import Path

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session, sessionmaker

from nasaq.storage import files as file_store
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction
from nasaq.storage.models import AppState, Project
from nasaq.workbench.names import is_valid_name

log = logging.getLogger(__name__)

MARKER = "examples_imported"


def example_folders(root: Path) -> list[Path]:
    return sorted(path for path in root.iterdir() if path.is_dir()) if root.is_dir() else []


def _sources(folder: Path) -> list[tuple[str, str]]:
    files = sorted(path for path in folder.iterdir() if path.is_file() and is_valid_name(path.name))
    return [(path.name, path.read_text("utf-8")) for path in files]


def _seed(session: Session, folders: list[Path]) -> list[str]:
    if session.get(AppState, MARKER) is not None:
        return []
    names: list[str] = []
    if session.scalar(select(Project.id).limit(1)) is None:
        for folder in folders:
            project = project_store.create_project(session, folder.name)
            file_store.add_files(session, project, _sources(folder))
            names.append(folder.name)
    stamp = datetime.now(UTC).isoformat(timespec="seconds")
    session.add(AppState(key=MARKER, value=f"{stamp} {', '.join(names) or '(none)'}"))
    return names


def seed_examples(factory: sessionmaker[Session], root: Path) -> list[str]:
    """Imports every sub-folder of ``root`` as a project, the first time only; their names."""
    folders = example_folders(root)
    if not folders:
        return []
    try:
        with transaction(factory) as session:
            names = _seed(session, folders)
    except (IntegrityError, project_store.ProjectNameTakenError):
        return []  # another server sharing the database is importing them at this moment
    if names:
        log.info("imported the example projects: %s", ", ".join(names))
    return names
