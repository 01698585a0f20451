"""Kinematic models.

Vehicles driven by the planner: a kinematic bicycle (rear-axle reference point, wheelbase L). The planner's
ControlCommand gives the speed to reach by the next step and a yaw rate; the player turns them into a longitudinal
acceleration a = (v_cmd − v)/dt and a steering angle δ = atan(ω·L / v), then applies, in this order:

1. Performance: −maxDeceleration ≤ a ≤ maxAcceleration, |v| ≤ maxSpeed; |δ| ≤ maxSteering.
2. Friction (μ = road friction scale × 1.0): the tyres transmit at most μ·g in total (friction circle over the
   longitudinal and lateral accelerations a and v·ω).
   - Braking beyond it is capped on the circle (an ABS-like limit).
   - Traction beyond it spins the driven wheels: the vehicle gets **no** longitudinal acceleration that step
     (`slipping` is set). A planner that floors the throttle with large steering on a low-friction road therefore
     does not start, which a planner fault mode relies on.
   - A yaw rate whose lateral acceleration exceeds μ·g is cut to what friction allows (the vehicle understeers).
3. Integration over dt at the mean speed along the mean heading (exact for constant a and ω to second order).

Pedestrians: a point mass with the same speed/yaw-rate command, limited only by their Performance.
"""

from __future__ import annotations

import math
from typing import NamedTuple

G = 9.81


class BicycleResult(NamedTuple):
    """One step's accepted command (a NamedTuple: built once per step for the ego, cheaper than a dataclass)."""

    speed: float
    yaw_rate: float
    accel: float
    slipping: bool


def bicycle_command(v: float, v_cmd: float, w_cmd: float, dt: float, *, wheelbase: float, max_steer: float,
                    max_accel: float, max_decel: float, max_speed: float, friction: float,
                    is_vehicle: bool = True) -> BicycleResult:
    """Accepted speed, yaw rate and acceleration for one step (see module docstring)."""
    # Every min(max(x, lo), hi) of this function is written as the comparisons the builtins make (max(a, b) is
    # `b if b > a else a`, min(a, b) is `b if b < a else a`: the same value, NaN and signed zeros included), which
    # costs a fifth of the calls; this runs for every vehicle every step.
    a = (v_cmd - v) / dt
    lo = -max_decel if max_decel > 0 else -math.inf
    a = lo if lo > a else a
    hi = max_accel if max_accel > 0 else math.inf
    a = hi if hi < a else a
    w = w_cmd
    if is_vehicle and abs(v) > 1e-3:
        w_max = abs(v) * math.tan(max_steer) / (1e-3 if 1e-3 > wheelbase else wheelbase)
        lo = -w_max
        w = lo if lo > w else w
        w = w_max if w_max < w else w
    elif is_vehicle:
        w = 0.0                     # a standing car cannot turn on the spot
    slipping = False
    if is_vehicle:
        mu_g = (0.0 if 0.0 > friction else friction) * G
        lat = abs(v * w)
        if lat > mu_g:
            w = math.copysign(mu_g / max(abs(v), 1e-6), w)
            lat = mu_g
        if a > 0.0:
            # Traction demand: throttle plus the steering input, the latter as the lateral acceleration it asks
            # for at no less than 1 m/s (so steering hard while pulling away counts even at standstill).
            steer = abs(w_cmd) * max(abs(v), abs(v_cmd), 1.0)
            if math.hypot(a, max(lat, steer)) > mu_g:
                a = 0.0
                slipping = True
        elif a < 0.0:
            q = mu_g * mu_g - lat * lat
            room = math.sqrt(0.0 if 0.0 > q else q)
            lo = -room
            a = lo if lo > a else a
    v_new = v + a * dt
    if v_cmd >= 0.0 and v_new < 0.0 <= v:
        v_new = 0.0                 # braking stops; it does not reverse
    if max_speed > 0:
        lo = -max_speed
        v_new = lo if lo > v_new else v_new
        v_new = max_speed if max_speed < v_new else v_new
    return BicycleResult(v_new, w, (v_new - v) / dt, slipping)


def integrate(x: float, y: float, h: float, v0: float, v1: float, w: float, dt: float) -> tuple[float, float, float]:
    """Pose after dt at mean speed along the mean heading."""
    vm = 0.5 * (v0 + v1)
    hm = h + 0.5 * w * dt
    return x + vm * math.cos(hm) * dt, y + vm * math.sin(hm) * dt, h + w * dt
