"""Fingerprints of whole runs, to prove that a speed-up changed nothing.

A run's fingerprint covers every recorded trajectory row (t, x, y, heading, speed per entity) and, in planner
mode, every Frame the planner saw (all EntityState fields and traffic lights), so the closed loop's inputs are
covered too. Two digests per run:

- `exact`: SHA-256 of the raw float64 bytes — byte-for-byte equality, for comparing two versions of the code on
  this machine;
- `rounded`: SHA-256 of the values rounded to 1e-6 (m, rad, m/s) — robust to last-bit differences of another libm
  or numpy, so it can be stored in a test.

`python -m scenario_player.fingerprint record OUT.json FILE_OR_DIR...` writes the digests of the storyboard and
toy-planner runs of every .xosc; `check OUT.json FILE_OR_DIR...` recomputes and lists the runs that differ.
"""

from __future__ import annotations

import hashlib
import json
import math
import struct
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from txt2sce_ros.contract import ControlCommand, EntityState, Frame

MODES = ("storyboard", "planner")


@dataclass(frozen=True, slots=True)
class RunDigest:
    """Digests of one run of one file in one mode."""

    name: str
    mode: str
    steps: int
    end_reason: str
    exact: str
    rounded: str


def toy_policy(frame: Frame) -> ControlCommand:
    """A deterministic stand-in for a planner (no dependency on `standin_planner`, which evolves on its own):
    accelerate towards 12 m/s while weaving gently, so the ego leaves its lane and exercises free motion."""
    k = round(frame.t / 0.05)
    return ControlCommand(t=frame.t, speed=min(frame.ego.speed + 0.1, 12.0), yaw_rate=0.03 * math.sin(0.05 * k))


def _state_values(s: EntityState) -> tuple[float, ...]:
    return (s.t, s.x, s.y, s.heading, s.speed, s.accel, s.yaw_rate, s.length, s.width, s.height, s.center_x,
            float(s.is_static))


class _Hasher:
    """Feeds the same values to the exact and the rounded digest."""

    def __init__(self) -> None:
        self.exact = hashlib.sha256()
        self.rounded = hashlib.sha256()

    def text(self, s: str) -> None:
        b = s.encode() + b"\0"
        self.exact.update(b)
        self.rounded.update(b)

    def floats(self, values: tuple[float, ...] | np.ndarray) -> None:
        arr = np.asarray(values, dtype=np.float64)
        self.exact.update(arr.tobytes())
        # +0.0 folds -0.0 into 0.0: a sign of zero is not a behaviour.
        self.rounded.update((np.round(arr, 6) + 0.0).tobytes())

    def frame(self, f: Frame) -> None:
        self.floats((f.t,))
        for s in (f.ego, *f.objects):
            self.text(f"{s.name}|{s.category}")
            self.floats(_state_values(s))
        for light in f.lights:
            self.text(repr(light))


def run_digest(path: str | Path, mode: str, *, time_limit: float = 30.0, seed: int = 0) -> RunDigest:
    """Run one file in `mode` ('storyboard' or 'planner' with `toy_policy`) and digest the whole run."""
    from scenario_player import Simulation, SimulationConfig, load_scenario

    sim = Simulation(load_scenario(str(path)), SimulationConfig(ego_mode=mode, seed=seed, time_limit=time_limit))
    h = _Hasher()
    frame = sim.reset()
    steps = 0
    if mode == "planner":
        h.frame(frame)
        while not sim.done:
            frame = sim.step(toy_policy(frame))
            h.frame(frame)
            steps += 1
    else:
        sim.run()
        steps = int(round(sim.t / sim.config.dt))
    for name, rows in sorted(sim.trajectory.items()):
        h.text(name)
        h.floats(rows)
    h.text(sim.end_reason)
    return RunDigest(Path(path).stem, mode, steps, sim.end_reason, h.exact.hexdigest(), h.rounded.hexdigest())


def _files(args: list[str]) -> list[Path]:
    out: list[Path] = []
    for a in args:
        p = Path(a)
        out.extend(sorted(p.glob("*.xosc")) if p.is_dir() else [p])
    return out


def digests(files: list[Path], *, time_limit: float = 30.0) -> dict[str, dict[str, object]]:
    """`name/mode` -> digest fields, for every file in both modes (a file that fails to load is recorded as such)."""
    from txt2sce_ros.errors import Txt2SceError

    out: dict[str, dict[str, object]] = {}
    for path in files:
        for mode in MODES:
            key = f"{path.stem}/{mode}"
            try:
                d = run_digest(path, mode, time_limit=time_limit)
                out[key] = {"steps": d.steps, "end": d.end_reason, "exact": d.exact, "rounded": d.rounded}
            except Txt2SceError as exc:
                out[key] = {"error": type(exc).__name__}
    return out


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if len(argv) < 3 or argv[0] not in ("record", "check"):
        print(__doc__)
        return 2
    cmd, out, files = argv[0], Path(argv[1]), _files(argv[2:])
    now = digests(files)
    if cmd == "record":
        out.write_text(json.dumps(now, indent=1, sort_keys=True))
        print(f"{len(now)} runs recorded to {out}")
        return 0
    ref = json.loads(out.read_text())
    bad = [k for k in sorted(set(ref) | set(now)) if ref.get(k) != now.get(k)]
    for k in bad:
        print(f"DIFFERS {k}: {ref.get(k)} -> {now.get(k)}")
    print(f"{len(now) - len(bad)}/{len(now)} runs identical")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
