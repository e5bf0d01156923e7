"""Gathers the corpus that ``corpus.py`` measures: real STEP 7 / TIA Portal sources from public
repositories.

The sources are other people's work, so they are never committed: this script clones each
repository listed in ``corpus_repos.txt`` (``owner/name commit`` per line) into a temporary
folder, and copies its source files into ``DEST/<owner>+<name>/<path>``, the layout
``corpus.py`` reads. A file whose content was already copied from an earlier repository is
skipped (forks and copied libraries would otherwise count twice).

    python tests/conformance/corpus_gather.py ~/nasaq-corpus
    NASAQ_CORPUS=~/nasaq-corpus make conformance

``--git-dir`` reads bare repositories already on disk instead of cloning (a template such as
``/mirrors/{owner}+{name}.git``), for machines without network access.
"""

from __future__ import annotations

import argparse
import hashlib
import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPOS = HERE / "corpus_repos.txt"

SOURCE_SUFFIXES = (".scl", ".awl", ".stl", ".db", ".udt")
SYMBOL_SUFFIXES = (".sdf", ".asc", ".seq")
MAX_BYTES = 4 * 1024 * 1024
# A STEP 7 source names at least one block; ``.scl`` is also IEC 61850's XML and ``.stl`` a 3D
# mesh format, ``.db`` often SQLite: those have none of these words and are left out.
BLOCK_WORDS = (
    b"FUNCTION",
    b"ORGANIZATION_BLOCK",
    b"DATA_BLOCK",
    b"TYPE",
    b"BAUSTEIN",
    b"DATENBAUSTEIN",
)

# Code generators' templates (``@@MODULE@@``, ``{{name}}``) are not sources anyone compiles.
TEMPLATE = re.compile(rb"@@[A-Z_]+@@|\{\{[^}]*\}\}")


@dataclass(frozen=True)
class Repo:
    owner: str
    name: str
    commit: str

    @property
    def folder(self) -> str:
        return f"{self.owner}+{self.name}"


def read_list(path: Path) -> list[Repo]:
    """``owner/name commit`` per line; ``#`` starts a comment."""
    repos = []
    for line in path.read_text(encoding="utf-8").splitlines():
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        owner, name = words[0].split("/", 1)
        repos.append(Repo(owner, name, words[1] if len(words) > 1 else "HEAD"))
    return repos


def is_source(path: str, data: bytes) -> bool:
    """Whether a file is a STEP 7 source or symbol table (by suffix, then by content)."""
    lower = path.lower()
    if not lower.endswith(SOURCE_SUFFIXES + SYMBOL_SUFFIXES) or len(data) > MAX_BYTES:
        return False
    if b"\0" in data[:8192]:
        return False
    if lower.endswith(SYMBOL_SUFFIXES):
        # STEP 7's .asc export: fixed columns starting "126,"; .sdf/.seq: quoted/tabbed rows.
        return not lower.endswith(".asc") or data.lstrip().startswith(b"126,")
    head = data.lstrip(b"\xef\xbb\xbf \t\r\n")
    if head.startswith((b"<?xml", b"<", b"solid ")):
        return False
    if TEMPLATE.search(data):
        return False
    upper = data.upper()
    return any(word in upper for word in BLOCK_WORDS)


def git(git_dir: Path, *args: str) -> bytes:
    return subprocess.run(
        ["git", f"--git-dir={git_dir}", *args], check=True, capture_output=True
    ).stdout


def resolve_commit(git_dir: Path, commit: str) -> str:
    """The listed commit, or HEAD (with a warning) when the repository no longer has it."""
    try:
        return git(git_dir, "rev-parse", "--verify", f"{commit}^{{commit}}").decode().strip()
    except subprocess.CalledProcessError:
        print(f"  {commit} not found, using HEAD", file=sys.stderr)
        return git(git_dir, "rev-parse", "HEAD").decode().strip()


def copy_sources(git_dir: Path, commit: str, dest: Path, seen: set[str]) -> tuple[int, int]:
    """Copies the repository's sources at ``commit``; returns (copied, duplicates skipped)."""
    names = git(git_dir, "ls-tree", "-r", "-z", "--name-only", commit).split(b"\0")
    copied = duplicates = 0
    for raw in names:
        path = raw.decode("utf-8", errors="replace")
        if not path.lower().endswith(SOURCE_SUFFIXES + SYMBOL_SUFFIXES):
            continue
        try:
            data = git(git_dir, "cat-file", "blob", f"{commit}:{path}")
        except subprocess.CalledProcessError:
            continue  # a submodule or a file the snapshot lacks
        if not is_source(path, data):
            continue
        digest = hashlib.sha256(data).hexdigest()
        if digest in seen:
            duplicates += 1
            continue
        seen.add(digest)
        target = dest / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
        copied += 1
    return copied, duplicates


def clone(repo: Repo, folder: Path) -> Path:
    url = f"https://github.com/{repo.owner}/{repo.name}.git"
    target = folder / repo.folder
    subprocess.run(["git", "clone", "--quiet", "--bare", url, str(target)], check=True)
    return target


def gather(repos: list[Repo], dest: Path, git_dir_template: str | None) -> None:
    seen: set[str] = set()
    with tempfile.TemporaryDirectory() as temp:
        for repo in repos:
            if git_dir_template:
                git_dir = Path(git_dir_template.format(owner=repo.owner, name=repo.name))
                if (git_dir / ".git").is_dir():
                    git_dir = git_dir / ".git"
            else:
                try:
                    git_dir = clone(repo, Path(temp))
                except subprocess.CalledProcessError:
                    print(f"{repo.owner}/{repo.name}: clone failed", file=sys.stderr)
                    continue
            commit = resolve_commit(git_dir, repo.commit)
            copied, duplicates = copy_sources(git_dir, commit, dest / repo.folder, seen)
            print(f"{repo.owner}/{repo.name}: {copied} files ({duplicates} duplicates skipped)")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dest", type=Path, help="the corpus folder (set NASAQ_CORPUS to it)")
    parser.add_argument("--repos", type=Path, default=REPOS, help="owner/name commit per line")
    parser.add_argument("--git-dir", help="read bare repositories at this {owner}/{name} path")
    args = parser.parse_args(argv)
    gather(read_list(args.repos), args.dest, args.git_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
