"""Run ASAM's ``asam-qc-opendrive`` on many files in one process of its own virtual environment.

The environment is ``$ASAM_VENV`` (default ``<repo>/.venv-asam``; ``scripts/setup`` creates it). The bundle's own
command takes one file per call and spends about 2 s starting up, so :func:`run_asam_many` runs the bundle's checks
(``qc_opendrive.main.run_checks``, exactly as ``qc_opendrive -c`` runs them) over a batch of files in one worker
process (``_asam_worker.py``) and reads each file's ``result.xqar`` with :mod:`benchmarks.asam_qc`.
"""

from __future__ import annotations

import os
import subprocess
from dataclasses import dataclass
from pathlib import Path

from benchmarks.asam_qc import AsamIssue, checker_statuses, config_text, read_result

REPO = Path(__file__).resolve().parents[2]
WORKER = Path(__file__).with_name("_asam_worker.py")


class AsamUnavailable(RuntimeError):
    """There is no ASAM virtual environment where the harness looks for it."""


@dataclass(frozen=True)
class AsamReport:
    """ASAM's verdict on one file: its issues and each checker's status (completed / skipped / error)."""

    path: Path
    issues: tuple[AsamIssue, ...]
    statuses: dict[str, str]

    @property
    def errors(self) -> tuple[AsamIssue, ...]:
        return tuple(i for i in self.issues if i.is_error)

    @property
    def failed_checkers(self) -> tuple[str, ...]:
        return tuple(sorted(c for c, status in self.statuses.items() if status == "error"))


def asam_python() -> Path:
    """The ASAM environment's interpreter; raises :class:`AsamUnavailable` naming how to create it."""
    venv = Path(os.environ.get("ASAM_VENV", REPO / ".venv-asam"))
    python = venv / "bin" / "python"
    if not (venv / "bin" / "qc_opendrive").is_file() or not python.is_file():
        raise AsamUnavailable(
            f"asam-qc-opendrive not found in {venv}: run scripts/setup (it creates .venv-asam with "
            "asam-qc-opendrive==1.0.0), or set ASAM_VENV to an environment that has it"
        )
    return python


class AsamRun:
    """ASAM running over a batch of files in ``workers`` background processes; :meth:`reports` waits for them."""

    def __init__(self, paths: list[Path], work: Path, workers: int = 2) -> None:
        python = asam_python()
        work.mkdir(parents=True, exist_ok=True)
        self.paths = list(paths)
        self.results: list[Path] = []
        configs = []
        for n, path in enumerate(self.paths):
            result = work / f"{n}-{path.stem}.xqar"
            config = work / f"{n}-{path.stem}.config.xml"
            config.write_text(config_text(path, result), encoding="utf-8")
            result.unlink(missing_ok=True)
            configs.append(config)
            self.results.append(result)
        # largest files first, dealt round-robin, so the workers finish at about the same time
        order = sorted(range(len(configs)), key=lambda n: -self.paths[n].stat().st_size)
        batches = [[configs[n] for n in order[w::workers]] for w in range(workers)]
        self.procs = [
            subprocess.Popen(
                [str(python), "-I", str(WORKER), *map(str, batch)],
                cwd=work,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE,
                text=True,
            )
            for batch in batches
            if batch
        ]

    def reports(self, timeout: float = 900) -> dict[Path, AsamReport]:
        """ASAM's report on each file (waits for the workers)."""
        errors = []
        for proc in self.procs:
            try:
                _, err = proc.communicate(timeout=timeout)
            except subprocess.TimeoutExpired:
                proc.kill()
                _, err = proc.communicate()
            errors.append("\n".join(err.strip().splitlines()[-5:]))
        out = {}
        for path, result in zip(self.paths, self.results):
            if not result.is_file():
                codes = [p.returncode for p in self.procs]
                raise RuntimeError(f"asam-qc-opendrive wrote no result for {path} (exits {codes}): {errors}")
            out[path] = AsamReport(path, tuple(read_result(result, path)), checker_statuses(result))
        return out


def run_asam_many(paths: list[Path], work: Path, workers: int = 2) -> dict[Path, AsamReport]:
    """ASAM's report on each of ``paths`` (config and result files go to the folder ``work``)."""
    return AsamRun(paths, work, workers).reports()
