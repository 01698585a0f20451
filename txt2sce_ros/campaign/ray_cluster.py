"""`--executor ray`: find the Ray cluster the way Ray users expect, ship self-contained tasks, bound in-flight work
by the cluster's CPUs.

Which cluster (the order `ray.init` itself uses, minus its guessing):
1. `--ray-address` (`address`), else 2. `RAY_ADDRESS`: connect there (`"local"` starts a private local instance);
3. else the cluster the last `ray start` on this machine recorded (`<RAY_TMPDIR|TMPDIR|/tmp>/ray/ray_current_cluster`,
   the file `ray.init()` reads): connect to it, so a driver on a head node started with `ray start --head` needs no
   address;
4. else start a local instance with `workers` CPUs and shut it down afterwards.
A cluster that cannot be reached, a version mismatch, or a worker that cannot import the project is one clear
`Txt2SceError`, never a traceback.

Tasks that share a large part (a campaign run's OpenDRIVE map: every node of a tree names the same one) can say so
(`executors.SharesPart`): the part is put into Ray's object store once per key and each task ships with a reference
that Ray resolves on the worker, so a map crosses the network once per node, not once per run.
"""

from __future__ import annotations

import logging
import os
import socket
import time
from pathlib import Path
from typing import Any, Callable, Hashable, Iterable, Iterator, TypeVar

from ..errors import InputError, SimulationFault, Txt2SceError

T = TypeVar("T")
R = TypeVar("R")

#: Tasks in flight per cluster CPU: enough that no worker waits for the driver between tasks.
IN_FLIGHT_PER_CPU = 4

#: Seconds between re-reads of the cluster's CPUs (nodes joining or leaving change how much to keep in flight).
RESIZE_EVERY = 5.0


def address_file() -> Path:
    """Where `ray start` records the cluster it started and `ray.init()` looks for it (Ray's default temp dir)."""
    base = os.environ.get("RAY_TMPDIR") or os.environ.get("TMPDIR") or "/tmp"
    return Path(base) / "ray" / "ray_current_cluster"


def find_address(address: str | None) -> tuple[str | None, str]:
    """(address to pass to `ray.init`, or None to start a local instance; where it came from). The cluster `ray
    start` recorded is passed as "auto", not as the address the file holds: only then does Ray present the token
    of a cluster with token authentication (`~/.ray/auth_token`), as a plain `ray.init()` on the head node would."""
    if address:
        return (None if address == "local" else address), "--ray-address"
    env = os.environ.get("RAY_ADDRESS", "").strip()
    if env:
        return (None if env == "local" else env), "RAY_ADDRESS"
    recorded = address_file()
    if recorded.is_file() and recorded.read_text(encoding="utf-8").strip():
        return "auto", f"the cluster `ray start` recorded in {recorded}"
    return None, "no running cluster found"


#: Seconds to wait for a cluster's GCS port to accept a connection (`ray.init` itself retries for many minutes).
PROBE_TIMEOUT = 10.0


def _probe(address: str, origin: str) -> None:
    """Fail fast, in one line, when nothing listens at a HOST:PORT address."""
    host, sep, port = address.rpartition(":")
    if not sep or not port.isdigit() or "://" in address:
        return                      # "auto", ray:// client addresses, malformed ones: ray.init says what is wrong
    try:
        socket.create_connection((host or "127.0.0.1", int(port)), timeout=PROBE_TIMEOUT).close()
    except OSError as exc:
        raise InputError(f"no Ray cluster answers at {address} ({origin}): {exc.strerror or exc}; start one with "
                         "`ray start --head` or give another address", source="--executor ray") from exc


