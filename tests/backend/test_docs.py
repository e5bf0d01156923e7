import json
import re
from pathlib import Path

from fastapi.testclient import TestClient

ROOT = Path(__file__).resolve().parents[2]


def test_openapi_schema_lists_the_api(client: TestClient) -> None:
    schema = client.get("/api/openapi.json").json()
    assert schema["info"]["title"] == "Nasaq"
    assert {"/api/health", "/api/projects", "/api/projects/{project_id}"} <= set(schema["paths"])


def test_docs_page_loads_only_local_assets(client: TestClient) -> None:
    response = client.get("/api/docs")
    assert response.status_code == 200
    assert "SwaggerUIBundle" in response.text
    assert re.findall(r"https?://", response.text) == []
    assert '"validatorUrl": null' in response.text
    for asset in re.findall(r'(?:href|src)="(/api/docs/assets/[^"]+)"', response.text):
        assert client.get(asset).status_code == 200


def test_the_front_ends_copy_of_the_openapi_document_is_current(client: TestClient) -> None:
    """frontend/src/api/openapi.json is what the front end's type tests check against."""
    committed = ROOT / "frontend" / "src" / "api" / "openapi.json"
    assert json.loads(committed.read_text("utf-8")) == client.get("/api/openapi.json").json(), (
        "the API changed: run `.venv/bin/nasaq openapi > frontend/src/api/openapi.json`"
    )
