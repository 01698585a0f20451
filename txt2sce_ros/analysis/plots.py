"""Figures of a campaign report (matplotlib, Agg backend: no display needed). Each returns PNG bytes."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Mapping, Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .behaviours import BehaviourRow  # noqa: E402
from .lift import LiftRow  # noqa: E402

VERDICT_COLOURS = {"pass": "#4caf50", "fail": "#e53935", "error": "#9e9e9e"}


def _png(fig: plt.Figure) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def category_bars(rows: Sequence[BehaviourRow]) -> bytes:
    fig, ax = plt.subplots(figsize=(6, 3.2))
    names = [r.category for r in rows]
    counts = [r.count for r in rows]
    bars = ax.bar(names, counts, color="#e57373")
    for bar, r in zip(bars, rows):
        ax.annotate(f"{r.count}\n{100 * r.share_of_behaviours:.1f}%", (bar.get_x() + bar.get_width() / 2,
                    bar.get_height()), ha="center", va="bottom", fontsize=8)
    ax.set_ylabel("runs showing the behaviour")
    ax.set_title("Unexpected behaviours by category")
    ax.margins(y=0.25)
    return _png(fig)


def lift_bars(table: Mapping[str, Sequence[LiftRow]], top: int = 6) -> bytes:
    cats = [c for c in table if table[c]]
    n = max(1, len(cats))
    fig, axes = plt.subplots(n, 1, figsize=(7, 1.0 + 1.6 * n), squeeze=False)
    for ax, cat in zip(axes[:, 0], cats):
        rows = list(table[cat])[:top][::-1]
        ax.barh([r.element for r in rows], [r.lift for r in rows], color="#7986cb")
        for i, r in enumerate(rows):
            ax.annotate(f" n={r.support}", (r.lift, i), va="center", fontsize=7)
        ax.axvline(1.0, color="k", lw=0.6, ls="--")
        ax.set_title(f"{cat}: top triggers by lift", fontsize=9)
        ax.tick_params(labelsize=7)
    if not cats:
        axes[0, 0].text(0.5, 0.5, "no unexpected behaviour observed", ha="center", va="center")
        axes[0, 0].axis("off")
    fig.tight_layout()
    return _png(fig)


def tree_view(nodes: Mapping[str, Mapping], verdicts: Mapping[str, str], title: str) -> bytes:
    """The derivation tree laid out by depth; failing nodes red, passing green, errors grey, not run white."""
    return _png(tree_figure(nodes, verdicts, title))


def tree_figure(nodes: Mapping[str, Mapping], verdicts: Mapping[str, str], title: str) -> plt.Figure:
    """`tree_view`'s figure (open; the caller closes it)."""
    children: dict[str | None, list[str]] = {}
    for nid, node in nodes.items():
        children.setdefault(node.get("parent"), []).append(nid)
    for v in children.values():
        v.sort()
    pos: dict[str, tuple[float, float]] = {}
    leaf_x = [0.0]

    def place(nid: str, depth: int) -> float:
        kids = children.get(nid, [])
        if not kids:
            x = leaf_x[0]
            leaf_x[0] += 1
        else:
            xs = [place(k, depth + 1) for k in kids]
            x = sum(xs) / len(xs)
        pos[nid] = (x, -depth)
        return x

    roots = [n for n in children.get(None, [])] + [n for n, d in nodes.items()
                                                   if d.get("parent") and d.get("parent") not in nodes]
    for r in sorted(set(roots)):
        place(r, 0)
    fig, ax = plt.subplots(figsize=(min(18, 3 + 0.15 * max(1, leaf_x[0])), 4))
    for nid, node in nodes.items():
        p = node.get("parent")
        if p in pos and nid in pos:
            ax.plot([pos[p][0], pos[nid][0]], [pos[p][1], pos[nid][1]], color="#bdbdbd", lw=0.5, zorder=1)
    if pos:
        xs, ys = zip(*(pos[n] for n in pos))
        cols = [VERDICT_COLOURS.get(verdicts.get(n, ""), "white") for n in pos]
        ax.scatter(xs, ys, c=cols, s=14, edgecolors="k", linewidths=0.3, zorder=2)
    for verdict, colour in (*VERDICT_COLOURS.items(), ("not run", "white")):
        ax.scatter([], [], c=colour, s=14, edgecolors="k", linewidths=0.3, label=verdict)
    # beside the drawing, never on it: a wide tree fills its axes to both edges
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, frameon=False)
    ax.set_title(title, fontsize=10)
    ax.set_yticks([])
    ax.set_xticks([])
    for s in ax.spines.values():
        s.set_visible(False)
    return fig


