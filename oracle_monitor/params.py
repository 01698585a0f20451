"""Oracle thresholds as frozen records, loaded from `config/oracle.yaml` (the paper's values by default)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, Mapping

from txt2sce_ros.config import check_sections, load_config, section_from_mapping
from txt2sce_ros.errors import InputError

COLLISION_RULES = ("contact", "jerk", "either")
JERK_MODES = ("magnitude", "signed")


@dataclass(frozen=True, slots=True)
class SafetyParams:
    collision_rule: str = "contact"
    jerk_threshold: float = 300.0          # m/s³
    jerk_max_interval: float = 0.015       # s
    contact_refine_steps: int = 12
    jerk_match_window: float = 0.5         # s
    struck_speed: float = 0.1              # m/s, an ego slower than this at contact was standing still: struck
    struck_from_behind: bool = True        # a rear-end by a faster entity behind, in line, is not the ego's crash
    unavoidable_decel: float = 8.0         # m/s², braking of the counterfactual ego that labels unavoidable crashes


@dataclass(frozen=True, slots=True)
class SmoothnessParams:
    window: float = 1.0                    # s
    jerk_low: float = 0.0                  # m/s³
    jerk_high: float = 0.9                 # m/s³
    jerk_mode: str = "magnitude"
    yaw_rate_limit_deg: float = 10.0       # deg/s
    min_speed: float = 0.0                 # m/s

    @property
    def yaw_rate_limit(self) -> float:
        """rad/s"""
        return math.radians(self.yaw_rate_limit_deg)


@dataclass(frozen=True, slots=True)
class SmartnessParams:
    start_distance: float = 0.5
    start_timeout: float = 5.0
    stop_speed: float = 0.1
    stop_timeout: float = 5.0
    park_time: float = 2.0
    clear_distance: float = 20.0
    clear_margin: float = 0.5
    conflict_distance: float = 40.0
    conflict_horizon: float = 8.0
    conflict_margin: float = 1.0
    light_half_width: float = 5.0
    light_heading_tolerance_deg: float = 60.0
    yellow_is_violation: bool = False
    visible_time: float = 1.0
    sensor_range: float = 80.0
    lane_types: tuple[str, ...] = ("driving",)


@dataclass(frozen=True, slots=True)
class OracleParams:
    safety: SafetyParams = field(default_factory=SafetyParams)
    smoothness: SmoothnessParams = field(default_factory=SmoothnessParams)
    smartness: SmartnessParams = field(default_factory=SmartnessParams)

    @classmethod
    def from_config(cls, path: str | None = None) -> "OracleParams":
        """Read `config/oracle.yaml` (or `path`); keys left out keep the paper's defaults, unknown keys are errors."""
        data = load_config("oracle", path)
        source = path or "config/oracle.yaml"
        check_sections(data, ("safety", "smoothness", "smartness"), source)
        return cls(
            safety=section_from_mapping(SafetyParams, data.get("safety", {}), source, "safety"),
            smoothness=section_from_mapping(SmoothnessParams, data.get("smoothness", {}), source, "smoothness"),
            smartness=section_from_mapping(SmartnessParams, data.get("smartness", {}), source, "smartness"),
        )._checked(source)

    def with_overrides(self, **sections: Mapping[str, Any]) -> "OracleParams":
        """A copy with some keys replaced, e.g. `with_overrides(safety={"collision_rule": "jerk"})`."""
        out = self
        for name, values in sections.items():
            out = replace(out, **{name: replace(getattr(out, name), **values)})
        return out._checked("overrides")

    def _checked(self, source: str) -> "OracleParams":
        if self.safety.collision_rule not in COLLISION_RULES:
            raise InputError(f"collision_rule must be one of {COLLISION_RULES}, got {self.safety.collision_rule!r}",
                             source=source, element="safety.collision_rule")
        if self.smoothness.jerk_mode not in JERK_MODES:
            raise InputError(f"jerk_mode must be one of {JERK_MODES}, got {self.smoothness.jerk_mode!r}",
                             source=source, element="smoothness.jerk_mode")
        if self.safety.struck_speed < 0:
            raise InputError("struck_speed must not be negative", source=source, element="safety.struck_speed")
        if self.smoothness.window <= 0:
            raise InputError("window must be positive", source=source, element="smoothness.window")
        return self
