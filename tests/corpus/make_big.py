#!/usr/bin/env python3
"""Write a 10 MB STL source for the bad-input corpus (never committed: generated at test time).

Usage: python tests/corpus/make_big.py [OUTPUT_DIR]  ->  prints the path of the file written.

The file is one syntactically valid ORGANIZATION_BLOCK OB 1 of about 10 MB (some 350 000
instructions in about 70 000 networks). An S7-300/400 code block is limited to 64 KB of MC7
code, so a correct tool must refuse it with a clear size diagnostic (block or source too
large), quickly and without running out of memory (see expected.yaml, entry big_ob1.awl).
The content is deterministic.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

TARGET_BYTES = 10 * 1024 * 1024


def write_big(out_dir: Path) -> Path:
    out_dir.mkdir(parents=True, exist_ok=True)
    path = out_dir / "big_ob1.awl"
    header = (
        "ORGANIZATION_BLOCK OB 1\r\nTITLE = 10 MB generated block\r\nVERSION : 0.1\r\n\r\nBEGIN\r\n"
    )
    footer = "END_ORGANIZATION_BLOCK\r\n"
    size = len(header) + len(footer)
    n = 0
    with path.open("w", encoding="ascii", newline="") as f:
        f.write(header)
        while size < TARGET_BYTES:
            byte, bit = divmod(n, 8)
            net = (
                f"NETWORK\r\nTITLE = generated network {n}\r\n"
                f"      A     I    {byte % 128}.{bit};\r\n"
                f"      AN    M    {byte % 1000}.{bit};\r\n"
                f"      O     M    {(byte + 1) % 1000}.{bit};\r\n"
                f"      =     Q    {byte % 128}.{bit};\r\n"
                f"      L     MW   {(2 * n) % 1000};\r\n"
            )
            f.write(net)
            size += len(net)
            n += 1
        f.write(footer)
    return path


def main() -> None:
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="nasaq-big-"))
    print(write_big(out))


if __name__ == "__main__":
    main()
