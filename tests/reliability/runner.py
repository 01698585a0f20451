"""Run one catalogue case as a real `txt2sce` subprocess under resource limits and classify what happened.

A case is clean when the command ends within its wall-clock bound and under the memory cap, with the expected exit
status, no Python traceback on stdout or stderr, an error message that is one line and says what is wrong, and the
good items of the input kept (the case's own `kept` check). Otherwise it is a *hang* (time or memory bound hit), a
*crash* (traceback, signal, unexpected exit status or message) or a *loss* (good items gone).
"""

from __future__ import annotations

import os
import re
import resource
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

#: Address-space cap of every case's process tree (each process; numpy + rclpy map ~1 GB of virtual memory).
MEMORY_CAP_BYTES = 3 * 1024**3
#: Peak resident memory above this is a hang (unbounded growth), even if the cap was not hit.
RSS_LIMIT_BYTES = 1024**3

REPO = Path(__file__).resolve().parents[2]


@dataclass(frozen=True)
class Case:
    """One bad input or fault. `argv(ws, d)` builds the command line (ws: the shared workspace of good fixtures,
    d: this case's own empty directory, where it writes its bad input); `message` must match one stderr line (or
    stdout line when the command reports per item on stdout); `kept(ws, d, out)` returns what good item was lost,
    or '' when everything good was kept. `during(pid)` injects a fault into the running process tree."""

    name: str
    argv: Callable[[Path, Path], list[str]]
    exit: tuple[int, ...] = (2,)
    message: str = r"error"
    kept: Callable[[Path, Path, str], str] | None = None
    timeout: float = 60.0
    env: dict[str, str] = field(default_factory=dict)
    during: Callable[[int, Path], None] | None = None
    expected_to_fail_until: str = ""      # a case owned by another issue that is not fixed yet


@dataclass(frozen=True)
class Outcome:
    case: str
    kind: str          # clean | crash | hang | loss
    detail: str
    seconds: float
    max_rss_mb: float
    exit: int | None


def _limits() -> None:
    # In the child before exec: cap memory; the new session lets the runner kill the whole tree at once.
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP_BYTES, MEMORY_CAP_BYTES))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def txt2sce_argv(*args: str) -> list[str]:
    return [sys.executable, "-m", "txt2sce_ros.cli.main", *args]


def run_case(case: Case, ws: Path, root: Path | None = None) -> Outcome:
    d = Path(tempfile.mkdtemp(prefix=f"{case.name[:40]}-", dir=root))
    argv = case.argv(ws, d)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO), env.get("PYTHONPATH", "")]))
    env.pop("TXT2SCE_DEBUG", None)
    env["TXT2SCE_CACHE"] = str(d / "cache")
    env.update(case.env)
    out_f, err_f = open(d / "stdout.txt", "wb"), open(d / "stderr.txt", "wb")
    t0 = time.monotonic()
    proc = subprocess.Popen(argv, cwd=d, env=env, stdout=out_f, stderr=err_f, stdin=subprocess.DEVNULL,
                            preexec_fn=_limits, start_new_session=True)
    timed_out = threading.Event()

    def _kill() -> None:
        timed_out.set()
        _killpg(proc.pid)

    timer = threading.Timer(case.timeout, _kill)
    timer.start()
    injector = None
    if case.during is not None:
        injector = threading.Thread(target=case.during, args=(proc.pid, d), daemon=True)
        injector.start()
    try:
        _, status, usage = os.wait4(proc.pid, 0)
    finally:
        timer.cancel()
        _killpg(proc.pid)          # whatever the command left behind in its session
        out_f.close()
        err_f.close()
    proc.returncode = os.waitstatus_to_exitcode(status)
    seconds = time.monotonic() - t0
    rss = usage.ru_maxrss * 1024
    code = proc.returncode
    stdout = (d / "stdout.txt").read_text(encoding="utf-8", errors="replace")
    stderr = (d / "stderr.txt").read_text(encoding="utf-8", errors="replace")
    kind, detail = _classify(case, code, stdout, stderr, timed_out.is_set(), rss, ws, d)
    return Outcome(case.name, kind, detail, seconds, rss / 2**20, code)


def _killpg(pid: int) -> None:
    try:
        os.killpg(pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _classify(case: Case, code: int, stdout: str, stderr: str, timed_out: bool, rss: int, ws: Path,
              d: Path) -> tuple[str, str]:
    if timed_out:
        return "hang", f"no end within {case.timeout:g} s"
    if rss > RSS_LIMIT_BYTES or "MemoryError" in stderr:
        return "hang", f"memory: peak {rss / 2**20:.0f} MB"
    if "Traceback (most recent call last)" in stderr + stdout:
        last = [ln for ln in stderr.splitlines() if ln.strip()][-1:] or ["?"]
        return "crash", f"traceback: {last[0][:160]}"
    internal = [ln for ln in stderr.splitlines() if "internal error" in ln]
    if internal:
        return "crash", internal[0][:200]
    if code < 0:
        return "crash", f"killed by signal {-code}"
    if code not in case.exit:
        tail = ([ln for ln in (stderr + stdout).splitlines() if ln.strip()] or ["(no output)"])[-1]
        return "crash", f"exit {code}, expected {case.exit}: {tail[:160]}"
    pattern = re.compile(case.message, re.IGNORECASE)
    lines = (stderr + "\n" + stdout).splitlines()
    if not any(pattern.search(ln) for ln in lines):
        tail = ([ln for ln in lines if ln.strip()] or ["(no output)"])[-1]
        return "crash", f"no line matches /{case.message}/; last: {tail[:160]}"
    if case.kept is not None:
        lost = case.kept(ws, d, stdout)
        if lost:
            return "loss", lost
    return "clean", ""
