"""Dynamics mutation family (Table III): TSM target speed, DTM transition dynamics, VPM vehicle performance."""

from __future__ import annotations

from typing import Any

import numpy as np
from lxml import etree

from .values import Recorder, gaussian, uniform

#: Elements of type TransitionDynamics in OpenSCENARIO 1.0 that an event's private actions carry.
DYNAMICS_TAGS = ("SpeedActionDynamics", "LaneChangeActionDynamics")
#: LaneOffsetActionDynamics is not a TransitionDynamics in 1.0: a shape and a maximum lateral acceleration.


def speed_style(action: str, cfg: dict[str, Any], rng: np.random.Generator) -> str:
    """'acc' or 'dec': from the event's action name when it names a direction, else drawn uniformly."""
    if action in cfg["accelerating_actions"]:
        return "acc"
    if action in cfg["decelerating_actions"]:
        return "dec"
    return "acc" if rng.random() < 0.5 else "dec"


def tsm(event: etree._Element, action: str, rng: np.random.Generator, cfg: dict[str, Any],
        rec: Recorder) -> str | None:
    """Target Speed Mutation on every AbsoluteTargetSpeed of the event: acc -> [x, 1.5x], dec -> [0.5x, x].
    Returns the style used, None when the event sets no absolute target speed."""
    targets = list(event.iter("AbsoluteTargetSpeed"))
    if not targets:
        return None
    style = speed_style(action, cfg, rng)
    lo, hi = cfg[style]
    for t in targets:
        x = float(t.get("value", "0"))
        new = x * uniform(rng, lo, hi)
        if x > 0:
            new = max(new, cfg["min_speed"])  # a moving party keeps moving; only a stop (x == 0) stays 0
        rec.set(t, "value", new, digits=3)
    return style


def initial_speed(private: etree._Element | None) -> float | None:
    """The Init SpeedAction's absolute target of an entity's Private (its speed at t = 0), None without one."""
    t = private.find("PrivateAction/LongitudinalAction/SpeedAction/SpeedActionTarget/AbsoluteTargetSpeed") \
        if private is not None else None
    try:
        return float(t.get("value", "0")) if t is not None else None
    except ValueError:
        return None


def standing_start(private: etree._Element, rec: Recorder) -> bool:
    """TSM on the ego's initial speed: a moving start becomes a standing one (target 0). Nothing else changes, so
    the AV sets off from its seed position along the same route. False when it already stands (or has no Init
    SpeedAction)."""
    v = initial_speed(private)
    if v is None or v <= 0.0:
        return False
    rec.set(private.find("PrivateAction/LongitudinalAction/SpeedAction/SpeedActionTarget/AbsoluteTargetSpeed"),
            "value", 0.0, digits=3)
    return True


def dtm(event: etree._Element, rng: np.random.Generator, cfg: dict[str, Any], rec: Recorder) -> bool:
    """Dynamic Transition Mutation: shape uniform over the configured shapes, value uniform in the range of its
    dynamicsDimension. Returns False when the event has no TransitionDynamics."""
    found = False
    for tag in DYNAMICS_TAGS:
        for dyn in event.iter(tag):
            found = True
            shapes = cfg["shapes"]
            rec.set(dyn, "dynamicsShape", str(shapes[int(rng.integers(len(shapes)))]))
            lo, hi = cfg["value"].get(dyn.get("dynamicsDimension", "time"), cfg["value"]["time"])
            rec.set(dyn, "value", uniform(rng, lo, hi), digits=3)
    for dyn in event.iter("LaneOffsetActionDynamics"):
        found = True
        shapes = cfg["shapes"]
        rec.set(dyn, "dynamicsShape", str(shapes[int(rng.integers(len(shapes)))]))
        rec.set(dyn, "maxLateralAcc", uniform(rng, *cfg["max_lateral_acc"]), digits=3)
    return found


def vpm(performance: etree._Element, defaults: tuple[float, float, float], rng: np.random.Generator,
        cfg: dict[str, Any], rec: Recorder) -> None:
    """Vehicle Performance Mutation: maxSpeed, maxAcceleration, maxDeceleration Gaussian around the category's
    defaults (sigma = share x default), clipped to [lo, hi] x default."""
    lo, hi = cfg["clip_share"]
    for attr, mean in zip(("maxSpeed", "maxAcceleration", "maxDeceleration"), defaults):
        rec.set(performance, attr, gaussian(rng, mean, cfg["sigma_share"] * mean, lo * mean, hi * mean), digits=3)
