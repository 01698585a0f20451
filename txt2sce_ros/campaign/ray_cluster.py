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
import shutil
import signal
import socket
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Callable, Hashable, Iterable, Iterator, Sequence, TypeVar

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


#: Tries to start a local instance (see `connect`).
LOCAL_START_ATTEMPTS = 3

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
    if target == "auto" and origin.startswith("the cluster `ray start` recorded"):
        # a file left by a cluster that died without `ray stop` would have ray.init retry for minutes
        _probe(address_file().read_text(encoding="utf-8").strip(), origin)
    elif target is not None:
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
            # Ray gives the new node 30 s to register (hard-coded); a loaded machine can miss that: try again.
            for attempt in range(LOCAL_START_ATTEMPTS):
                try:
                    ray.init(address="local", num_cpus=workers, **kwargs)
                    break
                except Exception as exc:  # noqa: BLE001 - Ray raises a bare Exception on that time-out
                    ray.shutdown()
                    if attempt == LOCAL_START_ATTEMPTS - 1 or "timed out during startup" not in str(exc):
                        raise
        else:
            ray.init(address=target, **kwargs)
    except Exception as exc:  # noqa: BLE001 - ray raises ConnectionError, ValueError, RuntimeError, TimeoutError
        where = f"the Ray cluster at {target!r} ({origin})" if target else "a local Ray instance"
        raise InputError(f"cannot connect to {where}: {_first_line(exc)}", source="--executor ray") from exc
    finally:
        ray_log.setLevel(level)
    cpus = int(ray.cluster_resources().get("CPU", 0))
    nodes = sum(1 for n in ray.nodes() if n.get("Alive"))
    sizing = f"up to {in_flight(ray)} runs in flight"
    if target is None:
        note(f"ray: {origin}; started a local instance ({cpus} CPUs, {sizing})")
    else:
        where = ray.get_runtime_context().gcs_address
        note(f"ray: connected to {where} ({origin}): {nodes} node(s), {cpus} CPUs, {sizing}")


def _first_line(exc: BaseException) -> str:
    text = str(exc).strip() or type(exc).__name__
    return text.splitlines()[0]


def _rejoin(fn: Callable[[Any], R], task: Any, part: Any) -> R:
    """Worker side: the task with its shared part (Ray resolved the reference to the value) put back."""
    return fn(task.with_shared(part))


def in_flight(ray: Any) -> int:
    """Tasks to keep submitted: IN_FLIGHT_PER_CPU per CPU of the whole cluster (not of the driver's machine)."""
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
        limit, sized_at = in_flight(ray), time.monotonic()
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
                limit, sized_at = in_flight(ray), time.monotonic()
    finally:
        if initialised_here:
            ray.shutdown()


def free_port() -> int:
    """A TCP port nothing listens on now (for a private cluster's GCS and agents)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _alive_under(directory: str) -> list[int]:
    """Processes (not zombies, not this one) whose command line or environment names `directory` (Ray's workers
    and agents rename their command line, `ray::IDLE`; they inherit RAY_TMPDIR)."""
    out = []
    for proc in Path("/proc").iterdir():
        if not proc.name.isdigit() or int(proc.name) == os.getpid():
            continue
        try:
            if (proc / "stat").read_text().rsplit(")", 1)[1].split()[0] == "Z":
                continue
            needle = directory.encode()
            if needle in (proc / "cmdline").read_bytes() or needle in (proc / "environ").read_bytes():
                out.append(int(proc.name))
        except (OSError, IndexError):
            continue
    return out


def stop_processes_under(directory: str, timeout: float = 5.0) -> int:
    """SIGKILL every process whose command line or environment names `directory` (a private Ray temp dir: the GCS,
    raylets, agents and workers of the instances started under it, and nothing else) and reap those that are our children.
    Needed because a node that missed Ray's start-up window is known to neither `Cluster.shutdown` nor
    `ray.shutdown` and would live on. Returns how many were stopped."""
    pids = _alive_under(directory)
    for pid in pids:
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    deadline = time.monotonic() + timeout
    while pids and time.monotonic() < deadline:
        for pid in pids:
            try:
                os.waitpid(pid, os.WNOHANG)     # our child: reaped; anyone else's: ChildProcessError
            except ChildProcessError:
                pass
        if not _alive_under(directory):
            break
        time.sleep(0.1)
    return len(pids)


@contextmanager
def simulated_cluster(cpus_per_node: Sequence[int], *, attempts: int = 3) -> Iterator[Any]:
    """Several Ray nodes on this machine (`ray.cluster_utils.Cluster`; a node per entry of `cpus_per_node`), in a
    private temp dir with free ports, so nothing meets another Ray instance on the machine; shut down on leaving.
    For tests and `txt2sce bench ray`: what a multi-machine cluster looks like to the driver. Ray gives a node 30 s
    to register (hard-coded), which a loaded 2-core machine can miss: a failed start is retried."""
    from ray.cluster_utils import Cluster

    old_tmp = os.environ.get("RAY_TMPDIR")
    # short: Ray's socket paths under it must fit in 107 bytes
    tmp = tempfile.mkdtemp(prefix="t2s_ray_", dir="/tmp")
    os.environ["RAY_TMPDIR"] = tmp
    cluster = None
    try:
        for attempt in range(attempts):
            cluster = Cluster()
            try:
                for i, cpus in enumerate(cpus_per_node):
                    head = {"gcs_server_port": free_port(), "include_dashboard": False,
                            "dashboard_agent_listen_port": free_port()} if i == 0 else {}
                    cluster.add_node(num_cpus=cpus, object_store_memory=80 * 1024 * 1024, **head)
                break
            except Exception:  # noqa: BLE001 - Ray raises a bare Exception on a node start-up timeout
                cluster.shutdown()
                cluster = None
                stop_processes_under(tmp)
                if attempt == attempts - 1:
                    raise
        yield cluster
    finally:
        if cluster is not None:
            cluster.shutdown()
        stop_processes_under(tmp)
        if old_tmp is None:
            os.environ.pop("RAY_TMPDIR", None)
        else:
            os.environ["RAY_TMPDIR"] = old_tmp
        shutil.rmtree(tmp, ignore_errors=True)
