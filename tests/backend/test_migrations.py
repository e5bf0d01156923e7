"""The Alembic migrations and the SQLAlchemy models must describe the same schema."""

from alembic import command
from alembic.autogenerate import compare_metadata
from alembic.migration import MigrationContext
from sqlalchemy import create_engine, inspect

from nasaq.settings import Settings
from nasaq.storage.migrate import alembic_config, upgrade_to_head
from nasaq.storage.models import Base


def test_upgrade_creates_database_file_and_projects_table(settings: Settings) -> None:
    upgrade_to_head(settings)
    assert (settings.data_dir / "nasaq.db").is_file()
    engine = create_engine(settings.effective_database_url)
    try:
        assert "projects" in inspect(engine).get_table_names()
    finally:
        engine.dispose()


def test_upgrade_twice_is_harmless(settings: Settings) -> None:
    upgrade_to_head(settings)
    upgrade_to_head(settings)


def test_models_match_migrations(settings: Settings) -> None:
    upgrade_to_head(settings)
    engine = create_engine(settings.effective_database_url)
    try:
        with engine.connect() as connection:
            context = MigrationContext.configure(connection, opts={"compare_type": True})
            assert compare_metadata(context, Base.metadata) == []
    finally:
        engine.dispose()


def test_downgrade_to_base_removes_the_tables(settings: Settings) -> None:
    upgrade_to_head(settings)
    command.downgrade(alembic_config(settings), "base")
    engine = create_engine(settings.effective_database_url)
    try:
        left = set(inspect(engine).get_table_names())
        assert not {"projects", "project_files", "app_state"} & left
    finally:
        engine.dispose()


def test_0002_adds_project_files_and_app_state_and_downgrades_to_0001(settings: Settings) -> None:
    upgrade_to_head(settings)
    config = alembic_config(settings)
    engine = create_engine(settings.effective_database_url)
    try:
        tables = set(inspect(engine).get_table_names())
        assert {"projects", "project_files", "app_state"} <= tables
        with engine.begin() as connection:
            connection.exec_driver_sql(
                "INSERT INTO projects (name, description, created_at, updated_at)"
                " VALUES ('Kept', '', '2026-01-01 00:00:00', '2026-01-01 00:00:00')"
            )
        command.downgrade(config, "0001")
        tables = set(inspect(engine).get_table_names())
        assert "project_files" not in tables
        assert "app_state" not in tables
        with engine.connect() as connection:
            names = connection.exec_driver_sql("SELECT name FROM projects").scalars().all()
        assert names == ["Kept"]
        command.upgrade(config, "head")
        assert "project_files" in inspect(engine).get_table_names()
    finally:
        engine.dispose()
