"""From a stream of contract messages to run verdicts: the one path the live monitor node and the offline judge
share, so a recording re-judged offline gives the verdict the live run gave.

A run starts with a scenario envelope on `/txt2sce/scenario` (or a `started` run status, or the first frame when a
bag has neither) and ends with a `finished` run status; a new envelope before that ends the previous run as
incomplete. A `finished` status that overtakes the run's last frames (topics are not ordered against each other)
is held until a frame reaches its time, the next run starts, or the input ends. Messages may be rclpy messages (live) or rosbags-decoded ones (offline): the `ros_io` conversions only
read attributes, which both kinds share.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field, replace
from typing import Any, Callable

from txt2sce_ros import contract as c
from txt2sce_ros.contract import Goal, RunStatus, ScenarioEnvelope
from txt2sce_ros.errors import Txt2SceError
from txt2sce_ros.ros_io import FrameAssembler, pose_to_goal

from .oracle import Oracle
from .params import OracleParams
from .records import RunVerdict, Violation


@dataclass
class RunState:
    scenario_id: str = ""
    envelope: ScenarioEnvelope | None = None
    goal: Goal | None = None
    network: Any | None = None
    oracle: Oracle | None = None
    notes: list[str] = field(default_factory=list)


_NETWORKS: dict[str, Any] = {}


def network_for(envelope: ScenarioEnvelope) -> tuple[Any | None, str]:
    """The road network of a scenario (from the OpenDRIVE text it carries, else its map path), cached by content;
    (None, why) when there is none or it does not load."""
    from txt2sce_ros.road import RoadNetwork, load_network

    try:
        if envelope.map_xodr:
            key = hashlib.sha1(envelope.map_xodr.encode()).hexdigest()
            if key not in _NETWORKS:
                _NETWORKS[key] = RoadNetwork.from_string(envelope.map_xodr, source=envelope.map_path or envelope.id)
            return _NETWORKS[key], ""
        if envelope.map_path:
            return load_network(envelope.map_path), ""
    except (Txt2SceError, OSError) as exc:
        return None, f"road network not loaded: {exc}"
    return None, "the scenario envelope carries no map"


class JudgeSession:
    """Feed `on_message(topic, msg)` in arrival order; finished runs land in `verdicts`. `on_verdict` and
    `on_violations` are called as they happen (the node publishes from them)."""

    def __init__(self, params: OracleParams | None = None, *,
                 on_violations: Callable[[float, list[Violation]], None] | None = None,
                 on_verdict: Callable[[RunVerdict], None] | None = None) -> None:
        self.params = params or OracleParams.from_config()
        self.on_violations = on_violations
        self.on_verdict = on_verdict
        self.assembler = FrameAssembler()
        self.run: RunState | None = None
        self.verdicts: list[RunVerdict] = []
        self.frames_seen = 0
        self._pending: RunStatus | None = None

    # --- dispatch ------------------------------------------------------------------------------------------------

    def on_message(self, topic: str, msg: Any) -> None:
        if topic == c.TOPIC_EGO_ODOM:
            # The ego is whoever /sim/ego/odom names (a scenario's own "Ego", "hero", ...), not a fixed name.
            if msg.child_frame_id != self.assembler.ego_name:
                self.assembler.ego_name = msg.child_frame_id
            self._frame(self.assembler.add_odometry(msg))
        elif topic == c.TOPIC_OBJECTS_ODOM:
            self._frame(self.assembler.add_odometry(msg))
        elif topic == c.TOPIC_OBJECTS_MARKERS:
            self._frame(self.assembler.add_markers(msg))
        elif topic == c.TOPIC_TRAFFIC_LIGHTS:
            self.assembler.add_lights(msg)
        elif topic == c.TOPIC_GOAL:
            goal = pose_to_goal(msg)
            self._settle()                        # a goal after a finished status is the next run's
            run = self._ensure_run()
            run.goal = goal
            if run.oracle is not None:
                run.oracle.set_goal(goal)
        elif topic == c.TOPIC_SCENARIO:
            self._start(ScenarioEnvelope.from_json(msg.data))
        elif topic == c.TOPIC_RUN_STATUS:
            status = RunStatus.from_json(msg.data)
            if status.state == "finished":
                if self.run is not None:
                    oracle = self.run.oracle
                    if oracle is not None and oracle.t_last < status.t - 1e-6:
                        # DDS does not order topics against each other: the last frames may still be on their
                        # way. Hold the status until a frame reaches its time, the next run starts, or input ends.
                        self._pending = status
                    else:
                        self.finish(status)
            else:
                self._settle()
                if self.run is None or (self.run.oracle is not None and self.run.oracle.frames):
                    self._start(None, status.scenario_id)

    def _settle(self) -> None:
        """Finish the run whose final status is being held (see TOPIC_RUN_STATUS)."""
        if self._pending is not None:
            self.finish(self._pending)

    def _start(self, envelope: ScenarioEnvelope | None, scenario_id: str = "") -> None:
        run = self.run
        if self._pending is not None and not (envelope is not None and run is not None and run.envelope is not None
                                              and run.envelope.id == envelope.id):
            self._settle()
            run = self.run
        if run is not None and envelope is not None and run.envelope is not None and run.envelope.id == envelope.id:
            return                                # the same envelope delivered again (transient-local history)
        # A run that has not seen a frame nor an envelope yet (only its goal or its 'started' status) is this one.
        if run is not None and (run.oracle is not None or (run.envelope is not None and envelope is not None)):
            self.finish(None)                     # the previous run never reported its end
            run = None
        run = run or RunState()
        if envelope is not None:
            run.envelope = envelope
            run.network, why = network_for(envelope)
            if why:
                run.notes.append(why)
        run.scenario_id = envelope.id if envelope else (scenario_id or run.scenario_id)
        self.run = run
        self.assembler.reset()

    def _ensure_run(self) -> RunState:
        if self.run is None:
            self.run = RunState()
        return self.run

    def _frame(self, frame: Any) -> None:
        if frame is None:
            return
        run = self._ensure_run()
        if run.oracle is None:
            run.oracle = Oracle(run.network, run.goal, self.params, scenario_id=run.scenario_id)
        self.frames_seen += 1
        new = run.oracle.observe(frame)
        if new and self.on_violations:
            self.on_violations(frame.t, new)
        if self._pending is not None and frame.t >= self._pending.t - 1e-6:
            self._settle()

    # --- end of a run --------------------------------------------------------------------------------------------

    def finish(self, status: RunStatus | None) -> RunVerdict:
        """Close the current run with its final status (None: it never reported one) and return its verdict."""
        self._pending = None
        run = self._ensure_run()
        oracle = run.oracle or Oracle(run.network, run.goal, self.params, scenario_id=run.scenario_id)
        verdict = oracle.finish(status)
        if run.notes:
            verdict = replace(verdict, notes=tuple(run.notes) + verdict.notes)
        self.verdicts.append(verdict)
        self.run = None
        self.assembler.reset()
        if self.on_verdict:
            self.on_verdict(verdict)
        return verdict

    def close(self) -> RunVerdict | None:
        """End of input (shutdown, end of the bag): a run still open is judged as incomplete."""
        if self._pending is not None:
            return self.finish(self._pending)
        if self.run is not None and (self.run.oracle is not None or self.run.envelope is not None):
            return self.finish(None)
        return None
