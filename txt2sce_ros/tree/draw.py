"""Drawing a tree from its manifest: a text outline and a layered PNG (x = insertion layer, y = DFS leaf order)."""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path
from typing import Any

KIND_COLOURS = {"weather": "#1f77b4", "ego": "#7f7f7f", "npc": "#ff7f0e", "signal": "#d62728", "new_signal": "#d62728", "event": "#2ca02c",
                "obstacle": "#8c564b", "new_obstacle": "#9467bd", None: "#000000"}


def _children(manifest: dict[str, Any]) -> dict[str | None, list[dict[str, Any]]]:
    kids: dict[str | None, list[dict[str, Any]]] = defaultdict(list)
    for n in manifest["nodes"]:
        kids[n["parent"]].append(n)
    return kids


def layer_summary(manifest: dict[str, Any]) -> list[str]:
    """One line per insertion layer: block, kind, M(b), nodes kept."""
    blocks = manifest["blocks"]
    per_depth: dict[int, int] = defaultdict(int)
    for n in manifest["nodes"]:
        per_depth[n["depth"]] += 1
    lines = [f"tree {manifest['tree']}  (seed file {manifest['seed_file']}, map {manifest['map']}, "
             f"RNG seed {manifest['rng_seed']})",
             f"{'layer':>5}  {'block':<28} {'kind':<13} {'M(b)':>4} {'nodes':>7}"]
    for depth, bi in enumerate(manifest["insertion"], start=1):
        b = blocks[bi]
        lines.append(f"{depth:>5}  {b['key']:<28} {b['kind']:<13} {len(b['variants']):>4} {per_depth.get(depth, 0):>7}")
    lines.append(f"nodes {manifest['nodes_written']} (Sum formula without pruning: {manifest['expected_nodes']}), "
                 f"pruned {manifest['pruned']}, invalid {manifest['invalid']}"
                 + (", thinned to the node budget" if manifest["truncated"] else ""))
    return lines


def outline(manifest: dict[str, Any], *, max_depth: int = 3, max_children: int = 8) -> list[str]:
    """Indented outline of the first layers: each node with the block it added, the operators, the version's
    features (what pruning and Table V see) and how many values changed."""
    kids = _children(manifest)
    out: list[str] = []

    def walk(node: dict[str, Any], indent: int) -> None:
        if node["parent"] is None:
            label = "seed"
        else:
            feats = manifest["blocks"][node["block"]]["variants"][node["variant"]]["features"]
            label = (f"+{node['block_key']} [{node['operator']}] {' '.join(map(str, feats[1:]))}"
                     f"  ({len(node['changes'])} changes)")
        out.append(f"{'  ' * indent}{node['id']}  {label}")
        if node["depth"] >= max_depth:
            return
        children = kids.get(node["id"], [])
        for c in children[:max_children]:
            walk(c, indent + 1)
        if len(children) > max_children:
            out.append(f"{'  ' * (indent + 1)}… {len(children) - max_children} more")

    for root in kids.get(None, []):
        walk(root, 0)
    return out


def draw_png(manifest: dict[str, Any], path: str | Path) -> Path:
    """The whole tree as a layered plot; node colour = kind of the block it added."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    kids = _children(manifest)
    pos: dict[str, tuple[float, float]] = {}
    leaf = [0]

    def place(node: dict[str, Any]) -> float:  # iterative depth would be nicer; trees are < 10 layers deep
        children = kids.get(node["id"], [])
        if not children:
            y = float(leaf[0])
            leaf[0] += 1
        else:
            ys = [place(c) for c in children]
            y = sum(ys) / len(ys)
        pos[node["id"]] = (float(node["depth"]), y)
        return y

    for root in kids.get(None, []):
        place(root)
    nodes = manifest["nodes"]
    segs = [(pos[n["parent"]], pos[n["id"]]) for n in nodes if n["parent"] is not None]
    height = min(40.0, 3.0 + leaf[0] * 0.01)
    fig, ax = plt.subplots(figsize=(10, height))
    ax.add_collection(LineCollection(segs, colors="#bbbbbb", linewidths=0.3))
    for kind, colour in KIND_COLOURS.items():
        pts = [pos[n["id"]] for n in nodes if n.get("block_kind") == kind]
        if pts:
            xs, ys = zip(*pts)
            ax.scatter(xs, ys, s=4, c=colour, label=kind or "seed", zorder=3)
    blocks = manifest["blocks"]
    ticks = [0] + list(range(1, len(manifest["insertion"]) + 1))
    labels = ["seed"] + [blocks[bi]["key"] for bi in manifest["insertion"]]
    ax.set_xticks(ticks)
    ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    ax.set_yticks([])
    ax.set_title(f"scenario tree {manifest['tree']}: {manifest['nodes_written']} nodes")
    ax.legend(loc="upper left", fontsize=7, markerscale=3)
    ax.autoscale()
    fig.tight_layout()
    out = Path(path)
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out
