"""The planner's parameters as frozen dataclasses, one per concern, loaded from `config/planner.yaml`.

Every value in the YAML must name a field here (a typo is an `InputError` naming the file and key), and missing
keys keep the defaults below, so a partial YAML in a test or a campaign stays valid.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

from txt2sce_ros.config import check_sections, load_config, section_from_mapping
from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import config_dir

CONFIG_NAME = "planner"


@dataclass(frozen=True, slots=True)
class LongitudinalParams:
    """IDM / stop-point control. Speeds m/s, accelerations m/s², distances m, times s."""

    desired_speed: float = 10.0
    max_accel: float = 1.2
    comfort_decel: float = 2.0
    planned_stop_decel: float = 2.5
    max_decel: float = 7.0
    time_headway: float = 1.6
    min_gap: float = 2.5
    accel_exponent: float = 4.0
    stop_margin: float = 1.5
    stop_onset_ratio: float = 0.6
    friction_safety: float = 0.6
    gravity: float = 9.81


@dataclass(frozen=True, slots=True)
class LateralParams:
    """Pure pursuit and curve speed."""

    lookahead_min: float = 4.0
    lookahead_gain: float = 0.8
    max_yaw_rate: float = 0.16
    max_lateral_accel: float = 1.5
    curve_preview: float = 40.0
    replan_offset: float = 3.0


@dataclass(frozen=True, slots=True)
class ComfortParams:
    max_jerk: float = 0.8
    emergency_jerk: float = 12.0
    min_speed_command: float = 0.0


@dataclass(frozen=True, slots=True)
class BehaviourParams:
    path_half_width_margin: float = 0.4
    lead_heading_tolerance: float = 1.0
    signal_lateral_tolerance: float = 3.0
    signal_lookahead: float = 120.0
    yellow_clear_decel: float = 2.5
    prediction_horizon: float = 8.0
    prediction_step: float = 0.25
    conflict_margin: float = 1.0
    conflict_time_gap: float = 2.0
    pass_lateral_margin: float = 0.5
    start_clear_distance: float = 8.0
    goal_overshoot: float = 0.0


@dataclass(frozen=True, slots=True)
class PerceptionParams:
    """Options degrading the player's ground truth before the planner sees it (objects only; the ego's own
    state is localisation, taken as exact)."""

    position_noise: float = 0.0
    speed_noise: float = 0.0
    latency: float = 0.0
    seed: int = 0


@dataclass(frozen=True, slots=True)
class FaultParams:
    """Magnitudes used by the fault modes (the switches themselves are `standin_planner.faults.Faults`)."""

    stale_tracking_delay: float = 1.0
    close_start_radius: float = 6.0
    aggressive_start_accel: float = 7.0
    aggressive_start_yaw_rate: float = 0.5
    aggressive_start_speed: float = 3.0
    dry_friction: float = 1.0
    late_brake_decel: float = 6.5



@dataclass(frozen=True, slots=True)
class PlannerParams:
    longitudinal: LongitudinalParams = field(default_factory=LongitudinalParams)
    lateral: LateralParams = field(default_factory=LateralParams)
    comfort: ComfortParams = field(default_factory=ComfortParams)
    behaviour: BehaviourParams = field(default_factory=BehaviourParams)
    perception: PerceptionParams = field(default_factory=PerceptionParams)
    faults: FaultParams = field(default_factory=FaultParams)

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, source: str = "<dict>") -> "PlannerParams":
        check_sections(data, (f.name for f in fields(cls)), source)
        kinds = {"longitudinal": LongitudinalParams, "lateral": LateralParams, "comfort": ComfortParams,
                 "behaviour": BehaviourParams, "perception": PerceptionParams, "faults": FaultParams}
        return cls(**{name: section_from_mapping(kind, data.get(name), source, name) for name, kind in kinds.items()})

    @classmethod
    def from_config(cls, path: str | Path | None = None) -> "PlannerParams":
        """Parameters from `config/planner.yaml` (or `path`)."""
        source = str(path) if path else str(config_dir() / f"{CONFIG_NAME}.yaml")
        return cls.from_dict(load_config(CONFIG_NAME, path), source=source)

    def replace(self, **sections: Any) -> "PlannerParams":
        """A copy with whole sections replaced, or single values via `section={"key": value}` dicts."""
        out: dict[str, Any] = {}
        for name, value in sections.items():
            current = getattr(self, name)
            out[name] = dataclasses.replace(current, **value) if isinstance(value, dict) else value
        return dataclasses.replace(self, **out)
