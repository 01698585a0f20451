"""The adapter's settings: everything it decides on the planner's behalf, named in every result it produces.

Defaults are the planner's own where it has one (time step, horizon, replanning frequency, vehicle model); the
rest are the behaviour-layer choices listed in README.md here. Override with a YAML file of the same keys
(node parameter `settings`); unknown keys are errors naming the file and key.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, fields
from pathlib import Path
from typing import Any

import yaml

from txt2sce_ros.errors import InputError


@dataclass(frozen=True)
class AdapterSettings:
    planner_dt: float = 0.1             # s, the reactive planner's default time step
    horizon_steps: int = 30             # 3 s horizon (the measured set-up)
    replan_steps: int = 3               # replan every 3 planner steps = 0.3 s (the planner's replanning_frequency)
    sampling_levels: int = 3            # levels 1-2 (the planner's default 4 adds level 3, whose sample count took
                                        # up to 60 s per cycle on this loaded 2-core machine)
    desired_speed: float = 10.0         # m/s, the same cruise speed the stand-in is given (config/planner.yaml)
    stop_margin: float = 1.0            # m, the stop target short of a red/yellow stop line (front bumper)
    yellow_comfort_decel: float = 3.0   # m/s², stop at yellow only when this deceleration suffices
    fallback_decel: float = 4.0         # m/s², braking command when the planner returns nothing or raises
    signal_lateral_window: float = 4.0  # m, a stop line governs the ego when this close to its reference path
    reroute_offset: float = 5.0         # m, a new route is planned when the ego is this far off the reference path

    @classmethod
    def from_yaml(cls, path: str | Path | None) -> "AdapterSettings":
        if not path:
            return cls()
        p = Path(path)
        try:
            data = yaml.safe_load(p.read_text(encoding="utf-8")) or {}
        except (OSError, yaml.YAMLError) as exc:
            raise InputError(f"cannot read adapter settings: {exc}", source=str(p)) from exc
        if not isinstance(data, dict):
            raise InputError("adapter settings must be a mapping", source=str(p))
        names = {f.name for f in fields(cls)}
        unknown = sorted(set(data) - names)
        if unknown:
            raise InputError(f"unknown adapter setting(s): {', '.join(unknown)}", source=str(p))
        return cls(**{k: type(getattr(cls(), k))(v) for k, v in data.items()})

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)
