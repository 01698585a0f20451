"""From a stream of contract messages to run verdicts: the one path the live monitor node and the offline judge
share, so a recording re-judged offline gives the verdict the live run gave.

A run starts with a scenario envelope on `/txt2sce/scenario` (or a `started` run status, or the first frame when a
bag has neither) and ends with a `finished` run status; a different scenario, or frames whose time goes back
(each run's clock restarts), before that end the previous run as incomplete.

Topics are not ordered against each other, and a monitor that falls behind receives each topic's backlog in its
own order: the player's `finished` status and the next run's scenario, status and goal may overtake the last
frames of a run. So a `finished` status ahead of the frames is held until a frame reaches its time; meanwhile the
next run's start messages wait, and its frame messages (recognised by a topic's stamps going back) are
assembled apart.
The node records messages in arrival order and the offline judge replays that order, so both decide alike. Messages may be rclpy messages (live) or rosbags-decoded ones (offline): the `ros_io` conversions only
read attributes, which both kinds share.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field, replace
from typing import Any, Callable

from txt2sce_ros import contract as c
from txt2sce_ros.contract import Goal, RunStatus, ScenarioEnvelope
from txt2sce_ros.errors import Txt2SceError
from txt2sce_ros.ros_io import FrameAssembler, pose_to_goal, stamp_key

from .oracle import Oracle
from .params import OracleParams
from .records import RunVerdict, Violation


#: Frames of the next run collected before the current run is closed anyway: with its held final status if it has
#: one (its last frames were lost in transport), else as incomplete (a bag recorded without run statuses, a player
#: that died between runs).
NEXT_RUN_PATIENCE = 40

_FRAME_TOPICS = frozenset({c.TOPIC_EGO_ODOM, c.TOPIC_OBJECTS_ODOM, c.TOPIC_OBJECTS_MARKERS, c.TOPIC_TRAFFIC_LIGHTS})


def _stamp_key(topic: str, msg: Any) -> int | None:
    """Integer nanoseconds of a frame message's stamp (a MarkerArray's first marker's), None if it has none."""
    if topic == c.TOPIC_OBJECTS_MARKERS:
        if not msg.markers:
            return None
        return stamp_key(msg.markers[0].header.stamp)
    return stamp_key(msg.header.stamp)


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
                 on_verdict: Callable[[RunVerdict], None] | None = None,
                 on_frame: Callable[[Any], None] | None = None) -> None:
        self.params = params or OracleParams.from_config()
        self.on_frame = on_frame                            # every judged frame, in order (trajectory keeping)
        self.on_violations = on_violations
        self.on_verdict = on_verdict
        self.assembler = FrameAssembler()
        self.run: RunState | None = None
        self.verdicts: list[RunVerdict] = []
        self.frames_seen = 0
        self._pending: RunStatus | None = None             # a final status held for the run's last frames
        self._deferred: list[tuple[str, Any]] = []          # the next run's scenario / status / goal messages
        self._goal_key = -1                                 # stamp of the current run's latest goal
        self._next: FrameAssembler | None = None            # ... and its frame messages, assembled apart
        self._next_frames: list[Any] = []
        self._gen = 0                                       # generation of the current run
        self._used = False                                  # whether the current run got a frame message
        self._topic_gen: dict[str, int] = {}                # each frame topic's generation and latest stamp
        self._topic_key: dict[str, int] = {}
        self._names_at_key: dict[str, set[str]] = {}        # entities seen at the topic's latest stamp
        self._cur_max_key = -1                              # latest stamp of the current run, of the next run,
        self._next_max_key = -1                             # and of the previous run (where it ended)
        self._prev_end_key = -1
        self.dropped = 0                                    # late messages of finished runs
        self._judged_envelope: ScenarioEnvelope | None = None  # the scenario of the run judged last
        self._judged_id = ""                                # ... and its name (from a status if it had no envelope)

    # --- dispatch ------------------------------------------------------------------------------------------------

    def on_message(self, topic: str, msg: Any) -> None:
        if topic in _FRAME_TOPICS:
            self._frame_message(topic, msg)
            return
        if topic == c.TOPIC_RUN_STATUS:
            # The player's statuses come in order on their one topic (started a, finished a, started b, ...), so
            # they need no matching by name (names differ between paths: a file path in-process, the envelope id
            # over ROS): a status behind a held one, or behind waiting start messages, is the next run's.
            status = RunStatus.from_json(msg.data)
            if self._pending is not None or (self._deferred and status.state != "finished"):
                self._deferred.append((topic, msg))
            elif status.state != "finished":
                self._start(None, status.scenario_id)
            elif self.run is not None:
                t_last = self.run.oracle.t_last if self.run.oracle is not None else None
                if status.t > 1e-6 and (t_last is None or t_last < status.t - 1e-6):
                    # The last frames are still on their way: hold the status until a frame reaches its time, a
                    # topic's stamps going back show that the next run began, or the input ends.
                    self._pending = status
                else:
                    self._end_run(status)
        elif topic == c.TOPIC_SCENARIO:
            # The generator's envelope is not ordered against the player's messages: one for another scenario
            # while the current run is under way waits for that run's end.
            envelope = ScenarioEnvelope.from_json(msg.data)
            run = self.run
            if self._pending is not None or self._deferred or (
                    run is not None and run.envelope is not None and run.envelope.id != envelope.id
                    and run.oracle is not None):
                self._deferred.append((topic, msg))
            else:
                self._start(envelope)
        elif topic == c.TOPIC_GOAL:
            # The player repeats the goal with every frame, stamped with the frame's time (for a stack that joins
            # late). Within a run the stamps grow: a goal stamped later than the run's last one is a repeat and
            # says nothing new. (Kept, the repeats were deferred as the next run's, below, and a scenario envelope
            # arriving late behind them was deferred too and never adopted by its run.)
            key = stamp_key(msg.header.stamp)
            run = self.run
            if run is not None and run.goal is not None and key > self._goal_key:
                self._goal_key = key
                return
            if self._pending is not None or self._deferred or (
                    run is not None and run.goal is not None and run.oracle is not None):
                # Another goal while the run has one (and frames), or behind the next run's waiting messages: the
                # next run's, ahead of its scenario. Its repeats are not kept.
                last = next((m for t, m in reversed(self._deferred) if t == c.TOPIC_GOAL), None)
                if last is None or pose_to_goal(msg) != pose_to_goal(last):
                    self._deferred.append((topic, msg))
                return
            goal = pose_to_goal(msg)
            run = self._ensure_run()
            run.goal, self._goal_key = goal, key
            if run.oracle is not None:
                run.oracle.set_goal(goal)

    def _frame_message(self, topic: str, msg: Any) -> None:
        """Route a frame message to the current run, the next one, or nowhere (a late one of a finished run).

        Each topic's stamps only grow within a run and restart with the next (the player's clock restarts), and
        each topic is delivered in order: so a topic whose stamps go back has moved on to the next run. Runs and
        topics carry generation numbers: run g takes the messages of generation g on every topic."""
        key = _stamp_key(topic, msg)
        gen, last = self._topic_gen.get(topic), self._topic_key.get(topic)
        if gen is None or gen < self._gen - 1:
            # First use of this topic in a while: it belongs to the run now under way on the other topics.
            next_begun = any(g > self._gen for g in self._topic_gen.values())
            gen = self._gen + 1 if next_begun else self._gen
        elif key is not None and last is not None and key < last:
            gen += 1                                # stamps went back: the next run's clock
        elif key is not None and key == last and gen == self._gen - 1 and self._repeat(topic, msg):
            gen += 1                                # the previous run ended at this very stamp, this one starts
                                                    # there (a run broken at t = 0, then the next from t = 0)
        elif gen == self._gen - 1 and key is not None and key > self._prev_end_key:
            gen = self._gen                         # later than the previous run ever got: not one of its own
        self._topic_gen[topic] = gen
        if key is not None:
            if key != last:
                self._names_at_key.pop(topic, None)
            self._topic_key[topic] = key
            if topic == c.TOPIC_OBJECTS_ODOM:
                names = self._names_at_key.get(topic)
                if names is None:
                    names = self._names_at_key[topic] = set()
                names.add(msg.child_frame_id)
        if gen < self._gen:
            self.dropped += 1                      # a finished run's late message (e.g. its last lights)
            return
        if gen == self._gen:
            self._used = True
            if key is not None and key > self._cur_max_key:
                self._cur_max_key = key
            self._feed(self.assembler, topic, msg, key, self._frame)
            return
        if key is not None and key > self._next_max_key:
            self._next_max_key = key
        # The next run's. Kept apart until the current run ends: by its final status (usually just behind), or —
        # when none comes within NEXT_RUN_PATIENCE frames of the next run — as a run that never reported its end.
        if self._next is None:
            self._next = FrameAssembler()
        self._feed(self._next, topic, msg, key, self._next_frames.append)
        if len(self._next_frames) > NEXT_RUN_PATIENCE:
            # The current run's end never came (or its last frames were lost in transport): close it with what
            # it has — its held final status, if any.
            self._end_run(self._pending)

    def _repeat(self, topic: str, msg: Any) -> bool:
        """Right after a run ended, a message with the stamp of the topic's last one starts the next run — except
        another entity's odometry of the same step (several per step on /sim/objects/odom)."""
        if topic != c.TOPIC_OBJECTS_ODOM:
            return True
        return msg.child_frame_id in self._names_at_key.get(topic, ())

    @staticmethod
    def _feed(asm: FrameAssembler, topic: str, msg: Any, key: int | None, sink: Callable[[Any], None]) -> None:
        # `key` is `_stamp_key(topic, msg)`: the assembler's own key of the message (None only for an empty
        # MarkerArray, which the assembler ignores).
        if topic == c.TOPIC_EGO_ODOM:
            # The ego is whoever /sim/ego/odom names (a scenario's own "Ego", "hero", ...), not a fixed name.
            if msg.child_frame_id != asm.ego_name:
                asm.ego_name = msg.child_frame_id
            frame = asm.add_odometry(msg, key)
        elif topic == c.TOPIC_OBJECTS_ODOM:
            frame = asm.add_odometry(msg, key)
        elif topic == c.TOPIC_OBJECTS_MARKERS:
            frame = asm.add_markers(msg, key)
        else:
            frame = asm.add_lights(msg, key)    # a step's lights may be the message that completes its frame
        if frame is not None:
            sink(frame)

    def _start(self, envelope: ScenarioEnvelope | None, scenario_id: str = "") -> None:
        """A scenario envelope or a 'started' status for the current run, or one after a run without frames.

        A run that has no scenario yet (its goal, status or first frames came before the generator's envelope)
        adopts the one that arrives."""
        sid = envelope.id if envelope is not None else scenario_id
        run = self.run
        if run is not None:
            if envelope is not None and run.envelope is not None:
                if run.envelope.id == envelope.id:
                    return None                   # the same envelope again (transient-local history)
                self._end_run(None)               # a scenario that never produced a frame
                return self._start(envelope) if self.run is None else None
        if run is None:
            last = self._judged_envelope
            if envelope is not None and envelope.id == (last.id if last is not None else self._judged_id):
                # The judged run's scenario delivered again (transient-local history reaching a late-matched
                # reader), or only now (the run was named by its 'started' status): no new run. A replay of it
                # starts with the player's 'started' status, which takes it.
                self._judged_envelope = envelope
                return None
            if envelope is None and last is not None and sid == last.id:
                envelope = last
            # No reset of the assembler here: `finish` cleared it, and what it holds now (parts of a first frame
            # that came before its scenario) is this run's.
            run = RunState()
        if envelope is not None:
            run.envelope = envelope
            run.network, why = network_for(envelope)
            if why:
                run.notes.append(why)
            if run.oracle is not None:
                run.oracle.set_network(run.network)
        if sid and (envelope is not None or not run.scenario_id):   # the envelope's id wins over a status's
            run.scenario_id = sid
            if run.oracle is not None:
                run.oracle.scenario_id = sid
        self.run = run
        return None

    def _ensure_run(self) -> RunState:
        if self.run is None:
            self.run = RunState()
        return self.run

    def _frame(self, frame: Any) -> None:
        run = self._ensure_run()
        if run.oracle is None:
            run.oracle = Oracle(run.network, run.goal, self.params, scenario_id=run.scenario_id)
        self.frames_seen += 1
        if self.on_frame is not None:
            self.on_frame(frame)
        new = run.oracle.observe(frame)
        if new and self.on_violations:
            self.on_violations(frame.t, new)
        if self._pending is not None and frame.t >= self._pending.t - 1e-6:
            self._end_run(self._pending)

    # --- end of a run --------------------------------------------------------------------------------------------

    def _end_run(self, status: RunStatus | None) -> None:
        """Judge the current run, then start the next with what was kept for it (messages, assembled frames)."""
        self.finish(status)
        deferred, self._deferred = self._deferred, []
        frames, self._next_frames = self._next_frames, []
        nxt, self._next = self._next, None
        if nxt is not None:
            self.assembler = nxt
            self._used = True
        for topic, msg in deferred:
            self.on_message(topic, msg)
        for frame in frames:
            self._frame(frame)

    def finish(self, status: RunStatus | None) -> RunVerdict:
        """Close the current run with its final status (None: it never reported one) and return its verdict."""
        self._pending = None
        run = self._ensure_run()
        oracle = run.oracle or Oracle(run.network, run.goal, self.params, scenario_id=run.scenario_id)
        verdict = oracle.finish(status)
        if run.notes:
            verdict = replace(verdict, notes=tuple(run.notes) + verdict.notes)
        self.verdicts.append(verdict)
        self._judged_envelope, self._judged_id = run.envelope, run.scenario_id
        self._goal_key = -1
        self.run = None
        self.assembler.reset()
        if self._used:                            # the next run takes the next generation of every topic
            self._gen += 1
            self._used = False
            self._prev_end_key, self._cur_max_key, self._next_max_key = self._cur_max_key, self._next_max_key, -1
        if self.on_verdict:
            self.on_verdict(verdict)
        return verdict

    def close(self) -> None:
        """End of input (shutdown, end of the bag): runs still open are judged (as incomplete if no end came)."""
        for _ in range(10_000):                   # each pass ends one run; the bound only guards against a loop
            if self._pending is not None:
                self._end_run(self._pending)
            elif self.run is not None and (self.run.oracle is not None or self.run.envelope is not None):
                self._end_run(None)
            elif self._deferred or self._next_frames:
                self._end_run_without_current()
            else:
                return

    def _end_run_without_current(self) -> None:
        """Start what was kept for the next run when there is no current run to judge."""
        deferred, self._deferred = self._deferred, []
        frames, self._next_frames = self._next_frames, []
        nxt, self._next = self._next, None
        if nxt is not None:
            self.assembler = nxt
            self._gen += 1
            self._used = True
            self._prev_end_key, self._cur_max_key, self._next_max_key = self._cur_max_key, self._next_max_key, -1
        for topic, msg in deferred:
            self.on_message(topic, msg)
        for frame in frames:
            self._frame(frame)
