from fastapi.testclient import TestClient
from sqlalchemy import create_engine

from nasaq import __version__


def test_health_reports_ok_and_version(client: TestClient) -> None:
    response = client.get("/api/health")
    assert response.status_code == 200
    assert response.json() == {"status": "ok", "version": __version__, "database": "ok"}


def test_health_reports_an_unreachable_database_as_503(client: TestClient) -> None:
    app = client.app
    app.state.engine = create_engine("sqlite:////nonexistent-folder/never/nasaq.db")  # type: ignore[attr-defined]
    response = client.get("/api/health")
    assert response.status_code == 503
    assert response.json()["error"]["code"] == "API106"