def connect(ray: Any, address: str | None, workers: int, note: Callable[[str], None]) -> None:
    """`ray.init` on the cluster `find_address` picks, or on a new local instance of `workers` CPUs."""
    target, origin = find_address(address)
    if target is not None:
        _probe(target, origin)
    # The driver's logs would garble the progress bar; Ray's own INFO lines say nothing the note does not.
    kwargs: dict[str, Any] = {"include_dashboard": False, "log_to_driver": False, "logging_level": "WARNING"}
    # Ray's own warnings at connection (token authentication on or off) would land in the middle of the bar.
    ray_log = logging.getLogger("ray")
    level = ray_log.level
    ray_log.setLevel(logging.ERROR)
    try:
        if target is None:
            # num_cpus only when starting an instance: Ray refuses it when connecting to an existing cluster.
            ray.init(address="local", num_cpus=workers, **kwargs)
        else:
            ray.init(address=target, **kwargs)
    except Exception as exc:  # noqa: BLE001 - ray raises ConnectionError, ValueError, RuntimeError, TimeoutError
        where = f"the Ray cluster at {target!r} ({origin})" if target else "a local Ray instance"
        raise InputError(f"cannot connect to {where}: {_first_line(exc)}", source="--executor ray") from exc
    finally:
        ray_log.setLevel(level)
    res = ray.cluster_resources()
    nodes = sum(1 for n in ray.nodes() if n.get("Alive"))
    if target is None:
        note(f"ray: {origin}; started a local instance ({int(res.get('CPU', 0))} CPUs)")
    else:
        where = ray.get_runtime_context().gcs_address
        note(f"ray: connected to {where} ({origin}): {nodes} node(s), {int(res.get('CPU', 0))} CPUs")


def _first_line(exc: BaseException) -> str:
    text = str(exc).strip() or type(exc).__name__
    return text.splitlines()[0]


def _rejoin(fn: Callable[[Any], R], task: Any, part: Any) -> R:
    """Worker side: the task with its shared part (Ray resolved the reference to the value) put back."""
    return fn(task.with_shared(part))


def _in_flight(ray: Any) -> int:
    return max(1, int(ray.cluster_resources().get("CPU", 1))) * IN_FLIGHT_PER_CPU


def run_on_ray(fn: Callable[[T], R], tasks: Iterable[T], *, workers: int, address: str | None = None,
               note: Callable[[str], None] = lambda _: None) -> Iterator[R]:
    """Apply `fn` to every task on the Ray cluster, yielding results as they complete."""
    try:
        import ray
        from ray.exceptions import RayError
    except ImportError as exc:  # pragma: no cover - ray is in requirements-dev
        raise InputError("--executor ray needs the 'ray' package (pip install ray)") from exc
    initialised_here = not ray.is_initialized()
    if initialised_here:
        connect(ray, address, workers, note)
    try:
        # A run is a pure function of its task, so a task lost with a node is safely run again elsewhere.
        plain = ray.remote(max_retries=3)(fn)
        joined = ray.remote(max_retries=3)(_rejoin)
        parts: dict[Hashable, Any] = {}         # shared-part key -> object ref, put once per campaign
        limit, sized_at = _in_flight(ray), time.monotonic()
        pending: list[Any] = []
        it = iter(tasks)
        exhausted = False
        while pending or not exhausted:
            while not exhausted and len(pending) < limit:
                try:
                    task = next(it)
                except StopIteration:
                    exhausted = True
                    break
                split = getattr(task, "shared_part", None)
                if split is None:
                    pending.append(plain.remote(task))
                    continue
                key, part, light = split()
                if key not in parts:
                    parts[key] = ray.put(part)
                pending.append(joined.remote(fn, light, parts[key]))
            if not pending:
                break
            done, pending = ray.wait(pending, num_returns=1)
            # take every other finished one too: one round trip per batch, not per task
            if pending:
                more, pending = ray.wait(pending, num_returns=len(pending), timeout=0)
                done += more
            for ref in done:
                try:
                    yield ray.get(ref)
                except RayError as exc:
                    cause = getattr(exc, "cause", None) or exc
                    if isinstance(cause, Txt2SceError):
                        raise cause from exc        # the task's own error, as the pool would raise it
                    raise SimulationFault(f"a Ray task failed: {type(cause).__name__}: {_first_line(cause)} (every "
                                          "node needs the project installed the same way; see the README)",
                                          source="--executor ray") from exc
            if time.monotonic() - sized_at > RESIZE_EVERY:
                limit, sized_at = _in_flight(ray), time.monotonic()
    finally:
        if initialised_here:
            ray.shutdown()
