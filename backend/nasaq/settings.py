"""Runtime settings, read from the environment (prefix ``NASAQ_``) or a ``.env`` file.

Defaults give the embedded set-up that ``make run`` promises: the server on 127.0.0.1:8000 and a
SQLite database in ``./data``. PostgreSQL is one setting away (``NASAQ_DATABASE_URL``), as in
docker-compose.yml.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from pydantic import Field
from pydantic_settings import BaseSettings, SettingsConfigDict

# backend/nasaq/settings.py -> repository root; the built front end sits at frontend/dist there.
_REPO_ROOT = Path(__file__).resolve().parents[2]


class Settings(BaseSettings):
    model_config = SettingsConfigDict(env_prefix="NASAQ_", env_file=".env", extra="ignore")

    host: str = Field(default="127.0.0.1", description="Interface the server listens on.")
    port: int = Field(default=8000, ge=1, le=65535, description="TCP port of the server.")
    data_dir: Path = Field(
        default=Path("data"), description="Folder for the embedded SQLite database and other data."
    )
    database_url: str | None = Field(
        default=None,
        description="SQLAlchemy URL; empty means SQLite at <data_dir>/nasaq.db.",
    )
    frontend_dist: Path = Field(
        default=_REPO_ROOT / "frontend" / "dist",
        description="Folder of the built front end served at '/'.",
    )
    examples_dir: Path = Field(
        default=_REPO_ROOT / "examples" / "projects",
        description="Example projects (one folder each) imported on the first start only; "
        "a missing folder imports none.",
    )
    lessons_dir: Path = Field(
        default=_REPO_ROOT / "examples" / "lessons",
        description="The course: one folder per unit, one per lesson (examples/lessons/README.md).",
    )
    log_level: str = Field(default="info", description="Log level of the server.")
    session_workers: int | None = Field(
        default=None,
        ge=1,
        description="Processes that run simulation sessions; empty means one per CPU core.",
    )
    max_sessions: int = Field(
        default=200, ge=1, description="Simulation sessions the server runs at most at once."
    )
    session_idle_seconds: float = Field(
        default=900, gt=0, description="A session with no client for this long is closed."
    )
    slow_client_seconds: float = Field(
        default=10, gt=0, description="A monitoring client that reads nothing this long is dropped."
    )

    @property
    def effective_database_url(self) -> str:
        if self.database_url:
            return self.database_url
        return f"sqlite:///{(self.data_dir / 'nasaq.db').resolve()}"

    @property
    def uses_sqlite(self) -> bool:
        return self.effective_database_url.startswith("sqlite")


@lru_cache(maxsize=1)
def get_settings() -> Settings:
    """The process-wide settings; tests build their own ``Settings`` instead."""
    return Settings()
