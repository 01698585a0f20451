"""Where a campaign's runs execute: in this process, in a local process pool, or on a Ray cluster.

Every executor takes the same picklable tasks and the same module-level worker function and yields results as
they finish (in completion order; the store, not the order, is what is compared). A run is a pure function of its
task, so the results are the same whatever the executor. In-flight work is bounded so memory stays flat on long
campaigns.
"""

from __future__ import annotations

import multiprocessing as mp
import os
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from typing import Any, Callable, Iterable, Iterator, TypeVar

from ..errors import InputError

T = TypeVar("T")
R = TypeVar("R")

EXECUTORS = ("serial", "pool", "ray")


def run_tasks(fn: Callable[[T], R], tasks: Iterable[T], *, executor: str = "pool", workers: int | None = None,
              ray_address: str | None = None) -> Iterator[R]:
    """Apply `fn` to every task with the chosen executor, yielding results as they complete."""
    workers = workers or max(1, os.cpu_count() or 1)
    if executor == "serial" or (executor == "pool" and workers == 1):
        for task in tasks:
            yield fn(task)
    elif executor == "pool":
        yield from _pool(fn, tasks, workers)
    elif executor == "ray":
        yield from _ray(fn, tasks, workers, ray_address)
    else:
        raise InputError(f"unknown executor {executor!r}; choose one of {', '.join(EXECUTORS)}")


def _pool(fn: Callable[[T], R], tasks: Iterable[T], workers: int) -> Iterator[R]:
    # fork: the cores import no rclpy and hold no threads, so children start in milliseconds.
    ctx = mp.get_context("fork")
    limit = workers * 4
    with ProcessPoolExecutor(max_workers=workers, mp_context=ctx) as pool:
        pending: set[Future[R]] = set()
        it = iter(tasks)
        exhausted = False
        while pending or not exhausted:
            while not exhausted and len(pending) < limit:
                try:
                    pending.add(pool.submit(fn, next(it)))
                except StopIteration:
                    exhausted = True
            if not pending:
                break
            done, pending = wait(pending, return_when=FIRST_COMPLETED)
            for fut in done:
                yield fut.result()


def _ray(fn: Callable[[T], R], tasks: Iterable[T], workers: int, address: str | None) -> Iterator[R]:
    try:
        import ray
    except ImportError as exc:  # pragma: no cover - ray is in requirements-dev
        raise InputError("--executor ray needs the 'ray' package (pip install ray)") from exc
    started_here = False
    if not ray.is_initialized():
        address = address or os.environ.get("RAY_ADDRESS")
        kwargs: dict[str, Any] = {"include_dashboard": False, "log_to_driver": False}
        if address:
            ray.init(address=address, **kwargs)
        else:
            ray.init(num_cpus=workers, **kwargs)
        started_here = True
    try:
        remote = ray.remote(fn)
        limit = workers * 4
        pending: list[Any] = []
        it = iter(tasks)
        exhausted = False
        while pending or not exhausted:
            while not exhausted and len(pending) < limit:
                try:
                    pending.append(remote.remote(next(it)))
                except StopIteration:
                    exhausted = True
            if not pending:
                break
            done, pending = ray.wait(pending, num_returns=1)
            for ref in done:
                yield ray.get(ref)
    finally:
        if started_here:
            ray.shutdown()
