from pathlib import Path

import pytest

from nasaq.settings import Settings


def test_defaults_serve_locally_with_sqlite_in_data_folder() -> None:
    settings = Settings(_env_file=None)  # type: ignore[call-arg]
    assert settings.host == "127.0.0.1"
    assert settings.port == 8000
    assert settings.effective_database_url == f"sqlite:///{Path('data/nasaq.db').resolve()}"
    assert settings.uses_sqlite


def test_environment_overrides_host_port_and_database(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("NASAQ_HOST", "0.0.0.0")
    monkeypatch.setenv("NASAQ_PORT", "9001")
    monkeypatch.setenv("NASAQ_DATABASE_URL", "postgresql+psycopg://u:p@db:5432/nasaq")
    settings = Settings(_env_file=None)  # type: ignore[call-arg]
    assert (settings.host, settings.port) == ("0.0.0.0", 9001)
    assert settings.effective_database_url == "postgresql+psycopg://u:p@db:5432/nasaq"
    assert not settings.uses_sqlite


def test_port_out_of_range_is_rejected(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("NASAQ_PORT", "70000")
    with pytest.raises(ValueError, match="port"):
        Settings(_env_file=None)  # type: ignore[call-arg]
