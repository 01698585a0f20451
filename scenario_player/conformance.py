"""Conformance against a reference player's recordings (esmini CSV: time, id, name, x, y, ... per entity/step).

Each scenario runs with the storyboard driving every entity (ego included) at the reference's step; positions are
compared at the times both recorded, per entity: RMS and max of the Euclidean position error.
"""

from __future__ import annotations

import csv
import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from txt2sce_ros.errors import Txt2SceError

from .simulation import Simulation, SimulationConfig
from .syntax.scenario import load_scenario


@dataclass(frozen=True, slots=True)
class EntityError:
    name: str
    rows: int
    rms: float
    max: float


@dataclass(frozen=True)
class FileResult:
    name: str
    ran: bool
    error: str = ""
    unsupported: tuple[str, ...] = ()
    entities: tuple[EntityError, ...] = ()
    sim_seconds: float = 0.0
    wall_seconds: float = 0.0

    @property
    def rms(self) -> float:
        """Worst entity RMS (the file passes if every entity is within the target)."""
        return max((e.rms for e in self.entities), default=math.nan)

    @property
    def max(self) -> float:
        return max((e.max for e in self.entities), default=math.nan)


def read_reference(path: Path) -> dict[str, np.ndarray]:
    """Reference CSV -> per entity name: rows of time, x, y, h, speed."""
    rows: dict[str, list[tuple[float, float, float, float, float]]] = {}
    with open(path, newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh, skipinitialspace=True)
        for r in reader:
            rows.setdefault(r["name"].strip(), []).append(
                (float(r["time"]), float(r["x"]), float(r["y"]), float(r["h"]), float(r["speed"])))
    return {k: np.array(v) for k, v in rows.items()}


def compare(mine: dict[str, np.ndarray], ref: dict[str, np.ndarray]) -> tuple[EntityError, ...]:
    out = []
    for name, r in ref.items():
        m = mine.get(name)
        if m is None or len(m) == 0:
            out.append(EntityError(name, 0, math.inf, math.inf))
            continue
        mine_t = {round(t, 3): i for i, t in enumerate(m[:, 0])}
        idx = [(i, mine_t[round(t, 3)]) for i, t in enumerate(r[:, 0]) if round(t, 3) in mine_t]
        if not idx:
            out.append(EntityError(name, 0, math.inf, math.inf))
            continue
        ri, mi = np.array(idx).T
        err = np.hypot(r[ri, 1] - m[mi, 1], r[ri, 2] - m[mi, 2])
        out.append(EntityError(name, len(err), float(np.sqrt(np.mean(err ** 2))), float(err.max())))
    return tuple(out)


def run_file(xosc: Path, reference: Path | None, *, dt: float = 0.05) -> tuple[FileResult, Simulation | None]:
    ref = read_reference(reference) if reference is not None and reference.is_file() else None
    end = max((float(v[-1, 0]) for v in ref.values()), default=60.0) if ref else 60.0
    try:
        sim = Simulation(load_scenario(xosc), SimulationConfig(dt=dt, ego_mode="storyboard", time_limit=end + 1e-6))
        t0 = time.perf_counter()
        status = sim.run()
        wall = time.perf_counter() - t0
    except Txt2SceError as exc:
        return FileResult(xosc.name, False, error=str(exc)), None
    except Exception as exc:  # noqa: BLE001 - one broken file must not end the table
        return FileResult(xosc.name, False, error=f"{type(exc).__name__}: {exc}"), None
    errors = compare(sim.trajectory, ref) if ref else ()
    return FileResult(xosc.name, True, unsupported=status.unsupported, entities=errors, sim_seconds=sim.t,
                      wall_seconds=wall), sim


@dataclass
class Table:
    results: list[FileResult] = field(default_factory=list)

    def passed(self, target: float = 0.5) -> int:
        return sum(1 for r in self.results if r.ran and r.entities and r.rms < target)


def run_directory(xosc_dir: Path, reference_dir: Path, *, only: list[str] | None = None) -> Table:
    table = Table()
    for xosc in sorted(xosc_dir.glob("*.xosc")):
        if only and xosc.stem not in only and xosc.name not in only:
            continue
        res, _ = run_file(xosc, reference_dir / f"{xosc.stem}.csv")
        table.results.append(res)
    return table
