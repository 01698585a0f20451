"""Child processes end when the process that started them dies, however it dies (SIGKILL included).

Linux delivers a chosen signal to a child when its parent exits (`prctl(PR_SET_PDEATHSIG)`). Campaign pool workers
and the ROS graph's node processes set it at start, so killing a campaign leaves no worker or node behind (a node
in its own session would otherwise keep running, and keep its DDS domain busy). Elsewhere this is a no-op.
"""

from __future__ import annotations

import ctypes
import os
import signal
import sys

PR_SET_PDEATHSIG = 1


def die_with_parent(sig: int = signal.SIGTERM, parent: int | None = None) -> None:
    """Ask the kernel to send `sig` to this process when its parent exits. `parent`: the pid the caller expects
    as parent; if it is already gone (we were re-parented before the call), exit now."""
    if not sys.platform.startswith("linux"):
        return
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(PR_SET_PDEATHSIG, int(sig), 0, 0, 0)
    except (OSError, AttributeError):
        return
    if parent is not None and os.getppid() != parent:
        os._exit(1)


def preexec(parent: int | None = None):
    """A `subprocess.Popen(preexec_fn=...)` that ties the child to the calling process (`parent`: its pid)."""
    pid = os.getpid() if parent is None else parent

    def _tie() -> None:
        die_with_parent(signal.SIGTERM, pid)

    return _tie
