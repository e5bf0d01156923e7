import json
import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from nasaq.cli import build_parser, main


def test_serve_takes_host_and_port() -> None:
    args = build_parser().parse_args(["serve", "--host", "0.0.0.0", "--port", "8123"])
    assert (args.host, args.port) == ("0.0.0.0", 8123)


def test_unknown_command_exits_with_usage(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["frobnicate"])
    assert exit_info.value.code == 2
    assert "invalid choice" in capsys.readouterr().err


def _env(tmp_path: Path) -> dict[str, str]:
    return {**os.environ, "NASAQ_DATA_DIR": str(tmp_path / "data")}


def _nasaq(tmp_path: Path, *args: str) -> str:
    """Runs the installed command as a user would and returns what it printed."""
    result = subprocess.run(
        [sys.executable, "-m", "nasaq", *args],
        env=_env(tmp_path),
        capture_output=True,
        text=True,
        check=True,
    )
    return result.stdout


def test_migrate_creates_the_database(tmp_path: Path) -> None:
    assert "up to date" in _nasaq(tmp_path, "migrate")
    assert (tmp_path / "data" / "nasaq.db").is_file()


def test_openapi_prints_the_schema(tmp_path: Path) -> None:
    assert "/api/projects" in json.loads(_nasaq(tmp_path, "openapi"))["paths"]


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


def test_serve_runs_a_real_uvicorn_server(tmp_path: Path) -> None:
    port = _free_port()
    server = subprocess.Popen(
        [sys.executable, "-m", "nasaq", "serve", "--port", str(port)],
        env=_env(tmp_path),
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
    )
    try:
        deadline = time.monotonic() + 20
        while True:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/health") as reply:
                    assert json.load(reply)["status"] == "ok"
                    break
            except OSError:
                assert server.poll() is None, server.stdout.read() if server.stdout else ""
                assert time.monotonic() < deadline, "server did not answer within 20 s"
                time.sleep(0.2)
    finally:
        server.terminate()
        server.wait(timeout=10)
    assert (tmp_path / "data" / "nasaq.db").is_file()
