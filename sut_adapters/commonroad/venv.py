"""Where the planner's own environment lives and how the harness starts the adapter in it.

The reactive planner pins protobuf 3.20.2 (through commonroad-io) while the harness's environment has a newer one
(through ray), so the adapter runs from its own venv, created by `make sut-commonroad` (`.venv-commonroad` in the
checkout; `$TXT2SCE_COMMONROAD_VENV` overrides). This module is imported by the harness: it must not import the
planner.
"""

from __future__ import annotations

import os
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]


def venv_dir() -> Path:
    env = os.environ.get("TXT2SCE_COMMONROAD_VENV")
    return Path(env) if env else REPO_ROOT / ".venv-commonroad"


def python() -> Path:
    return venv_dir() / "bin" / "python"


def available() -> str:
    """'' when the environment can run the adapter, else why not (one line, for errors and test skips)."""
    py = python()
    if not py.exists():
        return f"the CommonRoad planner environment is missing ({venv_dir()}): run `make sut-commonroad`"
    if not (venv_dir() / ".installed").exists():
        return f"the CommonRoad planner environment at {venv_dir()} is incomplete: rerun `make sut-commonroad`"
    return ""


def adapter_command() -> list[str]:
    """The adapter node's command line (parameters are appended by the launcher)."""
    why = available()
    if why:
        raise FileNotFoundError(why)
    return [str(python()), "-m", "sut_adapters.commonroad.node"]


def adapter_environment(env: dict[str, str]) -> dict[str, str]:
    """The child's environment: the checkout first on PYTHONPATH (the adapter imports the road model and the
    topic helpers from it) and no library path of the harness's venv (the planner venv's own .pth hook sets its
    ROS libraries at interpreter start)."""
    out = dict(env)
    parts = [str(REPO_ROOT)] + [p for p in out.get("PYTHONPATH", "").split(os.pathsep) if p]
    out["PYTHONPATH"] = os.pathsep.join(dict.fromkeys(parts))
    # the wheels' bootstrap re-executes the interpreter with its venv's library path unless a parent already did:
    # drop the parent's marker and path so the planner venv loads its own ROS libraries
    for key in ("LD_LIBRARY_PATH", "_ROS_WHEELS_BOOTSTRAP_COMPLETE", "VIRTUAL_ENV"):
        out.pop(key, None)
    return out


def planner_version() -> str:
    """The installed reactive planner's version, asked of its own environment (the harness cannot import it)."""
    import subprocess

    code = "from importlib.metadata import version; print(version('commonroad-reactive-planner'))"
    out = subprocess.run(adapter_command()[:1] + ["-c", code], capture_output=True, text=True, timeout=60,
                         env=adapter_environment(dict(os.environ)))
    if out.returncode != 0:
        raise FileNotFoundError(f"the CommonRoad planner environment at {venv_dir()} cannot report its version: "
                                f"{(out.stderr.strip().splitlines() or ['no output'])[-1]}")
    return out.stdout.strip()
