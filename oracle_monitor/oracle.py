"""The oracle core: `Oracle(network, goal, params).observe(frame)` online, `finish(status)` for the verdict.

Plain Python (no rclpy). The monitor node, the offline judge and the in-process campaign all drive this one class
with the same frames, so live and offline verdicts agree by construction.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from txt2sce_ros.contract import Frame, Goal, RunStatus

from .params import OracleParams
from .records import Category, Rule, RunVerdict, Violation
from .safety import Contact, ContactOracle, JerkCollisionOracle, reported_beside
from .signals import Differentiator
from .smartness import SmartnessOracle
from .smoothness import SmoothnessOracle
from .unavoidable import Counterfactual, assess
from .verdict import decide, error_reason


class Oracle:
    """Judges one run. `network` is a `txt2sce_ros.road.RoadNetwork` (None: lane checks are skipped and noted)."""

    def __init__(self, network: Any | None = None, goal: Goal | None = None, params: OracleParams | None = None,
                 *, scenario_id: str = "") -> None:
        self.params = params or OracleParams.from_config()
        self.network = network
        self.goal = goal
        self.scenario_id = scenario_id
        rule = self.params.safety.collision_rule
        self._contact_category = Category.COLLISIONS if rule in ("contact", "either") else None
        self._kin = Differentiator()
        self.contact = ContactOracle(self.params.safety)
        self.jerk = JerkCollisionOracle(self.params.safety,
                                        Category.COLLISIONS if rule in ("jerk", "either") else None)
        self.smooth = SmoothnessOracle(self.params.smoothness)
        self.smart = SmartnessOracle(self.params.smartness, goal, network)
        self.violations: list[Violation] = []
        self._replay = Counterfactual()
        self.frames = 0
        self.t_last = 0.0
        self._finished: RunVerdict | None = None
        self._end_reason = ""

    def set_network(self, network: Any | None) -> None:
        """The road network arrived after the first frame (its scenario came late)."""
        self.network = network
        self.smart.set_network(network)

    def set_goal(self, goal: Goal) -> None:
        """The goal arrived after the first frame (topics are not ordered across each other)."""
        self.goal = goal
        self.smart.goal = goal

    def observe(self, frame: Frame) -> list[Violation]:
        """Judge one frame; returns the violations that start at it (often none). Frames not later than the last
        one are ignored (duplicates delivered twice)."""
        sample = self._kin.update(frame.ego)
        if sample is None:
            return []
        self._replay.observe(frame)
        self.frames += 1
        self.t_last = frame.t
        new: list[Violation] = []
        for contact in self.contact.observe(frame):
            new.append(self._classify_contact(contact, frame))
        jerk = self.jerk.observe(sample, frame)
        if jerk:
            new.append(jerk)
        new.extend(self.smooth.observe(sample))
        new.extend(self.smart.observe(frame, sample))
        self.violations.extend(new)
        return new

    def _classify_contact(self, contact: Contact, frame: Frame) -> Violation:
        beside = reported_beside(contact, self.params.safety)
        if beside is not None:
            return beside
        t, obj, depth = contact.t, contact.entity, contact.depth
        ego = frame.ego
        rel = ego.speed - obj.speed
        seen = self.smart.visible_for(obj.name, t)
        if obj.is_static and seen >= self.params.smartness.visible_time:
            return Violation(Rule.STATIC_OBSTACLE_HIT, Category.MISINTERP, t, seen,
                             self.params.smartness.visible_time, "s", (obj.name,),
                             f"hit static {obj.category} {obj.name} in view for {seen:.1f} s "
                             f"(ego {ego.speed:.2f} m/s, overlap {depth:.2f} m)")
        return Violation(Rule.CONTACT, self._contact_category, t, depth, 0.0, "m", (obj.name,),
                         f"contact with {obj.category} {obj.name} (ego {ego.speed:.2f} m/s, "
                         f"closing {rel:+.2f} m/s, overlap {depth:.2f} m)")

    def finish(self, status: RunStatus | None) -> RunVerdict:
        """The verdict of the run; `status` is the player's final RunStatus (None: the run never reported its end).
        Calling it twice returns the same verdict."""
        if self._finished is not None:
            return self._finished
        t_end = status.t if status and status.t else self.t_last
        self._end_reason = status.end_reason if status else ""
        # End-of-run checks (goal reached, never started) judge the system under test: not for runs that broke.
        if status is not None and status.state == "finished" and not error_reason(status, self.frames):
            self.violations.extend(self.smart.finish(t_end, status.end_reason))
        notes = self._notes()
        if status is not None and status.unsupported:
            # The run went on without these elements: a verdict on a scenario that was not played as written.
            notes += (f"the player skipped {len(status.unsupported)} unsupported element(s): "
                      + "; ".join(status.unsupported[:5]),)
        verdict = decide(tuple(self.violations), status, frames=self.frames, t_end=t_end,
                         scenario_id=self.scenario_id, notes=notes)
        self._finished = self._label_unavoidable(verdict, t_end)
        return self._finished

    def _label_unavoidable(self, verdict: RunVerdict, t_end: float) -> RunVerdict:
        """The failed categories the scripted parties made unavoidable (`unavoidable.py`), beside the verdict."""
        if verdict.verdict.value != "fail":
            return verdict
        cats = {f.category for f in verdict.categories}
        plan = verdict.finding(Category.PLAN_FAIL)
        blocker = ""
        if plan is not None and plan.rule is Rule.GOAL_NOT_REACHED and self.smart.last_frame is not None:
            blocker = self.smart.blocker_ahead(self.smart.last_frame)
        labels = assess(self._replay, cats, decel=self.params.safety.unavoidable_decel,
                        jerk=self.params.smoothness.jerk_high, t_end=t_end, blocker=blocker)
        if not labels:
            return verdict
        return replace(verdict, unavoidable=tuple(labels[f.category] for f in verdict.categories
                                                  if f.category in labels))

    def _notes(self) -> tuple[str, ...]:
        notes = []
        if self.network is None:
            notes.append("no road network: the parked-outside-lane check was skipped")
        if self.goal is None:
            notes.append("no goal: reaching the goal was not judged")
        if self.jerk.coarse_interval is not None:
            notes.append(f"jerk rule computed over {self.jerk.coarse_interval * 1000:.0f} ms frames (paper: "
                         f"5–15 ms)")
        contacts = [v for v in self.violations if v.rule in (Rule.CONTACT, Rule.STATIC_OBSTACLE_HIT)]
        struck = [v for v in self.violations if v.rule in (Rule.STRUCK_WHILE_STOPPED, Rule.STRUCK_FROM_BEHIND)]
        if self._end_reason == "collision" and not contacts and not struck:
            notes.append("the player ended the run on a collision that the footprints never showed (check the "
                         "entities' bounding boxes)")
        jerks = [v for v in self.violations if v.rule is Rule.JERK_COLLISION]
        w = self.params.safety.jerk_match_window
        both = sum(1 for c in contacts if any(abs(j.t - c.t) <= w for j in jerks))
        notes.append(f"collision rules: {len(contacts)} contact(s), {len(jerks)} jerk event(s) "
                     f"(|jerk| > {self.params.safety.jerk_threshold:g} m/s³), {both} contact(s) matched by a jerk "
                     f"event within {w:g} s")
        notes.append(f"peak 1 s mean |jerk| {self.smooth.peak_jerk:.3f} m/s³, |yaw rate| "
                     f"{self.smooth.peak_yaw_rate * 57.29577951308232:.2f} °/s")
        return tuple(notes)
