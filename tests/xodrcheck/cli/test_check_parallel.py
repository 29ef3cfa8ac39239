"""``xodrcheck check -j N`` and ``--scheduler``: the same report, errors and exit code as the serial run, in the order
the files were given."""

from __future__ import annotations

import io
import shutil
from pathlib import Path

import pytest

from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.cli import main
from xodrcheck.support.batch import Outcome, check_files

FILES = [
    fixture("road-link-target-missing", "fail.xodr"),
    fixture("link-not-reciprocal", "pass.xodr"),
    fixture("lane-link-missing-lane", "fail_dangling.xodr"),
    fixture("road-overlap", "fail.xodr"),
    fixture("lane-fold", "fail.xodr"),
    fixture("connection-lanes-cross", "fail.xodr"),
]


@pytest.fixture
def folder(tmp_path: Path, monkeypatch) -> Path:
    """A folder of maps, one of them unreadable, named so that sorting puts the small files first."""
    home = tmp_path / "cwd"
    home.mkdir()
    monkeypatch.chdir(home)  # no project configuration
    maps = tmp_path / "maps"
    maps.mkdir()
    for n, path in enumerate(FILES):
        shutil.copy(path, maps / f"m{n:02d}_{path.parent.name}_{path.name}")
    (maps / "m99_truncated.xodr").write_bytes(FILES[0].read_bytes()[:300])
    (maps / "m50_empty.xodr").write_bytes(b"")
    return maps


def run(capsys, *args) -> tuple[int, str, str]:
    code = main(["check", *map(str, args)])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("fmt", ["text", "json"])
def test_parallel_report_is_the_serial_report(capsys, folder: Path, fmt: str):
    serial = run(capsys, folder, "-j", "1", "--format", fmt)
    parallel = run(capsys, folder, "-j", "2", "--format", fmt)
    assert parallel == serial
    code, out, err = serial
    assert code == 1 and out  # errors found; the empty file is a finding, not a crash
    assert "Traceback" not in err


def test_outcomes_come_in_the_order_given(folder: Path):
    paths = sorted(str(p) for p in folder.iterdir())[::-1]  # largest-first scheduling must not reorder them
    outcomes = check_files(paths, jobs=2)
    assert [o.path for o in outcomes] == paths
    assert [o.report.path if o.report else None for o in outcomes] == [o.path if o.report else None for o in outcomes]
    assert outcomes == check_files(paths, jobs=1)


def test_an_unreadable_path_is_one_error_line_in_order(capsys, folder: Path, tmp_path: Path):
    missing = tmp_path / "nope.xodr"
    code, out, err = run(capsys, FILES[1], missing, FILES[0], "-j", "2")
    assert code == 2
    first = err.splitlines()[0]
    assert first.startswith(f"xodrcheck: cannot read {missing}") and "Traceback" not in err
    assert "R010" in out  # the file after it is still checked


def test_jobs_must_be_positive(capsys, folder: Path):
    with pytest.raises(SystemExit) as exc:
        main(["check", str(folder), "-j", "0"])
    assert exc.value.code == 2
    assert "at least 1" in capsys.readouterr().err


def test_progress_bar_goes_to_stderr(folder: Path, monkeypatch):
    stream = io.StringIO()
    monkeypatch.setattr("sys.stderr", stream)
    outcomes = check_files(sorted(folder.iterdir()), jobs=1, progress=True)
    assert len(outcomes) == len(list(folder.iterdir()))
    shown = stream.getvalue()
    assert f"0/{len(outcomes)}" in shown and "xodrcheck:" in shown and "%|" in shown  # tqdm throttles the rest


def test_dask_local_cluster_gives_the_serial_outcomes(folder: Path):
    try:
        import distributed
    except ImportError:  # the extra is optional for users, not for the suite
        pytest.fail("dask.distributed is missing: install the [dask] extra (scripts/setup does)")
    paths = sorted(str(p) for p in folder.iterdir())
    serial = check_files(paths, jobs=1)
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        on_dask = check_files(paths, scheduler=client)
        by_address = check_files(paths, scheduler=cluster.scheduler_address)
    assert on_dask == serial and by_address == serial
    assert all(isinstance(o, Outcome) for o in on_dask)


def test_scheduler_nobody_listens_at_is_one_error_line(capsys, folder: Path):
    code, out, err = run(capsys, folder, "--scheduler", "tcp://127.0.0.1:9")
    assert code == 2 and out == ""
    assert "--scheduler" in err and "Traceback" not in err
