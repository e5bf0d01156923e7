from pathlib import Path

from fastapi.testclient import TestClient

from nasaq.api.app import create_app
from nasaq.settings import Settings


def test_index_page_is_served_at_root_without_caching(client: TestClient) -> None:
    response = client.get("/")
    assert response.status_code == 200
    assert '<div id="root">' in response.text
    assert response.headers["cache-control"] == "no-cache"


def test_client_side_routes_fall_back_to_the_index_page(client: TestClient) -> None:
    response = client.get("/projects/3/blocks/OB1")
    assert response.status_code == 200
    assert '<div id="root">' in response.text


def test_hashed_assets_are_cached_for_a_year_and_gzipped(client: TestClient) -> None:
    response = client.get("/assets/app-1a2b.js", headers={"accept-encoding": "gzip"})
    assert response.status_code == 200
    assert "immutable" in response.headers["cache-control"]
    assert response.headers["content-encoding"] == "gzip"


def test_missing_asset_is_404(client: TestClient) -> None:
    assert client.get("/assets/nope.js").status_code == 404


def test_top_level_public_files_are_served(client: TestClient) -> None:
    response = client.get("/favicon.svg")
    assert response.status_code == 200
    assert response.text.startswith("<svg")


def test_paths_outside_the_build_folder_are_not_served(client: TestClient, tmp_path: Path) -> None:
    (tmp_path / "secret.txt").write_text("top secret", encoding="utf-8")
    response = client.get("/..%2Fsecret.txt")
    assert "top secret" not in response.text


def test_without_a_build_the_page_says_how_to_build(settings: Settings, tmp_path: Path) -> None:
    settings.frontend_dist = tmp_path / "missing"
    with TestClient(create_app(settings)) as client:
        response = client.get("/")
        assert response.status_code == 503
        assert "make install" in response.text
        assert client.get("/api/health").status_code == 200
