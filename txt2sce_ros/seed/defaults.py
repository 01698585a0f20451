"""Seed defaults from `config/seed.yaml` (paper Table III) as frozen records."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from ..config import load_config
from ..errors import InputError


@dataclass(frozen=True, slots=True)
class Timing:
    time_to_conflict: float
    ego_goal_beyond_conflict: float
    time_limit: float
    goal_tolerance: float
    signal_phase_before: float


@dataclass(frozen=True, slots=True)
class SeedDefaults:
    raw: Any                       # the YAML mapping (read-only)
    timing: Timing
    accelerate_factor: float
    decelerate_factor: float
    reverse_speed: float
    max_acceleration: float
    max_deceleration: float
    max_speed: float
    shape: str
    dyn_value: float
    dimension: str
    lane_change_time: float
    lane_offset_max_lat_acc: float

    def speed(self, category: str) -> float:
        return float(self._get("target_speed", category))

    def dims(self, category: str) -> tuple[float, float, float]:
        w, l, h = self._get("dimensions", category)
        return float(w), float(l), float(h)

    def _get(self, table: str, key: str) -> Any:
        try:
            return self.raw[table][key]
        except KeyError as exc:
            raise InputError(f"no default for {key!r}", source="config/seed.yaml", element=table) from exc


@lru_cache(maxsize=None)
def seed_defaults(path: str | None = None) -> SeedDefaults:
    raw = load_config("seed", path)
    t = raw["timing"]
    p = raw["performance"]
    d = raw["dynamics"]
    return SeedDefaults(
        raw=raw,
        timing=Timing(**{k: float(v) for k, v in t.items()}),
        accelerate_factor=float(raw["accelerate_factor"]),
        decelerate_factor=float(raw["decelerate_factor"]),
        reverse_speed=float(raw["reverse_speed"]),
        max_acceleration=float(p["max_acceleration"]),
        max_deceleration=float(p["max_deceleration"]),
        max_speed=float(p["max_speed"]),
        shape=str(d["shape"]),
        dyn_value=float(d["value"]),
        dimension=str(d["dimension"]),
        lane_change_time=float(d["lane_change_time"]),
        lane_offset_max_lat_acc=float(d["lane_offset_max_lat_acc"]),
    )
