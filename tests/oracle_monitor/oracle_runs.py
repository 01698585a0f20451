"""Constructed runs for the oracle tests: frames built from simple motion laws, and esmini's reference trajectories
(real third-party data in ../shared) turned into frames."""

from __future__ import annotations

import csv
import math
from collections import defaultdict
from dataclasses import replace
from pathlib import Path
from typing import Callable, Iterable

from txt2sce_ros.contract import EntityState, Frame, RunStatus, TrafficLightState
from txt2sce_ros.paths import shared_dir

DT = 0.05


def ego(t: float, x: float, y: float = 0.0, heading: float = 0.0, speed: float = 0.0, **kw) -> EntityState:
    return EntityState("ego", "car", t, x, y, heading, speed, **kw)


def car(name: str, t: float, x: float, y: float = 0.0, heading: float = 0.0, speed: float = 0.0,
        **kw) -> EntityState:
    return EntityState(name, kw.pop("category", "car"), t, x, y, heading, speed, **kw)


def straight_run(speed_at: Callable[[float], float], duration: float, *, x0: float = 0.0, dt: float = DT,
                 objects: Callable[[float], Iterable[EntityState]] = lambda t: (),
                 lights: Callable[[float], Iterable[TrafficLightState]] = lambda t: ()) -> list[Frame]:
    """Ego along +x with the given speed law (position integrated with the trapezoid rule)."""
    frames, x, v_prev = [], x0, speed_at(0.0)
    n = int(round(duration / dt))
    for k in range(n + 1):
        t = round(k * dt, 9)
        v = speed_at(t)
        if k:
            x += 0.5 * (v + v_prev) * dt
        v_prev = v
        frames.append(Frame(t, ego(t, x, speed=v), tuple(objects(t)), tuple(lights(t))))
    return frames


def turning_run(speed: float, yaw_rate_at: Callable[[float], float], duration: float, dt: float = DT) -> list[Frame]:
    frames, x, y, h = [], 0.0, 0.0, 0.0
    for k in range(int(round(duration / dt)) + 1):
        t = round(k * dt, 9)
        if k:
            h += yaw_rate_at(t) * dt
            x += speed * math.cos(h) * dt
            y += speed * math.sin(h) * dt
        frames.append(Frame(t, ego(t, x, y, h, speed)))
    return frames


def finished(t: float, reason: str = "stop_trigger", **kw) -> RunStatus:
    return RunStatus("constructed", "finished", t=t, end_reason=reason, **kw)


def judge(oracle, frames: list[Frame], status: RunStatus | None = "auto"):
    """Feed every frame, then finish; returns (verdict, violations raised online in order)."""
    online = []
    for f in frames:
        online.extend(oracle.observe(f))
    if status == "auto":
        status = finished(frames[-1].t)
    return oracle.finish(status), online


# --- esmini reference runs ----------------------------------------------------------------------------------------

ESMINI = shared_dir() / "data" / "conformance" / "esmini"

#: Bounding boxes (length, width, center_x) of the esmini catalog entities these runs use: cars of the
#: VehicleCatalog are 5.04 × 2.0 m centred 1.4 m ahead of the rear axle; the adult pedestrian is 0.6 × 0.5 m.
ESMINI_BOXES = {"car": (5.04, 2.0, 1.4), "pedestrian": (0.6, 0.5, 0.06)}


def esmini_frames(name: str, ego_name: str = "Ego", categories: dict[str, str] | None = None) -> list[Frame]:
    """esmini's reference trajectory `reference/<name>.csv` as frames, the entity `ego_name` renamed to ego."""
    categories = categories or {}
    rows: dict[float, list[dict[str, str]]] = defaultdict(list)
    with open(ESMINI / "reference" / f"{name}.csv", newline="") as fh:
        for row in csv.DictReader(fh):
            rows[float(row["time"])].append(row)
    frames = []
    for t in sorted(rows):
        ents = []
        for row in rows[t]:
            is_ego = row["name"] == ego_name
            cat = "car" if is_ego else categories.get(row["name"], "car")
            length, width, cx = ESMINI_BOXES.get(cat, ESMINI_BOXES["car"])
            ents.append(EntityState("ego" if is_ego else row["name"], cat, t, float(row["x"]), float(row["y"]),
                                    float(row["h"]), float(row["speed"]), length=length, width=width,
                                    center_x=cx, is_static=False))
        ego_state = next(e for e in ents if e.name == "ego")
        frames.append(Frame(t, ego_state, tuple(e for e in ents if e.name != "ego")))
    return frames


def esmini_map(name: str) -> Path:
    return ESMINI / "xodr" / name


def shifted(frames: list[Frame], **changes) -> list[Frame]:
    return [replace(f, ego=replace(f.ego, **changes)) for f in frames]
