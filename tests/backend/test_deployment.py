"""The container set-up: docker-compose.yml runs the app image against PostgreSQL.

Docker cannot run on the development machines, so these tests hold the contract the files must
keep: the app is built from the Dockerfile, points at the db service by URL, and the image carries
the PostgreSQL driver pinned in the lock file.
"""

from pathlib import Path
from typing import Any

import yaml
from sqlalchemy.engine import make_url

ROOT = Path(__file__).resolve().parents[2]


def _compose() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load((ROOT / "docker-compose.yml").read_text("utf-8"))
    return data


def test_compose_has_app_built_here_and_postgres() -> None:
    services = _compose()["services"]
    assert services["db"]["image"].startswith("postgres:")
    build = services["app"]["build"]
    assert (ROOT / build["context"] / build["dockerfile"]).is_file()
    assert services["app"]["depends_on"]["db"]["condition"] == "service_healthy"


def test_app_points_at_the_db_service_with_the_psycopg_driver() -> None:
    env = _compose()["services"]["app"]["environment"]
    url = make_url(env["NASAQ_DATABASE_URL"].replace("${POSTGRES_PASSWORD:-nasaq}", "pw"))
    assert url.drivername == "postgresql+psycopg"
    assert (url.host, url.port, url.database) == ("db", 5432, "nasaq")


def test_image_installs_the_postgres_extra_and_the_built_front_end() -> None:
    dockerfile = (ROOT / "Dockerfile").read_text("utf-8")
    assert "[postgres]" in dockerfile
    assert "--constraint backend/requirements.lock" in dockerfile
    assert "npm run build -w frontend" in dockerfile
    assert "NASAQ_FRONTEND_DIST=/app/frontend/dist" in dockerfile
    lock = (ROOT / "backend" / "requirements.lock").read_text("utf-8")
    assert "psycopg==" in lock
    assert "psycopg-binary==" in lock
