"""A picture of a recorded run drawn from the bag alone: the road (`/sim/map/markers`), the goal and the lights
(`/sim/scenario/markers`), every entity's track and its box at one moment (`/sim/objects/markers`).

Nothing but the recording is read — no map file, no scenario — so the picture shows what a viewer of the bag sees.
A bag may hold several runs (a monitor records every run it saw): the k-th road message starts run k, and each
marker topic's stamps restart with the next run (the player's clock starts at 0 for every scenario), which is how
the entity and scenario markers of run k are told from those of the run before.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from txt2sce_ros import contract as c
from txt2sce_ros.errors import InputError

from .bagread import read_bag
from .recorder import typestore

_MARKER_ARRAY = "visualization_msgs/msg/MarkerArray"
_DELETEALL = 3


@dataclass
class RunPicture:
    """What one run's markers say: road lines, scenario markers over time, entity boxes over time."""

    road: list[Any] = field(default_factory=list)                        # Marker (LINE_STRIP) of the road
    scene: list[tuple[float, list[Any]]] = field(default_factory=list)   # (t, goal and light markers)
    frames: list[tuple[float, list[Any]]] = field(default_factory=list)  # (t, one CUBE per entity)


def _stamp(marker: Any) -> float:
    return marker.header.stamp.sec + marker.header.stamp.nanosec * 1e-9


def _split(stamped: list[tuple[float, list[Any]]]) -> list[list[tuple[float, list[Any]]]]:
    """Cut a topic's (t, markers) stream where t stops growing: the next run's clock started again."""
    runs: list[list[tuple[float, list[Any]]]] = []
    last = math.inf
    for t, markers in stamped:
        if t <= last:
            runs.append([])
        runs[-1].append((t, markers))
        last = t
    return runs


def read_runs(bag: str | Path) -> list[RunPicture]:
    """Every run of the recording that has a road; raises InputError when the bag holds none."""
    ts = typestore()
    topics = frozenset({c.TOPIC_MAP_MARKERS, c.TOPIC_SCENARIO_MARKERS, c.TOPIC_OBJECTS_MARKERS})
    reading = read_bag(bag)
    roads: list[list[Any]] = []
    streams: dict[str, list[tuple[float, list[Any]]]] = {c.TOPIC_SCENARIO_MARKERS: [], c.TOPIC_OBJECTS_MARKERS: []}
    for raw in reading.messages(topics):
        if raw.msgtype != _MARKER_ARRAY:
            continue
        try:
            msg = ts.deserialize_cdr(bytes(raw.data), _MARKER_ARRAY)
        except Exception as exc:          # noqa: BLE001 - one damaged message is reported, not fatal
            reading.issues.append(f"undecodable {raw.topic} message: {exc}")
            continue
        drawn = [m for m in msg.markers if m.action != _DELETEALL]
        if raw.topic == c.TOPIC_MAP_MARKERS:
            roads.append(drawn)
        elif msg.markers:
            streams[raw.topic].append((_stamp(msg.markers[0]), drawn))
    if not roads:
        raise InputError(f"no road markers on {c.TOPIC_MAP_MARKERS} (recorded before the road was published?)",
                         source=str(bag))
    scenes, frames = _split(streams[c.TOPIC_SCENARIO_MARKERS]), _split(streams[c.TOPIC_OBJECTS_MARKERS])
    return [RunPicture(road=road, scene=scenes[k] if k < len(scenes) else [],
                       frames=frames[k] if k < len(frames) else []) for k, road in enumerate(roads)]


def _rgba(m: Any) -> tuple[float, float, float, float]:
    return (m.color.r, m.color.g, m.color.b, max(m.color.a, 0.2))


def _yaw(q: Any) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def _box(m: Any) -> list[tuple[float, float]]:
    """Corners of a CUBE marker's footprint."""
    h, cx, cy = _yaw(m.pose.orientation), m.pose.position.x, m.pose.position.y
    hl, hw = m.scale.x / 2.0, m.scale.y / 2.0
    cos, sin = math.cos(h), math.sin(h)
    return [(cx + dx * cos - dy * sin, cy + dx * sin + dy * cos)
            for dx, dy in ((hl, hw), (-hl, hw), (-hl, -hw), (hl, -hw))]


