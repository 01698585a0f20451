"""Offline judging: read a recording, decode it to contract records, run the same `JudgeSession` the live monitor
runs, and compare with the verdicts the live monitor recorded (if any).

Works on any bag with the contract topics (ours, or one made with `ros2 bag record`). Messages are decoded by
`cdr.decode` (fast paths for Odometry / MarkerArray / DiagnosticArray, rosbags for the rest; both give objects with
rclpy's field names, which is all `ros_io` reads), only for the topics the oracle needs: /clock and
/control/command are counted but not decoded. The live node decodes with the same function.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from txt2sce_ros import contract as c
from txt2sce_ros.errors import InputError

from .bagread import read_bag
from .cdr import decode
from .messages import verdicts_in
from .params import OracleParams
from .recorder import typestore
from .records import RunVerdict
from .session import JudgeSession
from .topics import JUDGED_TOPICS


@dataclass
class JudgeResult:
    path: Path
    verdicts: list[RunVerdict]
    live: list[dict[str, Any]] = field(default_factory=list)    # verdicts the live monitor recorded
    issues: list[str] = field(default_factory=list)             # why the recording is not whole
    messages: int = 0
    decode_errors: int = 0

    @property
    def complete(self) -> bool:
        return not self.issues

    def agrees_with_live(self) -> bool | None:
        """True/False when the recording holds live verdicts for every run, None when it holds none."""
        if not self.live:
            return None
        return [v.to_dict() for v in self.verdicts] == self.live


def judge_bag(path: str | Path, params: OracleParams | None = None, *,
              on_frame: Callable[[Any], None] | None = None) -> JudgeResult:
    """Judge every run in a recording. A damaged or unfinished recording is judged up to where it is readable;
    `issues` says what was lost. Raises InputError when nothing can be read at all. `on_frame` gets every judged
    frame in order (e.g. to keep the trajectories)."""
    reading = read_bag(path)
    ts = typestore()
    session = JudgeSession(params, on_frame=on_frame)
    live: list[dict[str, Any]] = []
    decode_errors = 0
    wanted = JUDGED_TOPICS | {c.TOPIC_VIOLATIONS}
    violations, on_message = c.TOPIC_VIOLATIONS, session.on_message      # looked up once: ~60k messages a bag
    for topic, msgtype, _t, data in reading.messages():
        if topic not in wanted:
            continue
        try:
            decoded = decode(data, msgtype, ts)
        except Exception:                 # a damaged message: count it, judge the rest
            decode_errors += 1
            continue
        if topic == violations:
            live.extend(verdicts_in(decoded))
            continue
        try:
            on_message(topic, decoded)
        except InputError:
            decode_errors += 1
    session.close()
    if reading.count == 0 and reading.issues:
        raise InputError("nothing readable: " + "; ".join(reading.issues), source=str(path))
    issues = list(reading.issues)
    if decode_errors:
        issues.append(f"{decode_errors} message(s) could not be decoded and were skipped")
    return JudgeResult(Path(path), session.verdicts, live, issues, reading.count, decode_errors)
