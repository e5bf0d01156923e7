"""Reading source files from disk and compiling them, shared by ``nasaq run`` and ``nasaq test``."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from nasaq.diagnostics import Diagnostic
from nasaq.lang.stl import CompileResult, SourceFile, compile_sources

MAX_SOURCE_BYTES = 64 * 1024 * 1024


class SourceError(Exception):
    """A source that cannot be read at all (missing, a folder, too large)."""


def read_source(path: Path) -> SourceFile:
    """Reads a source as STEP 7 writes it: UTF-8, or Windows-1252 (what STEP 7 exports) if not."""
    try:
        if path.stat().st_size > MAX_SOURCE_BYTES:
            raise SourceError(f"{path}: larger than {MAX_SOURCE_BYTES // (1024 * 1024)} MB")
        raw = path.read_bytes()
    except OSError as exc:
        raise SourceError(f"{path}: {exc.strerror or exc}") from exc
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = raw.decode("cp1252", errors="replace")
    return SourceFile(name=str(path), text=text)


def compile_files(
    paths: Sequence[Path], mnemonics: str = "auto", test_ops: bool = False, profile: str = "S7-300"
) -> CompileResult:
    """Compiles ``paths`` for the CPU family ``profile`` (``nasaq.lang.profiles``)."""
    return compile_sources(
        [read_source(path) for path in paths],
        mnemonics=mnemonics,
        test_ops=test_ops,
        profile=profile,
    )


def diagnostic_line(diagnostic: Diagnostic) -> str:
    """``file:line:column: code: message``, the form editors and CI logs link to."""
    span = diagnostic.span
    where = ":".join(
        str(part)
        for part in (
            span.file if span else None,
            span.line if span else None,
            span.column if span else None,
        )
        if part is not None
    )
    return f"{where or '<program>'}: {diagnostic.code}: {diagnostic.message}"