def draw(run: RunPicture, out: str | Path, *, t: float | None = None, whole_map: bool = False,
         title: str = "") -> tuple[Path, float]:
    """Draw one run at sim time `t` (default: its last frame); returns (PNG path, the frame time drawn). The view
    frames the entities' tracks and the goal with a margin, or the whole road with `whole_map`."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Circle, Polygon

    fig, ax = plt.subplots(figsize=(10, 8))
    ax.set_facecolor("#3a3a3a")                  # asphalt-dark: the road's light lines read as in a viewer
    road_xy: list[tuple[float, float]] = []
    for kind, z in (("border", 1), ("centre", 2), ("stop_line", 3)):
        lines = [m for m in run.road if m.ns == kind and len(m.points) >= 2]
        segs = [[(p.x, p.y) for p in m.points] for m in lines]
        if segs:
            ax.add_collection(LineCollection(segs, colors=[_rgba(m) for m in lines], zorder=z,
                                             linewidths=[{"border": 0.8, "centre": 0.5}.get(kind, 2.0)] * len(segs),
                                             linestyles="dashed" if kind == "centre" else "solid"))
            road_xy.extend(xy for seg in segs for xy in seg)
    frame_t, boxes = 0.0, []
    if run.frames:
        chosen = run.frames[-1] if t is None else min(run.frames, key=lambda f: abs(f[0] - t))
        frame_t, boxes = chosen
    focus: list[tuple[float, float]] = []
    tracks: dict[str, list[tuple[float, float]]] = {}
    colours: dict[str, tuple[float, float, float, float]] = {}
    for ft, markers in run.frames:
        if ft > frame_t + 1e-9:
            break
        for m in markers:
            tracks.setdefault(m.text, []).append((m.pose.position.x, m.pose.position.y))
            colours[m.text] = _rgba(m)
    for name, pts in tracks.items():
        ax.plot([p[0] for p in pts], [p[1] for p in pts], color=colours[name], linewidth=1.0, zorder=4)
        focus.extend(pts)
    for m in boxes:
        corners = _box(m)
        ax.add_patch(Polygon(corners, closed=True, facecolor=_rgba(m), edgecolor="white", linewidth=0.6, zorder=6))
        ax.annotate(m.text, (m.pose.position.x, m.pose.position.y), color="white", fontsize=7, zorder=7,
                    xytext=(4, 4), textcoords="offset points")
        focus.extend(corners)
    scene = [ms for st, ms in run.scene if st <= frame_t + 1e-9]
    for m in scene[-1] if scene else []:
        x, y = m.pose.position.x, m.pose.position.y
        if m.ns == "goal" and m.type == 3:
            ax.add_patch(Circle((x, y), m.scale.x / 2.0, facecolor=(0.1, 0.9, 0.3, 0.25), edgecolor=(0.1, 0.9, 0.3),
                                zorder=5))
            ax.annotate("goal", (x, y), color=(0.1, 0.9, 0.3), fontsize=8, zorder=7, xytext=(6, -10),
                        textcoords="offset points")
            focus.append((x, y))
        elif m.ns == "traffic_light":
            ax.add_patch(Circle((x, y), 1.2, facecolor=_rgba(m), edgecolor="black", zorder=5))
    pts = road_xy if whole_map or not focus else focus
    if pts:
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        pad = 5.0 if whole_map or not focus else 25.0
        x0, x1, y0, y1 = min(xs) - pad, max(xs) + pad, min(ys) - pad, max(ys) + pad
        # Widen the narrower side to the axes' shape: the picture fills the figure at equal scale.
        shape = 1.25
        if (x1 - x0) < shape * (y1 - y0):
            grow = (shape * (y1 - y0) - (x1 - x0)) / 2.0
            x0, x1 = x0 - grow, x1 + grow
        else:
            grow = ((x1 - x0) / shape - (y1 - y0)) / 2.0
            y0, y1 = y0 - grow, y1 + grow
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("map x (m)")
    ax.set_ylabel("map y (m)")
    ax.set_title(f"{title}t = {frame_t:.2f} s, {len(boxes)} entities, {len(run.road)} road lines", fontsize=10)
    fig.tight_layout()
    path = Path(out)
    if path.parent and not path.parent.exists():
        raise InputError("output directory does not exist", source=str(path))
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path, frame_t
