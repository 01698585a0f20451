"""Traffic signals: states set by TrafficSignalStateAction and by TrafficSignalController phase cycles, published
as contract `TrafficLightState` records (state + stop line of the lanes the signal controls).

OpenSCENARIO gives states as free strings; esmini's convention is one on/off per lamp, top to bottom
("on;off;off" = red of a red/yellow/green head, "off;on" = green of a red/green head). Named colours pass through.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

from txt2sce_ros.contract import SignalState, TrafficLightState
from txt2sce_ros.road import RoadNetwork


@lru_cache(maxsize=1024)
def state_of(text: str) -> SignalState:
    """The colour a state text shows (cached: a run decodes the same few texts every step)."""
    low = text.strip().lower()
    for s in SignalState:
        if low == s.value:
            return s
    lamps = [p.strip() for p in low.split(";")]
    if len(lamps) >= 2 and all(p in ("on", "off", "flashing") for p in lamps):
        colours = ([SignalState.RED, SignalState.YELLOW, SignalState.GREEN] if len(lamps) == 3
                   else [SignalState.RED, SignalState.GREEN])
        for lamp, colour in zip(lamps, colours):
            if lamp != "off":
                return colour
        return SignalState.OFF
    return SignalState.OFF


@dataclass(frozen=True, slots=True)
class Phase:
    name: str
    duration: float
    states: tuple[tuple[str, str], ...]        # (signal id, state text)


@dataclass(frozen=True, slots=True)
class SignalController:
    name: str
    delay: float
    phases: tuple[Phase, ...]


class SignalBoard:
    def __init__(self, net: RoadNetwork) -> None:
        self.net = net
        self.states: dict[str, str] = {}
        self.controllers: dict[str, SignalController] = {}
        self.phase_start: dict[str, tuple[int, float]] = {}   # controller -> (phase index, start time)
        self._geometry: dict[str, tuple[float, float, float, str, tuple[int, ...]]] = {}
        # lights() is asked for every frame but changes only when a state does: the records are frozen, so the
        # same tuple is handed out until the (id, text) items differ.
        self._lights_key: tuple[tuple[str, str], ...] | None = None
        self._lights: tuple[TrafficLightState, ...] = ()
        for sid, sig in net.signals.items():
            if getattr(sig, "dynamic", False):
                self.states.setdefault(sid, "off")

    def add_controller(self, ctrl: SignalController) -> None:
        self.controllers[ctrl.name] = ctrl
        if ctrl.phases:
            self.phase_start[ctrl.name] = (0, ctrl.delay)
            self._apply_phase(ctrl, 0)

    def _apply_phase(self, ctrl: SignalController, idx: int) -> None:
        for sid, state in ctrl.phases[idx].states:
            self.states[sid] = state

    def set_state(self, name: str, state: str) -> None:
        self.states[name] = state

    def set_phase(self, controller: str, phase: str, t: float) -> None:
        ctrl = self.controllers.get(controller)
        if ctrl is None:
            return
        for i, ph in enumerate(ctrl.phases):
            if ph.name == phase:
                self.phase_start[controller] = (i, t)
                self._apply_phase(ctrl, i)

    def controller_phase(self, controller: str) -> str:
        ctrl = self.controllers.get(controller)
        if ctrl is None or controller not in self.phase_start:
            return ""
        return ctrl.phases[self.phase_start[controller][0]].name

    def state_text(self, name: str) -> str:
        return self.states.get(name, "")

    def step(self, t: float) -> None:
        """Advance controller phases whose duration has elapsed."""
        if not self.phase_start:
            return                      # no controllers (most scenarios): nothing to copy and walk each step
        for name, (idx, start) in list(self.phase_start.items()):
            ctrl = self.controllers[name]
            if t < start:
                continue
            dur = ctrl.phases[idx].duration
            if dur > 0 and t - start >= dur - 1e-9:
                nxt = (idx + 1) % len(ctrl.phases)
                self.phase_start[name] = (nxt, start + dur)
                self._apply_phase(ctrl, nxt)

    def lights(self) -> tuple[TrafficLightState, ...]:
        key = tuple(self.states.items())
        if key != self._lights_key:
            self._lights = self._build_lights()
            self._lights_key = key
        return self._lights

    def _build_lights(self) -> tuple[TrafficLightState, ...]:
        out = []
        for sid in sorted(self.states):
            x, y, h, road_id, lanes = self._stop_line(sid)
            out.append(TrafficLightState(id=sid, state=state_of(self.states[sid]), stop_x=x, stop_y=y, heading=h,
                                         road_id=road_id, lane_ids=lanes))
        return tuple(out)

    def _stop_line(self, sid: str) -> tuple[float, float, float, str, tuple[int, ...]]:
        geo = self._geometry.get(sid)
        if geo is not None:
            return geo
        sig = self.net.signals.get(sid)
        if sig is None:
            geo = (math.nan, math.nan, 0.0, "", ())
        else:
            lanes = tuple(getattr(sig, "controlled_lanes", ()) or ())
            x, y, h = sig.x, sig.y, sig.heading
            if lanes:
                try:
                    x, y, h = self.net.lane_to_world(sig.road_id, lanes[0], sig.s)
                except Exception:  # noqa: BLE001 - a sloppy map keeps the signal's own pose
                    pass
            geo = (float(x), float(y), float(h), str(sig.road_id), lanes)
        self._geometry[sid] = geo
        return geo
