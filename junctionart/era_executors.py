"""Where the expressive range analysis (:mod:`junctionart.era`) and the search (:mod:`junctionart.search`) run their
work: local processes (:class:`Local`, ``concurrent.futures.ProcessPoolExecutor``) or a Dask cluster (:class:`Dask`,
the ``[dask]`` extra), behind one ``submit`` / ``wait_first`` pair and :meth:`Executor.map_ordered`."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor
from concurrent.futures import wait as _wait
from typing import Any

from .errors import ParamsError


class Executor:
    """What both executors share on top of their ``submit`` / ``wait_first``."""

    def submit(self, fn, *args):
        raise NotImplementedError

    def wait_first(self, pending):
        raise NotImplementedError

    def map_ordered(self, fn: Callable[..., Any], calls: Iterable[tuple], bar: Any = None) -> list[Any]:
        """``[fn(*args) for args in calls]`` on the workers: every call submitted at once, the results in the order
        of ``calls`` whatever order they finish in; ``bar`` (a tqdm bar or None) ticks once per finished call."""
        pending = {self.submit(fn, *args): k for k, args in enumerate(calls)}
        out: list[Any] = [None] * len(pending)
        while pending:
            done, _ = self.wait_first(pending)
            for future in done:
                out[pending.pop(future)] = future.result()
                if bar is not None:
                    bar.update(1)
        return out


class Local(Executor):
    def __init__(self, jobs: int):
        self.pool = ProcessPoolExecutor(max_workers=jobs)
        self.width = jobs

    def submit(self, fn, *args):
        return self.pool.submit(fn, *args)

    def wait_first(self, pending):
        return _wait(pending, return_when=FIRST_COMPLETED)

    def close(self):
        self.pool.shutdown(wait=True, cancel_futures=True)


class Dask(Executor):
    def __init__(self, address):
        try:
            from distributed import Client
        except ImportError:
            raise ParamsError("--scheduler needs dask: pip install 'junctionart[dask]'") from None
        try:
            self.client = address if isinstance(address, Client) else Client(address, timeout=30)
        except (OSError, TimeoutError) as exc:
            raise ParamsError(f"--scheduler {address}: cannot connect ({exc})") from None
        self.owned = not isinstance(address, Client)
        self.width = max(sum(self.client.nthreads().values()), 1)

    def submit(self, fn, *args):
        return self.client.submit(fn, *args, pure=False)

    def wait_first(self, pending):
        from distributed import wait

        return wait(list(pending), return_when="FIRST_COMPLETED")

    def close(self):
        if self.owned:
            self.client.close()
