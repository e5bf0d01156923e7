"""The ``nasaq`` command: ``serve`` the IDE, ``migrate`` the database, print the ``openapi`` schema.

Later capabilities add their subcommands here (``run``, ``test``, ``compile``).
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence

from nasaq import __version__
from nasaq.settings import Settings, get_settings


def _serve(settings: Settings, args: argparse.Namespace) -> int:
    import uvicorn

    from nasaq.api.app import create_app

    host = args.host or settings.host
    port = args.port or settings.port
    print(f"Nasaq {__version__}: http://{host}:{port}/  (API docs at /api/docs)", flush=True)
    uvicorn.run(create_app(settings), host=host, port=port, log_level=settings.log_level)
    return 0


def _migrate(settings: Settings, _args: argparse.Namespace) -> int:
    from nasaq.storage.migrate import upgrade_to_head

    upgrade_to_head(settings)
    print("database schema is up to date")
    return 0


def _openapi(settings: Settings, _args: argparse.Namespace) -> int:
    from nasaq.api.app import create_app

    json.dump(create_app(settings).openapi(), sys.stdout, indent=2, ensure_ascii=False)
    sys.stdout.write("\n")
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="nasaq", description=__doc__)
    parser.add_argument("--version", action="version", version=f"nasaq {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)

    serve = commands.add_parser("serve", help="start the web IDE and API server")
    serve.add_argument("--host", help="interface to listen on (default: NASAQ_HOST or 127.0.0.1)")
    serve.add_argument("--port", type=int, help="port (default: NASAQ_PORT or 8000)")
    serve.set_defaults(handler=_serve)

    migrate = commands.add_parser("migrate", help="create or upgrade the database schema")
    migrate.set_defaults(handler=_migrate)

    openapi = commands.add_parser("openapi", help="print the OpenAPI schema as JSON")
    openapi.set_defaults(handler=_openapi)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    handler = args.handler
    result: int = handler(get_settings(), args)
    return result


if __name__ == "__main__":
    raise SystemExit(main())
