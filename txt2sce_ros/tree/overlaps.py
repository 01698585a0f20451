"""Entities whose footprints overlap at their written starts: a node that starts in a contact is an invalid scenario
(the closed loop judges it `error`, overlap at start), so a tree should hold none. A check over written nodes (map
poses of every start, the footprint from each ScenarioObject's BoundingBox), not used while building (per node it
would cost the build its speed); the tree's operators keep starts clear where they place them.

    python -m txt2sce_ros.tree.overlaps TREE_DIR [TREE_DIR ...]    # per tree: nodes that start overlapped, and pairs
"""

from __future__ import annotations

import itertools
import sys
from collections import Counter
from pathlib import Path

from ..seed.boxes import boxes_gap
from ..seed.context import SeedContext
from .trajectory import start_box


def overlapping_starts(node: str | Path) -> list[tuple[str, str]]:
    """Pairs (sorted names) of entities of scenario `node` whose footprints overlap at their starts."""
    ctx = SeedContext.from_file(node)
    boxes = {name: box for name in ctx.entities
             if (box := start_box(ctx, name, ctx.root.find(f"Entities/ScenarioObject[@name='{name}']"))) is not None}
    return [(a, b) for a, b in itertools.combinations(sorted(boxes), 2) if boxes_gap(boxes[a], boxes[b]) < 0.0]


def main(argv: list[str] | None = None) -> int:
    dirs = [Path(a) for a in (sys.argv[1:] if argv is None else argv)]
    if not dirs:
        print(__doc__.strip().splitlines()[-1].strip(), file=sys.stderr)
        return 2
    total = bad = 0
    for d in dirs:
        nodes = sorted((d / "nodes").glob("n*.xosc"))
        if not nodes:
            print(f"{d}: no nodes/n*.xosc", file=sys.stderr)
            return 2
        pairs: Counter[tuple[str, str]] = Counter()
        hit = 0
        for n in nodes:
            found = overlapping_starts(n)
            hit += bool(found)
            pairs.update(found)
        total, bad = total + len(nodes), bad + hit
        if hit or len(dirs) == 1:
            print(f"{d.name}: {hit} of {len(nodes)} nodes start overlapped"
                  + (f" ({', '.join(f'{a}-{b} {k}' for (a, b), k in sorted(pairs.items()))})" if pairs else ""))
    print(f"total: {bad} of {total} nodes in {len(dirs)} trees start with overlapping footprints")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
