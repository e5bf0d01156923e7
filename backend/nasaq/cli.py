"""The ``nasaq`` command: ``serve`` the IDE, ``run`` STL/SCL/LAD/FBD/S7-Graph sources headless,
``compile`` them (``--emit stl`` shows what SCL and S7-Graph become), ``test`` scenarios,
``migrate`` the database, print the ``openapi`` schema."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence

from nasaq import __version__
from nasaq.lang.profiles import PROFILES
from nasaq.settings import Settings, get_settings

EXIT_STATUS = (
    "exit status (every command): 0 all is well; 1 what the command was given has errors "
    "(sources that do not compile, a CPU STOP on an error, a failed scenario or lesson, a "
    "refused conversion); 2 a usage error (an unknown option or address, a file that cannot be "
    "read, nothing found)"
)


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


def _run(_settings: Settings, args: argparse.Namespace) -> int:
    from nasaq.headless.addresses import AddressError
    from nasaq.headless.run import main as run_main
    from nasaq.headless.run import options_from_args

    try:
        options = options_from_args(
            args.sources,
            args.cycles,
            args.cycle_ms,
            args.set,
            args.at,
            args.mnemonics,
            args.test_ops,
            args.profile,
            args.time,
            args.restart,
            args.clock_memory,
        )
    except AddressError as exc:
        print(f"nasaq run: {exc}", file=sys.stderr)
        return 2
    return run_main(options)


def _compile(_settings: Settings, args: argparse.Namespace) -> int:
    from pathlib import Path

    from nasaq.headless.emit import main as compile_main

    return compile_main([Path(source) for source in args.sources], args.emit, profile=args.profile)


def _convert(_settings: Settings, args: argparse.Namespace) -> int:
    from pathlib import Path

    from nasaq.headless.convert import main as convert_main

    out = Path(args.out) if args.out else None
    return convert_main(Path(args.source), args.to, out)


def _test(_settings: Settings, args: argparse.Namespace) -> int:
    from nasaq.scenarios.report import main as test_main

    return test_main(args.scenarios, sys.stdout)


def _lessons(settings: Settings, args: argparse.Namespace) -> int:
    from nasaq.lessons import report

    if args.action == "check":
        return report.check_main(args.paths, settings.lessons_dir, sys.stdout)
    if args.action == "lint":
        return report.lint_main(args.paths, settings.lessons_dir, sys.stdout)
    return report.list_main(settings.lessons_dir, args.lang, sys.stdout)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="nasaq", description=__doc__, epilog=EXIT_STATUS)
    parser.add_argument("--version", action="version", version=f"nasaq {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)

    serve = commands.add_parser("serve", help="start the web IDE and API server")
    serve.add_argument("--host", help="interface to listen on (default: NASAQ_HOST or 127.0.0.1)")
    serve.add_argument("--port", type=int, help="port (default: NASAQ_PORT or 8000)")
    serve.set_defaults(handler=_serve)

    run = commands.add_parser(
        "run", help="run STL/SCL/LAD/FBD/Graph sources for N scans and print the final CPU state"
    )
    run.add_argument(
        "sources",
        nargs="+",
        metavar="SOURCE",
        help=".awl/.scl/.db/.udt/.lad/.fbd/.graph sources, symbol tables",
    )
    run.add_argument("--cycles", type=int, default=1, help="scans of OB1 to run (after OB100)")
    run.add_argument(
        "--cycle-ms", type=float, help="virtual time per scan (default: cpu.properties, else 10)"
    )
    run.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="ADDR=VALUE",
        help="hold an input from before scan 1; M, Q, DB are written once after OB100",
    )
    run.add_argument(
        "--at", action="append", default=[], metavar="K:ADDR=VALUE", help="change before scan K"
    )
    run.add_argument("--mnemonics", choices=["auto", "en", "de"], default="auto")
    run.add_argument(
        "--test-ops", action="store_true", help="accept the __ASSERT== ... self-check operations"
    )
    run.add_argument(
        "--cpu",
        "--profile",
        dest="profile",
        choices=PROFILES,
        help="the CPU family (S7-1500 stands for S7-1200/1500); default: cpu.properties, else "
        "S7-300",
    )
    run.add_argument(
        "--time",
        choices=["virtual", "real", "fast"],
        default="virtual",
        help="virtual: exact cycle steps (default); real: paced to the wall clock; fast: no pacing",
    )
    run.add_argument(
        "--restart",
        choices=["warm", "cold"],
        help="startup: warm restart (OB100) or cold restart (OB102); default: the startup of "
        "cpu.properties, else warm",
    )
    run.add_argument(
        "--clock-memory",
        metavar="MB",
        help="marker byte used as clock memory (e.g. 100 or MB100): bit 0 = 0.1 s ... bit 7 = 2 s",
    )
    run.set_defaults(handler=_run)

    compile_ = commands.add_parser(
        "compile", help="compile sources: print problems (and, with --emit stl, the STL)"
    )
    compile_.add_argument(
        "sources", nargs="+", metavar="SOURCE", help=".awl/.scl/.db/.udt/.lad/.fbd/.graph sources"
    )
    compile_.add_argument(
        "--emit",
        choices=["stl", "none"],
        default="none",
        help="stl: print the STL the SCL and S7-Graph blocks are compiled to, with their lines",
    )
    compile_.add_argument(
        "--cpu",
        "--profile",
        dest="profile",
        choices=PROFILES,
        help="the CPU family to compile for; default: cpu.properties, else S7-300",
    )
    compile_.set_defaults(handler=_compile)

    convert = commands.add_parser(
        "convert",
        help="convert a source between STL, LAD and FBD (networks without LAD shape stay STL), "
        "or an S7-Graph source to its STL",
    )
    convert.add_argument("source", metavar="SOURCE", help=".awl/.stl, .lad, .fbd or .graph source")
    convert.add_argument(
        "--to",
        required=True,
        choices=["stl", "lad", "fbd", "graph"],
        help="graph: nothing converts to S7-Graph (the error says so)",
    )
    convert.add_argument("--out", metavar="FILE", help="write here instead of standard output")
    convert.set_defaults(handler=_convert)

    test = commands.add_parser("test", help="run scenario files (PLC unit tests)")
    test.add_argument("scenarios", nargs="+", metavar="SCENARIO", help="YAML files or folders")
    test.set_defaults(handler=_test)

    lessons = commands.add_parser("lessons", help="check, lint or list the course's lessons")
    lesson_actions = lessons.add_subparsers(dest="action", required=True)
    for action, text in (
        ("check", "each solution passes every check, each start/ and wrong/ fails one"),
        ("lint", "texts in every language, links, plant wiring, hints, check files"),
    ):
        found = lesson_actions.add_parser(action, help=text)
        found.add_argument(
            "paths", nargs="*", metavar="PATH", help="course, unit or lesson folders (default: all)"
        )
    listed = lesson_actions.add_parser("list", help="the units and lessons of the course")
    listed.add_argument("--lang", choices=["en", "ar", "fa", "vi"], default="en")
    lessons.set_defaults(handler=_lessons)

    migrate = commands.add_parser("migrate", help="create or upgrade the database schema")
    migrate.set_defaults(handler=_migrate)

    openapi = commands.add_parser("openapi", help="print the OpenAPI schema as JSON")
    openapi.set_defaults(handler=_openapi)
    for command in commands.choices.values():
        command.epilog = EXIT_STATUS
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    handler = args.handler
    result: int = handler(get_settings(), args)
    return result


if __name__ == "__main__":
    raise SystemExit(main())
