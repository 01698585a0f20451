"""Figures of the report keep their labels off each other and off what they label (issue 18)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from txt2sce_ros.analysis.plots import trajectory_figure, tree_figure


def _boxes(fig: plt.Figure, artists: list) -> list:
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    return [a.get_window_extent(renderer) for a in artists]


def test_tree_legend_sits_beside_the_nodes() -> None:
    # a wide tree: 3 layers, 40 leaves, so nodes reach both edges of the axes
    nodes = {"root": {"parent": None}}
    for i in range(4):
        nodes[f"n{i}"] = {"parent": "root"}
        for j in range(10):
            nodes[f"n{i}_{j}"] = {"parent": f"n{i}"}
    verdicts = {n: ("fail" if n.endswith("3") else "pass") for n in nodes}
    fig = tree_figure(nodes, verdicts, "tree")
    ax = fig.axes[0]
    legend = _boxes(fig, [ax.get_legend()])[0]
    pts = ax.transData.transform(np.vstack([c.get_offsets() for c in ax.collections if len(c.get_offsets())]))
    inside = ((pts[:, 0] >= legend.x0) & (pts[:, 0] <= legend.x1) & (pts[:, 1] >= legend.y0) & (pts[:, 1] <= legend.y1))
    assert len(pts) == len(nodes) and not inside.any()
    plt.close(fig)


def test_violation_labels_do_not_overlap_each_other_the_legend_or_the_map() -> None:
    t = np.linspace(0, 5, 50)
    traj = {"ego": np.column_stack([t, 10 * t, np.zeros_like(t), np.zeros_like(t), np.full_like(t, 10)]),
            "npc1": np.column_stack([t, 10 * t, 3 + 0 * t, np.zeros_like(t), np.full_like(t, 10)])}
    # three violations a few metres apart: labels beside their crosses used to overprint
    marks = [(20.0, 0.0, "Collisions: contact @ 2.0 s"), (26.0, 1.0, "Smooth: smooth_jerk @ 2.6 s"),
             (31.0, 0.5, "PlanFail: planner_stuck @ 3.1 s")]
    fig = trajectory_figure(traj, [], "three violations", marks)
    ax = fig.axes[0]
    labels = [a for a in ax.texts if "@" in a.get_text()]
    assert len(labels) == 3
    # the labels' boxes (an annotation's own extent includes its leader line, which does reach the map)
    boxes = _boxes(fig, [a.get_bbox_patch() for a in labels] + [ax.get_legend()])
    axes_box = ax.get_window_extent(fig.canvas.get_renderer())
    for i, a in enumerate(boxes):
        assert not a.overlaps(axes_box), "a label covers the map"
        for b in boxes[i + 1:]:
            assert not a.overlaps(b), "two labels overlap"
    plt.close(fig)
