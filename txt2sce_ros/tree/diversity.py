"""Diversity of generated trees (paper §V RQ1, Table V), read back from tree manifests.

Every generated node is encoded with the pruning features (numeric attributes in uniform bins, enumerations by
value, events by driving semantics): the version of each block it inserted, the seed's own version for the rest.
Three abstraction levels project that vector:

- Weather: the weather block. Abstract representations: the seeds' weather types.
- Event Sequence: the event blocks, in order. Abstract representations: the seeds' sequences of event actions.
- Entity Configuration: the NPC and obstacle blocks. Abstract representations: the seeds' multisets of categories.

"Variants generated" counts distinct projections over all generated nodes; "unique scenario categories" counts
distinct whole vectors.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import InputError

LEVELS = ("Weather", "Event Sequence", "Entity Configuration")
_LEVEL_KINDS = {"Weather": ("weather",), "Event Sequence": ("event",),
                "Entity Configuration": ("npc", "obstacle", "new_obstacle")}


@dataclass(frozen=True)
class DiversityRow:
    level: str
    abstract: int
    variants: int


@dataclass(frozen=True)
class DiversityTable:
    trees: int
    files: int
    rows: tuple[DiversityRow, ...]
    unique_categories: int


def _tup(x: Any) -> Any:
    return tuple(_tup(i) for i in x) if isinstance(x, list) else x


def load_manifest(tree_dir: str | Path) -> dict[str, Any]:
    path = Path(tree_dir) / "manifest.json"
    try:
        manifest = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError as exc:
        raise InputError("not a tree directory (no manifest.json)", source=str(tree_dir)) from exc
    except json.JSONDecodeError as exc:
        raise InputError(f"manifest is not JSON: {exc}", source=str(path)) from exc
    if not isinstance(manifest, dict) or "blocks" not in manifest:
        # a seed directory's manifest (built/refused) sits under the same name
        what = "a seed directory" if isinstance(manifest, dict) and "built" in manifest else "no tree manifest"
        raise InputError(f"{what}, not a scenario tree (grow trees with `txt2sce tree SEEDS --out DIR`)",
                         source=str(tree_dir))
    return manifest


def find_trees(paths: Iterable[str | Path]) -> list[Path]:
    """Tree directories among `paths`: each path itself if it holds a manifest, else its subdirectories that do."""
    out: list[Path] = []
    for p in map(Path, paths):
        if (p / "manifest.json").is_file():
            out.append(p)
        elif p.is_dir():
            found = sorted(m.parent for m in p.glob("*/manifest.json"))
            if not found:
                raise InputError("holds no scenario tree (no manifest.json in it or in its subdirectories)",
                                 source=str(p))
            out.extend(found)
        else:
            raise InputError("no such tree directory", source=str(p))
    return out


def _abstract(manifest: dict[str, Any], level: str) -> tuple:
    blocks = manifest["blocks"]
    if level == "Weather":
        return tuple(b["original_features"][1] for b in blocks if b["kind"] == "weather")
    if level == "Event Sequence":
        return tuple(b["original_features"][1] for b in blocks if b["kind"] == "event")
    return tuple(sorted(b["original_features"][1] for b in blocks if b["kind"] in ("npc", "obstacle")))


def node_vectors(manifest: dict[str, Any]) -> Iterable[tuple[tuple, ...]]:
    """Per generated node: the feature tuple of every block (inserted version or the seed's)."""
    blocks = manifest["blocks"]
    base = [_tup(b["original_features"]) for b in blocks]
    variants = [[_tup(v["features"]) for v in b["variants"]] for b in blocks]
    insertion = manifest["insertion"]
    for n in manifest["nodes"]:
        if n["depth"] == 0:
            continue
        vec = list(base)
        for k, j in enumerate(n["path"]):
            bi = insertion[k]
            vec[bi] = variants[bi][j]
        yield tuple(vec)


def diversity(tree_dirs: Iterable[str | Path]) -> DiversityTable:
    abstract: dict[str, set] = {lv: set() for lv in LEVELS}
    concrete: dict[str, set] = {lv: set() for lv in LEVELS}
    whole: set = set()
    trees = files = 0
    for d in find_trees(tree_dirs):
        m = load_manifest(d)
        trees += 1
        kinds = [b["kind"] for b in m["blocks"]]
        for lv in LEVELS:
            abstract[lv].add(_abstract(m, lv))
        idx = {lv: [i for i, k in enumerate(kinds) if k in _LEVEL_KINDS[lv]] for lv in LEVELS}
        for vec in node_vectors(m):
            files += 1
            # the seed's structure (its event actions) is part of the category: equal vectors need equal seeds'
            # shapes, which the event features already carry
            whole.add(vec)
            for lv in LEVELS:
                concrete[lv].add(tuple(vec[i] for i in idx[lv]))
    rows = tuple(DiversityRow(lv, len(abstract[lv]), len(concrete[lv])) for lv in LEVELS)
    return DiversityTable(trees=trees, files=files, rows=rows, unique_categories=len(whole))


def format_table(t: DiversityTable) -> str:
    lines = [f"Table V — scenario variants ({t.trees} trees, {t.files} generated files)", "",
             f"{'Abstraction level':<22} {'Abstract representations':>25} {'Variants generated':>19}",
             "-" * 68]
    for r in t.rows:
        lines.append(f"{r.level:<22} {r.abstract:>25} {r.variants:>19}")
    lines += ["-" * 68, f"Unique scenario categories (all mutation dimensions): {t.unique_categories}"]
    return "\n".join(lines)
