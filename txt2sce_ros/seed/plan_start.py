"""No two footprints touch at t=0: starts are moved apart along their paths, never past the AV, keeping the
reported contact where a shift allows it (a contact in the first frame is an invalid scenario, not a collision).

One concept of the seed planner (`plan.Planner` combines them); the methods work on the planner's state."""

from __future__ import annotations

import math

import numpy as np

from .actor import Actor, predicted_gap
from .boxes import START_CLEARANCE
from .kinematics import box_corners, boxes_gap
from .track import Track

#: m a start may be moved along its path to clear another entity
MAX_START_SHIFT = 30.0


class StartSeparation:
    """Mixin of `plan.Planner` (footprints apart at t=0)."""

    # ---- nobody overlaps at t=0
    def _start_box(self, a: Actor, d0: float | None = None) -> np.ndarray:
        p = a.track.world(a.d0 if d0 is None else d0, a.lat0)
        return box_corners(p.x, p.y, p.h, a.length, a.width, a.cx)

    def _separate_at_start(self) -> None:
        """Keep every two footprints START_CLEARANCE apart at t=0. The placement rules each put one entity where it
        meets the AV, so two can land on one spot (two obstacles ahead, a parked car where a reversing car starts)
        or a party can start touching the AV (a reversing car whose run-up is shorter than a car length); the
        player would then start in a collision. Entities are settled one by one — the AV, the reported party, then
        the rest in planning order — each moved along its path just clear of those already settled."""
        target = self.sketch.collision.with_
        order = sorted(self.actors, key=lambda a: (a is not self.ego, a.name != target))
        settled: list[tuple[Actor, np.ndarray]] = []
        for actor in order:
            box = self._start_box(actor)
            hit = next((a for a, b in settled if boxes_gap(box, b) < START_CLEARANCE - 1e-6), None)
            if hit is not None and not (isinstance(actor.track, Track) and self._shift_start(actor, hit, settled)):
                self.choices.setdefault("start_overlap", []).append(f"{hit.name}-{actor.name}")
            settled.append((actor, self._start_box(actor)))

    def _shift_start(self, actor: Actor, hit: Actor, settled: list[tuple[Actor, np.ndarray]]) -> bool:
        """Move `actor` along its path by the smallest distance that clears the settled footprints, away from `hit`
        first, never past the AV (a party reported behind it stays behind). A party reported to touch the AV must
        still do so later in the plan; when no shift allows that, the smallest clearing one is taken and noted."""
        def lon(box: np.ndarray, of: np.ndarray, h: float) -> float:
            """How far the centre of `box` lies ahead of the centre of `of` along heading h."""
            c, ref = box.mean(axis=0), of.mean(axis=0)
            return float((c[0] - ref[0]) * math.cos(h) + (c[1] - ref[1]) * math.sin(h))

        own_h = actor.track.world(actor.d0, actor.lat0).h
        away = -1.0 if lon(self._start_box(hit), self._start_box(actor), own_h) > 0 else 1.0
        ego_box, ego_h = self._start_box(self.ego), self.ego.track.world(self.ego.d0).h
        side = math.copysign(1.0, lon(self._start_box(actor), ego_box, ego_h))
        contact = self.sketch.collision.with_ == actor.name
        d_orig, fallback = actor.d0, None
        for mag in np.arange(0.25, MAX_START_SHIFT + 1e-9, 0.25):
            for sign in (away, -away):
                d = d_orig + sign * float(mag)
                if not 0.0 <= d <= actor.track.length:
                    continue
                box = self._start_box(actor, d)
                if any(boxes_gap(box, b) < START_CLEARANCE for _, b in settled) or \
                        lon(box, ego_box, ego_h) * side < 0:
                    continue
                if contact:
                    actor.d0 = d
                    gap, _ = predicted_gap(self.actors, actor.name, self.horizon)
                    actor.d0 = d_orig
                    if gap > 0.0:
                        fallback = d if fallback is None else fallback
                        continue
                self._moved(actor, d, d_orig, "")
                return True
        if fallback is None:
            return False
        self._moved(actor, fallback, d_orig, "; the reported contact no longer happens in the plan")
        return True

    def _moved(self, actor: Actor, d: float, d_orig: float, why: str) -> None:
        actor.d0 = d
        actor.notes.append(f"start moved {d - d_orig:+.2f} m along its path: it overlapped another entity at "
                           f"t=0{why}")
        self.ev.check_lane_changes(actor)
        if actor.name in self.choices.get("parties", {}):
            self.choices["parties"][actor.name]["start_d"] = round(d, 2)
        elif actor.name in self.choices.get("obstacles", {}):
            self.choices["obstacles"][actor.name]["d"] = round(d, 2)
            self.choices["obstacles"][actor.name]["note"] = actor.notes[-1]