def trajectory_plot(trajectories: Mapping[str, np.ndarray], lanes: Sequence[np.ndarray], title: str,
                    marks: Sequence[tuple[float, float, str]] = ()) -> bytes:
    """Top-down view: lane borders in grey, each entity's path (columns t, x, y, …) with start and end marked."""
    return _png(trajectory_figure(trajectories, lanes, title, marks))


def trajectory_figure(trajectories: Mapping[str, np.ndarray], lanes: Sequence[np.ndarray], title: str,
                      marks: Sequence[tuple[float, float, str]] = ()) -> plt.Figure:
    """`trajectory_plot`'s figure (open; the caller closes it)."""
    fig, ax = plt.subplots(figsize=(6, 6))
    for border in lanes:
        ax.plot(border[:, 0], border[:, 1], color="#cfcfcf", lw=0.6)
    # the ego always blue; other parties from a palette without blue or red (red marks the violations)
    palette = iter(["#ff9800", "#43a047", "#8e24aa", "#6d4c41", "#00acc1", "#757575", "#c0ca33", "#f06292"])
    for name, tr in trajectories.items():
        if len(tr) == 0:
            continue
        colour = "#1e88e5" if name == "ego" else next(palette, "#424242")
        lw = 2.4 if name == "ego" else 1.4
        if np.ptp(tr[:, 1]) + np.ptp(tr[:, 2]) < 0.5:
            # a party that never moved (parked car, debris): a marker, not an invisible zero-length line
            ax.plot(tr[0, 1], tr[0, 2], "D", ms=8, color=colour, label=f"{name} (static)")
            continue
        ax.plot(tr[:, 1], tr[:, 2], label=name, lw=lw, color=colour)
        ax.plot(tr[0, 1], tr[0, 2], "o", ms=5, color=colour)
        ax.plot(tr[-1, 1], tr[-1, 2], "s", ms=5, color=colour)
    # violations at (nearly) the same place share one cross and one stacked label, so texts never overprint
    spots: dict[tuple[int, int], tuple[float, float, list[str]]] = {}
    for x, y, text in marks:
        spots.setdefault((round(x / 4.0), round(y / 4.0)), (x, y, []))[2].append(text)
    # Labels stack in a column right of the axes, each with a leader line to its cross: labels of nearby spots
    # placed beside their crosses overprinted each other and the paths.
    top = 1.0
    for x, y, texts in sorted(spots.values(), key=lambda s: -s[1]):
        ax.plot(x, y, "x", color="#e53935", ms=11, mew=2.2, zorder=5)
        ax.annotate("\n".join(texts), (x, y), xytext=(1.04, top), textcoords="axes fraction", va="top",
                    fontsize=8, color="#c62828", annotation_clip=False,
                    bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="#e53935"),
                    arrowprops=dict(arrowstyle="-", color="#e53935", lw=0.6, shrinkB=6))
        top -= 0.045 * len(texts) + 0.04
    ax.plot([], [], "ko", ms=4, label="start")
    ax.plot([], [], "ks", ms=4, label="end")
    allpts = np.vstack([tr[:, 1:3] for tr in trajectories.values() if len(tr)]) if trajectories else np.zeros((1, 2))
    lo, hi = allpts.min(axis=0) - 15, allpts.max(axis=0) + 15
    span = max(hi - lo)
    mid = (hi + lo) / 2
    ax.set_xlim(mid[0] - span / 2, mid[0] + span / 2)
    ax.set_ylim(mid[1] - span / 2, mid[1] + span / 2)
    ax.set_aspect("equal")
    # the legend below the violation labels, outside the axes too, so neither hides a path or the other
    ax.legend(fontsize=7, loc="lower left", bbox_to_anchor=(1.04, 0.0), borderaxespad=0.0)
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return fig


def lane_borders_near(scenario_file: str | Path, traj: Mapping[str, np.ndarray]) -> list[np.ndarray]:
    """Borders of the driving lanes of the scenario's map within 60 m of the trajectories (a plot's background);
    [] when the scenario names no map."""
    from ..road import load_network
    from ..scenario_source import logic_file

    path = Path(scenario_file)
    xodr = logic_file(path, path.read_bytes())
    if xodr is None:
        return []
    net = load_network(str(xodr))
    pts = np.vstack([t[:, 1:3] for t in traj.values() if len(t)])
    lo, hi = pts.min(axis=0) - 60, pts.max(axis=0) + 60
    borders = []
    for rid, road in net.roads.items():
        for lane_id in net.lane_ids(rid, 0.0, types=("driving",)):
            left, right = net.lane_borders(rid, lane_id, ds=1.0)
            for b in (left, right):
                if len(b) and ((b >= lo) & (b <= hi)).all(axis=1).any():
                    borders.append(b)
    return borders
