"""A project as a zip of plain sources: one folder named after the project, one file per source.

Reading an upload is defensive, since a zip says little truthful about itself before it is
unpacked: at most ``MAX_ENTRIES`` entries and ``MAX_UNPACKED_BYTES`` unpacked (counted while
reading, not taken from the headers, so a zip bomb stops at the limit), no entry with an absolute
path or ``..``. What is not a source (a README, the scenario files) is skipped and reported;
sub-folders are flattened, as a project is one flat list of files.
"""

from __future__ import annotations

import io
import re
import zipfile
import zlib
from collections.abc import Iterable
from dataclasses import dataclass, field
from datetime import UTC, datetime
from typing import Any

from nasaq.workbench.names import MAX_FILES, MAX_TEXT_CHARS, is_valid_name

MAX_UPLOAD_BYTES = 32 * 1024 * 1024
MAX_UNPACKED_BYTES = 64 * 1024 * 1024
MAX_ENTRIES = 2000
_CHUNK = 64 * 1024
_JUNK = re.compile(r"(^|/)(__MACOSX|\.DS_Store|Thumbs\.db|desktop\.ini)(/|$)", re.IGNORECASE)


class ArchiveError(Exception):
    """An upload refused with catalogue ``code`` (``API1xx``) and its parameters."""

    def __init__(self, code: str, **params: Any) -> None:
        super().__init__(code)
        self.code = code
        self.params = params


@dataclass(slots=True)
class Unpacked:
    folder: str | None  # the one top folder all files are in, if there is one
    files: list[tuple[str, str]] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)


def folder_name(project_name: str) -> str:
    """The export's folder: the project's name (names never hold path characters), unless it is
    nothing but dots, which an unzip tool would read as a relative path."""
    return project_name if project_name.strip(". ") else "project"


def write_zip(folder: str, files: Iterable[tuple[str, str, datetime]]) -> bytes:
    """``files`` as (name, text, last change) under ``folder/``; the zip's times are UTC."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, text, changed in files:
            stamp = changed.astimezone(UTC).timetuple()[:6]
            info = zipfile.ZipInfo(f"{folder}/{name}", date_time=max(stamp, (1980, 1, 1, 0, 0, 0)))
            info.compress_type = zipfile.ZIP_DEFLATED
            archive.writestr(info, text.encode("utf-8"))
    return buffer.getvalue()


def _decode(data: bytes) -> str:
    """UTF-8 (a byte order mark dropped), else Windows-1252 as STEP 7 writes its sources."""
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("cp1252", errors="replace")


def _unsafe(path: str) -> bool:
    return (
        path.startswith("/")
        or re.match(r"[A-Za-z]:", path) is not None
        or ".." in path.split("/")
        or "\x00" in path
    )


class _Reader:
    def __init__(self, archive: zipfile.ZipFile) -> None:
        self.archive = archive
        self.unpacked = 0

    def read(self, info: zipfile.ZipInfo) -> bytes:
        parts: list[bytes] = []
        with self.archive.open(info) as stream:
            while chunk := stream.read(_CHUNK):
                self.unpacked += len(chunk)
                if self.unpacked > MAX_UNPACKED_BYTES:
                    raise _too_large()
                parts.append(chunk)
        return b"".join(parts)


def _too_large() -> ArchiveError:
    return ArchiveError(
        "API114", limit_mb=MAX_UNPACKED_BYTES // (1024 * 1024), limit_entries=MAX_ENTRIES
    )


def _entries(archive: zipfile.ZipFile) -> list[tuple[zipfile.ZipInfo, str]]:
    infos = archive.infolist()
    if len(infos) > MAX_ENTRIES:
        raise _too_large()
    entries: list[tuple[zipfile.ZipInfo, str]] = []
    for info in infos:
        path = info.filename.replace("\\", "/")
        if _unsafe(path):
            raise ArchiveError("API113", entry=info.filename)
        if not info.is_dir() and not path.endswith("/") and _JUNK.search(path) is None:
            entries.append((info, path))
    if sum(info.file_size for info, _ in entries) > MAX_UNPACKED_BYTES:
        raise _too_large()
    return entries


def read_zip(data: bytes) -> Unpacked:
    """The sources of an uploaded zip; :class:`ArchiveError` when it is refused."""
    try:
        archive = zipfile.ZipFile(io.BytesIO(data))
    except (zipfile.BadZipFile, ValueError, OSError) as exc:
        raise ArchiveError("API112") from exc
    with archive:
        entries = _entries(archive)
        tops = {path.split("/")[0] for _, path in entries}
        nested = all("/" in path for _, path in entries)
        folder = next(iter(tops)) if len(tops) == 1 and nested else None
        found = Unpacked(folder)
        seen: set[str] = set()
        reader = _Reader(archive)
        for info, path in entries:
            name = path.rsplit("/", 1)[-1]
            if not is_valid_name(name):
                found.skipped.append(path)
                continue
            if name.lower() in seen:
                raise ArchiveError("API108", name=name)
            seen.add(name.lower())
            try:
                text = _decode(reader.read(info))
            except (zipfile.BadZipFile, zlib.error, NotImplementedError, RuntimeError) as exc:
                raise ArchiveError("API112") from exc  # corrupt data, unknown method, encrypted
            if len(text) > MAX_TEXT_CHARS:
                size = {"size_kb": len(text) // 1024, "limit_kb": MAX_TEXT_CHARS // 1024}
                raise ArchiveError("API110", name=name, **size)
            found.files.append((name, text))
    if not found.files:
        raise ArchiveError("API116")
    if len(found.files) > MAX_FILES:
        raise ArchiveError("API117", limit=MAX_FILES)
    return found
