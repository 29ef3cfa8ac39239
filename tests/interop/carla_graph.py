"""Ask CARLA's map API (``carla`` 0.9.16, in ``.venv-carla``) where lanes lead, in a separate process.

:func:`carla_walk` hands the worker (``_carla_graph_worker.py``) lane ends to step past with ``Waypoint.next`` and a
route to walk waypoint by waypoint; CARLA can segfault on a bad map, so it never runs in the test process.
"""

from __future__ import annotations

import json
import subprocess
import tempfile
from pathlib import Path

from tests.interop.carla_harness import carla_python

WORKER = Path(__file__).with_name("_carla_graph_worker.py")


def carla_walk(xodr_path: str | Path, request: dict, timeout: float = 300) -> dict:
    """CARLA's answer to ``request`` (see the worker's docstring); raises ``RuntimeError`` when CARLA fails."""
    python = carla_python()
    with tempfile.TemporaryDirectory(prefix="carla-graph-") as tmp:
        asked, out = Path(tmp) / "request.json", Path(tmp) / "answer.json"
        asked.write_text(json.dumps(request), encoding="utf-8")
        proc = subprocess.run(
            [str(python), "-I", str(WORKER), str(Path(xodr_path).resolve()), str(asked), str(out)],
            check=False,
            capture_output=True,
            text=True,
            timeout=timeout,
            stdin=subprocess.DEVNULL,
        )
        if proc.returncode != 0 or not out.is_file():
            raise RuntimeError(f"CARLA worker exited {proc.returncode}: {proc.stderr.strip()[-2000:]}")
        return json.loads(out.read_text(encoding="utf-8"))
