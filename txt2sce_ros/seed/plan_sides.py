"""Keeping each party on the side of the AV the report puts it (R1-R7): retiming a party that would start on
the wrong side, and saying in the manifest why a start still reads otherwise.

One concept of the seed planner (`plan.Planner` combines them); the methods work on the planner's state."""

from __future__ import annotations


import numpy as np

from ..sketch import Party
from .actor import Actor, predicted_gap
from .boxes import START_CLEARANCE
from .sides import on_reported_side, reported_code, start_position
from .track import Track

#: the fastest a party may drive, as a multiple of its category's cruise speed, to come from the side of the AV the
#: report puts it (a cyclist overtaking a turning AV from behind at 2 x 3 m/s is still an ordinary cyclist)
MAX_SPEED_FACTOR = 2.0


class ReportedSides:
    """Mixin of `plan.Planner` (reported sides of the AV)."""

    def _note_reported_sides(self) -> None:
        """Every party whose start does not read as its reported position (R1-R7 + lane, by the one definition in
        analysis.features.derived_position; a crossing party by where it stands) says so, and why, in its notes."""
        for p in self.sketch.npcs:
            actor = next((a for a in self.actors if a.name == p.id), None)
            if actor is None:
                continue
            crossing = p.actions[:1] == "m"
            got = start_position(self.ego, actor, by_place=crossing)
            want = reported_code(p.position, p.lane)
            if got == want:
                continue
            actor.notes.append(f"starts at {'/'.join(x for x in got if x)} by its start pose (reported "
                               f"{'/'.join(x for x in want if x)}): {self._side_reason(p, actor, got, crossing)}")
            self.choices["parties"].setdefault(p.id, {})["notes"] = actor.notes

    def _side_reason(self, p: Party, actor: Actor, got: tuple[str, str | None], crossing: bool) -> str:
        """Why a party cannot start where the report puts it (see _note_reported_sides)."""
        travel = float(np.max(self.ego_d[self.ego_t <= self.T + 2.0 + 1e-9])) if len(self.ego_d) else 0.0
        if crossing and got[0] == p.position:
            return "a crossing party waits beside the road; the lane reported is the one it crosses"
        if crossing and p.position == "R6" and travel > 1.0:
            if self._reversing_time(self.T) is not None:
                return (f"the AV moves {travel:.0f} m forward before it backs into the party, which crosses behind "
                        "where it reverses: ahead of the AV's start")
            return (f"the AV drives {travel:.0f} m to where the party pulls in behind it: the party waits beside "
                    "the road ahead of the AV's start and pulls in once the AV has passed")
        if got[0] == p.position and any(n.startswith("lateral offset") for n in actor.notes):
            return ("no lane change is reported and its first move comes too late to drift toward the AV, so its "
                    "whole path runs beside the AV's box for the reported contact, within a lane half-width of the "
                    "AV's centreline")
        if p.position == "R2" and got[0] == "R7":
            return "an oncoming party on the approach facing the AV reads as R7 while within a road's width of its lane"
        if isinstance(actor.track, Track) and self.net.roads[actor.track.lane_at(actor.d0).road_id].in_junction:
            return "it meets the AV inside the junction and starts there (its run-up is shorter than its way in)"
        if any(n.startswith("no ") and "keeps the reported contact" in n for n in actor.notes):
            return "no re-timing keeps the reported contact from there"
        return "placed where it meets the AV at the conflict time"

    def _retime_to_reported_side(self, p: Party, actor: Actor, build) -> Actor:
        """The party that touches the AV would start on the wrong side of it (a side-swiping car reported behind
        the AV starting ahead of it, a cyclist reported coming from behind starting ahead, a car reported beside it
        at the light starting behind): keep the meeting, change how it gets there. A moving party drives faster
        (to come from behind) or slower (to be caught up with), up to MAX_SPEED_FACTOR of its cruise speed; a
        standing one moves off later or earlier. The first candidate that starts on the reported side and still
        touches the AV in the plan wins; without one the original plan stays and the manifest says why."""
        ego = self.ego
        saved = (ego.d0, self.choices.get("ego_start_d"))
        base_gap, _ = predicted_gap([ego, actor], actor.name, self.horizon)
        behind = p.position == "R6"
        if actor.v0 > 0:
            steps = np.arange(0.1, MAX_SPEED_FACTOR - 1.0 + 1e-9, 0.1) if behind else np.arange(0.1, 0.71, 0.1)
            cands = [("speed", round(actor.v0 * (1.0 + f if behind else 1.0 - f), 2)) for f in steps]
        else:
            cands = [("shift", round(-s if behind else s, 2)) for s in np.arange(0.25, self.T + 1e-9, 0.25)]
        chosen = None
        for kind, value in cands:
            ego.d0 = saved[0]
            cand = build(speed=value) if kind == "speed" else build(shift=value)
            gap, _ = predicted_gap([ego, cand], cand.name, self.horizon)
            if on_reported_side(ego, cand, p.position) and gap <= max(base_gap, 0.0):
                chosen = (kind, value)
                break
        ego.d0 = saved[0]
        if saved[1] is not None:
            self.choices["ego_start_d"] = saved[1]
        if chosen is None:
            actor = build()
            how = f"no speed up to {MAX_SPEED_FACTOR:g}x its own" if actor.v0 > 0 else "no other time to move off"
            actor.notes.append(f"{how} starts it {'behind' if behind else 'beside or ahead of'} the AV (reported "
                               f"{p.position}) and keeps the reported contact")
            return actor
        kind, value = chosen
        actor = build(speed=value) if kind == "speed" else build(shift=value)
        if kind == "speed":
            actor.notes.append(f"speed {value:g} m/s so that it starts {'behind' if behind else 'ahead of'} the AV "
                               f"(reported {p.position}) and still meets it")
        else:
            actor.notes.append(f"moves off {abs(value):g} s {'earlier' if value < 0 else 'later'} so that it starts "
                               f"{'behind' if behind else 'beside or ahead of'} the AV (reported {p.position}) and "
                               "still meets it")
        return actor

    def _keep_reported_side(self, p: Party, actor: Actor) -> None:
        """A party reported behind (R6) or ahead of (R5) the AV that did not touch it starts there, clear of it:
        meeting the AV at the conflict time alone would start a follower that stops early ahead of the AV."""
        ego = self.ego
        pose = actor.track.world(actor.d0, actor.lat0)
        d_on_ego = float(ego.track.project(pose.x, pose.y))
        if p.position == "R6":   # its front behind the AV's rear
            shift = min(ego.d0 + ego.cx - ego.length / 2 - START_CLEARANCE - (actor.cx + actor.length / 2) - d_on_ego,
                        0.0)
        else:                    # its rear ahead of the AV's front
            shift = max(ego.d0 + ego.cx + ego.length / 2 + START_CLEARANCE - (actor.cx - actor.length / 2) - d_on_ego,
                        0.0)
        if shift:
            actor.d0 += shift
            actor.notes.append(f"start moved {shift:+.1f} m: reported {'behind' if shift < 0 else 'ahead of'} the AV")
