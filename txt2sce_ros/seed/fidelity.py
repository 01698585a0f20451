"""Fidelity of a seed (the automatic version of the paper's manual check, 31/33 = 93.9%): run it in the scenario
player with a storyboard-driven (non-reactive) AV that follows its reported manoeuvre, and ask whether the reported
party comes into conflict with the AV: boxes in contact, or a time-to-collision below 1.5 s.

TTC here: the smallest t in [0, 1.5] s at which the two boxes would overlap if both kept their current velocity and
heading (checked every 0.1 s), so parallel traffic in adjacent lanes never counts, and a party about to cut across
the AV's front does.

    from txt2sce_ros.seed.fidelity import check_seed, fidelity_batch
    res = check_seed(seed_result)              # FidelityResult
    results = fidelity_batch(sketches, seed=0) # one result per buildable sketch
"""

from __future__ import annotations

import math
import tempfile
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..contract import EntityState
from ..errors import Txt2SceError
from .boxes import boxes_gap, first_contacts, state_corners  # noqa: F401  (first_contacts: its old home)

if TYPE_CHECKING:   # pragma: no cover
    from ..sketch import ErrorRecord, Sketch
    from .generate import SeedResult

TTC_LIMIT = 1.5
TTC_STEP = 0.1


@dataclass(frozen=True, slots=True)
class FidelityResult:
    report_id: str
    target: str | None
    faithful: bool
    kind: str                 # 'contact' | 'ttc' | 'none' | 'error' | 'no_target'
    time: float | None        # s, first conflict
    min_gap: float | None     # m, smallest box gap seen
    min_ttc: float | None     # s
    note: str = ""


def ttc(a: EntityState, b: EntityState, *, limit: float = TTC_LIMIT, step: float = TTC_STEP) -> float | None:
    """Constant-velocity time until the boxes overlap (0 when they already do); None beyond `limit`."""
    t = 0.0
    while t <= limit + 1e-9:
        if boxes_gap(state_corners(a, t), state_corners(b, t)) <= 0.0:
            return round(t, 3)
        t += step
    return None


def check_frames(frames: Iterable, target: str) -> tuple[str, float | None, float | None, float | None]:
    """(kind, time, min gap, min ttc) over a run's frames."""
    min_gap, min_ttc = math.inf, math.inf
    first: tuple[str, float] | None = None
    for fr in frames:
        other = next((o for o in fr.objects if o.name == target), None)
        if other is None:
            continue
        gap = boxes_gap(state_corners(fr.ego), state_corners(other))
        min_gap = min(min_gap, gap)
        if gap <= 0.0:
            return "contact", fr.t, min_gap, 0.0
        if gap < 25.0:
            tt = ttc(fr.ego, other)
            if tt is not None:
                min_ttc = min(min_ttc, tt)
                if first is None:
                    first = ("ttc", fr.t)
    gap_out = None if min_gap == math.inf else round(min_gap, 3)
    ttc_out = None if min_ttc == math.inf else round(min_ttc, 3)
    if first:
        return first[0], first[1], gap_out, ttc_out
    return "none", None, gap_out, ttc_out


def check_seed(result: SeedResult, *, dt: float = 0.05, target: str | None = None) -> FidelityResult:
    """Run one generated seed in the player (storyboard AV) and judge it."""
    tgt = target or result.manifest.get("fidelity_target")
    with tempfile.TemporaryDirectory(prefix="txt2sce_fid_") as tmp:
        path = Path(tmp) / "seed.xosc"
        path.write_bytes(result.xosc)
        res, _ = check_file(path, tgt, report_id=result.report_id, dt=dt, time_limit=result.plan.time_limit)
    return res


def check_file(path: str | Path, target: str | None, *, report_id: str | None = None, dt: float = 0.05,
               time_limit: float | None = None) -> tuple[FidelityResult, dict[str, np.ndarray]]:
    """Run a seed file in the player (storyboard AV) and judge it; also returns the trajectories (per entity: rows
    of t, x, y, heading, speed) so a caller can draw what was judged. `time_limit` None: the player's default."""
    from scenario_player import Simulation, SimulationConfig, load_scenario

    rid = report_id or Path(path).stem
    if target is None:
        return FidelityResult(rid, None, False, "no_target", None, None, None, "nothing to meet"), {}
    try:
        scenario = load_scenario(path, source=rid)
        sim = Simulation(scenario, SimulationConfig(dt=dt, ego_mode="storyboard", time_limit=time_limit))
        frames = [sim.reset()]
        while not sim.done:
            frames.append(sim.step(None))
    except Txt2SceError as exc:
        return FidelityResult(rid, target, False, "error", None, None, None, str(exc)), {}
    unsupported = "; ".join(sim.unsupported[:3])
    kind, when, gap, tt = check_frames(frames, target)
    return (FidelityResult(rid, target, kind in ("contact", "ttc"), kind, when, gap, tt,
                           f"unsupported: {unsupported}" if unsupported else ""), sim.trajectory)


def fidelity_batch(items: Iterable[Sketch | ErrorRecord], *, seed: int = 0, maps: str | Path | None = None,
                   dt: float = 0.05) -> list[FidelityResult]:
    """Generate and check every buildable sketch (refused ones are skipped: they have no seed)."""
    from ..sketch import ErrorRecord   # on use, as the generator below
    from .generate import fidelity_target, generate_seed

    out = []
    for item in items:
        if isinstance(item, ErrorRecord) or item.missing:
            continue
        try:
            res = generate_seed(item, seed=seed, maps=maps)
        except Txt2SceError as exc:
            out.append(FidelityResult(item.report_id, None, False, "error", None, None, None, str(exc)))
            continue
        out.append(check_seed(res, dt=dt, target=fidelity_target(item)))
    return out
