"""Whatever goes wrong, the client gets the same JSON error shape with a catalogue code."""

from fastapi.testclient import TestClient

from nasaq.api.app import create_app
from nasaq.settings import Settings


def test_unknown_api_route_is_json_api101_not_the_index_page(client: TestClient) -> None:
    response = client.get("/api/does-not-exist")
    assert response.status_code == 404
    assert response.headers["content-type"].startswith("application/json")
    assert response.json()["error"]["code"] == "API101"


def test_wrong_method_is_api102(client: TestClient) -> None:
    response = client.put("/api/health")
    assert response.status_code == 405
    assert response.json()["error"]["code"] == "API102"
    assert response.json()["error"]["params"] == {"method": "PUT", "path": "/api/health"}


def test_non_numeric_id_is_api103(client: TestClient) -> None:
    response = client.get("/api/projects/abc")
    assert response.status_code == 422
    assert response.json()["error"]["location"] == ["path", "project_id"]


def test_a_bug_in_a_route_is_api199_without_internals(settings: Settings) -> None:
    app = create_app(settings)

    @app.get("/api/boom")
    def boom() -> None:
        raise RuntimeError("secret internal detail")

    # Routes registered after the front end's catch-all are still found first by path match.
    app.router.routes.insert(0, app.router.routes.pop())
    with TestClient(app, raise_server_exceptions=False) as client:
        response = client.get("/api/boom")
    assert response.status_code == 500
    error = response.json()["error"]
    assert error["code"] == "API199"
    assert "secret" not in response.text
