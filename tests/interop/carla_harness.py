"""Load a map with CARLA's OpenDRIVE parser (``carla`` 0.9.16) in a separate process and bring back its waypoints.

CARLA is an independent reader: a map that loads in CARLA and whose lane centres agree with ours is evidence for both
the map and our reader. CARLA can segfault on a bad map, so it never runs in the test process: it runs in the
interpreter named by ``$CARLA_PYTHON`` (default ``<repo>/.venv-carla/bin/python``, which ``.ci/run`` creates).
"""

from __future__ import annotations

import json
import os
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
WORKER = Path(__file__).with_name("_carla_worker.py")


class CarlaUnavailable(RuntimeError):
    """There is no interpreter with ``carla`` installed where the harness looks for it."""


@dataclass(frozen=True)
class CarlaPoint:
    """A CARLA waypoint in OpenDRIVE's frame (y and heading turned back from CARLA's left-handed frame)."""

    road_id: str
    section_id: int
    lane_id: int
    s: float
    x: float
    y: float
    z: float
    hdg: float


@dataclass(frozen=True)
class CarlaResult:
    """What CARLA made of a map. ``loaded`` is False when CARLA raised, crashed or timed out; ``returncode`` is the
    worker's exit code (negative: killed by that signal, e.g. -11 for a segfault; None: timed out)."""

    loaded: bool
    returncode: int | None
    error: str
    waypoints: tuple[CarlaPoint, ...] = ()
    topology: tuple[tuple[CarlaPoint, CarlaPoint], ...] = ()
    #: ``Map.get_all_landmarks()``: (signal id, type, road id) of each landmark (a signal as CARLA read it)
    landmarks: tuple[tuple[str, str, str], ...] = ()
    #: the waypoints of each ring walk asked for (``_carla_worker.py``), in the order asked
    walks: tuple[tuple[CarlaPoint, ...], ...] = ()

    @property
    def crashed(self) -> bool:
        return self.returncode is not None and self.returncode < 0


def carla_python() -> Path:
    """The interpreter that has ``carla``; raises :class:`CarlaUnavailable` naming how to get one."""
    python = Path(os.environ.get("CARLA_PYTHON", REPO / ".venv-carla" / "bin" / "python"))
    if not python.is_file():
        raise CarlaUnavailable(
            f"no CARLA interpreter at {python}: run .ci/run (it creates .venv-carla with carla==0.9.16, as does the "
            "README's set-up command), or set CARLA_PYTHON to a python that has carla installed"
        )
    return python


def _tail(text: str, lines: int = 5) -> str:
    return "\n".join(text.strip().splitlines()[-lines:])


def carla_waypoints(
    xodr_path: str | os.PathLike, distance: float = 2.0, timeout: float = 60, walks: list[dict] | None = None
) -> CarlaResult:
    """Waypoints every ``distance`` metres on every driving lane of the map, and CARLA's lane topology; with
    ``walks``, a waypoint walk round a ring for each (``_carla_worker.py`` says what one asks for)."""
    python = carla_python()
    with tempfile.TemporaryDirectory(prefix="carla-") as tmp:
        out = Path(tmp) / "result.json"
        command = [str(python), "-I", str(WORKER), str(Path(xodr_path).resolve()), repr(float(distance)), str(out)]
        if walks:
            (Path(tmp) / "walks.json").write_text(json.dumps(walks), encoding="utf-8")
            command.append(str(Path(tmp) / "walks.json"))
        try:
            proc = subprocess.run(
                command,
                check=False,
                capture_output=True,
                text=True,
                timeout=timeout,
                stdin=subprocess.DEVNULL,
            )
        except subprocess.TimeoutExpired:
            return CarlaResult(False, None, f"CARLA did not finish within {timeout:g} s")
        if proc.returncode != 0 or not out.is_file():
            return CarlaResult(False, proc.returncode, _tail(proc.stderr) or f"worker exited {proc.returncode}")
        data = json.loads(out.read_text(encoding="utf-8"))
    return CarlaResult(
        loaded=True,
        returncode=0,
        error=_tail(proc.stderr),
        waypoints=tuple(CarlaPoint(**p) for p in data["waypoints"]),
        topology=tuple((CarlaPoint(**a), CarlaPoint(**b)) for a, b in data["topology"]),
        landmarks=tuple(tuple(m) for m in data.get("landmarks", ())),
        walks=tuple(tuple(CarlaPoint(**p) for p in walk) for walk in data.get("walks", ())),
    )
