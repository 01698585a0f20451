"""Where a campaign's runs execute: in this process, in a local process pool, or on a Ray cluster.

Every executor takes the same picklable tasks and the same module-level worker function and yields results as
they finish (in completion order; the store, not the order, is what is compared). A run is a pure function of its
task, so the results are the same whatever the executor. In-flight work is bounded so memory stays flat on long
campaigns, and tasks are drawn from the iterable only as they are submitted (a lazy iterable keeps the driver small).
Ray specifics (which cluster, shared parts in the object store) live in `ray_cluster.py`.
"""

from __future__ import annotations

import gc
import multiprocessing as mp
import os
import signal
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from typing import Any, Callable, Hashable, Iterable, Iterator, Protocol, TypeVar

from ..errors import InputError
from ..lifeline import die_with_parent

T = TypeVar("T")
R = TypeVar("R")

EXECUTORS = ("serial", "pool", "ray")

#: Tasks in flight per worker process on the pool (Ray sizes from the cluster's CPUs: `ray_cluster`).
IN_FLIGHT_PER_WORKER = 4

#: The pool workers' first-generation threshold of the garbage collector (CPython's default: 700). A closed-loop
#: run makes ~100 container objects a step and almost no cycles: at 700 the collector ran ~5 times a run for ~2 %
#: of its CPU; at 10,000 under 0.5 %, memory flat. (Off altogether was slower in session 8: memory growth.)
WORKER_GC_GEN0 = 10_000


class SharesPart(Protocol):
    """A task with a large part other tasks share (a run's map). Ray ships the part once per key through its object
    store; the other executors ship the task whole."""

    def shared_part(self) -> tuple[Hashable, Any, "SharesPart"]:
        """(key naming the part, the part, this task without it)."""
        ...

    def with_shared(self, part: Any) -> "SharesPart":
        """This task with the part put back (called on the worker)."""
        ...


def run_tasks(fn: Callable[[T], R], tasks: Iterable[T], *, executor: str = "pool", workers: int | None = None,
              ray_address: str | None = None, note: Callable[[str], None] = lambda _: None) -> Iterator[R]:
    """Apply `fn` to every task with the chosen executor, yielding results as they complete.

    `workers`: processes of the pool, CPUs of a Ray instance started here (a running cluster brings its own);
    `ray_address`: the cluster to use (`ray_cluster.find_address`); `note`: one-line messages (which cluster)."""
    workers = workers or max(1, os.cpu_count() or 1)
    if executor == "serial" or (executor == "pool" and workers == 1):
        for task in tasks:
            yield fn(task)
    elif executor == "pool":
        yield from _pool(fn, tasks, workers)
    elif executor == "ray":
        from .ray_cluster import run_on_ray

        yield from run_on_ray(fn, tasks, workers=workers, address=ray_address, note=note)
    else:
        raise InputError(f"unknown executor {executor!r}; choose one of {', '.join(EXECUTORS)}")


def _worker_start(sig: int, parent: int) -> None:
    """A pool worker's set-up: it dies with the campaign process (however that dies: no orphan keeps running, or
    holding a DDS domain); what it inherited from the driver is frozen out of the collector's sweeps (the worker
    never frees it), and the collector runs less often (`WORKER_GC_GEN0`)."""
    die_with_parent(sig, parent)
    gc.freeze()
    gc.set_threshold(WORKER_GC_GEN0, *gc.get_threshold()[1:])


def _pool(fn: Callable[[T], R], tasks: Iterable[T], workers: int) -> Iterator[R]:
    # fork: the cores import no rclpy and hold no threads, so children start in milliseconds.
    ctx = mp.get_context("fork")
    limit = workers * IN_FLIGHT_PER_WORKER
    with ProcessPoolExecutor(max_workers=workers, mp_context=ctx, initializer=_worker_start,
                             initargs=(signal.SIGTERM, os.getpid())) as pool:
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
