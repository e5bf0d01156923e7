"""The fuzz worker: a subprocess that runs cases through the pipeline until its input ends.

It is started by ``driver.Worker`` with its address space capped (``RLIMIT_AS``, 1 GB by
default): a case that asks for more gets ``MemoryError`` here and is a finding, and the machine
never swaps. Requests and answers are JSON lines: ``{"name", "language", "text", "profile"}`` in,
``{"ok": true}`` or ``{"ok": false, "type", "frame", "message", "trace"}`` out. ``frame`` is the
innermost frame in Nasaq's package (``nasaq/lang/scl/parse.py:412 in retype``), which with the
exception type names a distinct failure.
"""

from __future__ import annotations

import gc
import json
import resource
import sys
import traceback
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def nasaq_frame(error: BaseException) -> str:
    """The innermost traceback frame inside the ``nasaq`` package (else the innermost one)."""
    frames = traceback.extract_tb(error.__traceback__)
    inside = [f for f in frames if "/nasaq/" in f.filename.replace("\\", "/")]
    frame = (inside or frames or [None])[-1]
    if frame is None:
        return "?"
    path = frame.filename.replace("\\", "/")
    path = "nasaq/" + path.split("/nasaq/", 1)[1] if "/nasaq/" in path else Path(path).name
    return f"{path}:{frame.lineno} in {frame.name}"


def main() -> None:
    limit = int(sys.argv[1]) if len(sys.argv) > 1 else 1 << 30
    if limit > 0:
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    from pipeline import run_pipeline  # after the limit: the imports count too

    for name, language in (("warm.awl", "stl"), ("warm.scl", "scl"), ("warm.lad", "lad")):
        run_pipeline(name, language, "", "S7-300")  # builds the parsers before the clock runs
    gc.collect()
    gc.freeze()  # the parsers and tables live forever: collections need not walk them
    out = sys.stdout
    out.write(json.dumps({"ready": True}) + "\n")
    out.flush()
    for line in sys.stdin:
        request = json.loads(line)
        text = request["text"]
        answer: dict[str, object]
        try:
            run_pipeline(
                request["name"],
                request["language"],
                text,
                request["profile"],
                request.get("conversions", True),
            )
            answer = {"ok": True}
        except BaseException as error:
            answer = {
                "ok": False,
                "type": type(error).__name__,
                "frame": nasaq_frame(error),
                "message": str(error)[:300] if not isinstance(error, RecursionError) else "",
                "trace": "".join(traceback.format_exception(error, limit=-12))[-4000:],
            }
            del error
        out.write(json.dumps(answer) + "\n")
        out.flush()


if __name__ == "__main__":
    main()
