"""Tree building (paper §III-D.1): blocks inserted in a fixed order, each child extends its parent by one block
version, layer by layer, with diversity-aware pruning per layer and every node streamed to disk as it is made.

Without pruning the node count is the paper's Sum = M(b1) + M(b1)M(b2) + … + ∏M(bi) (the seed itself, written as
`nodes/root.xosc`, is not counted). A node at depth d holds versions of blocks 1..d; the blocks not yet inserted
keep the seed's own content, so every node is a complete, runnable scenario.
"""

from __future__ import annotations

import copy
import json
import os
import sys
import time
import zlib
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from lxml import etree

from ..config import check_sections, load_config
from ..errors import InputError, Txt2SceError
from ..xosc.validate import document_version, validate_xosc
from .assembly import assemble
from .blocks import Disassembly, Variant
from ..seed.context import SeedContext, build_context
from .disassembly import disassemble
from .export import write_dot, write_graphml, write_manifest
from .mutate import block_variants, original_features
from .prune import diagonal, prune
from .xml import parse_bytes

MANIFEST_SCHEMA = "txt2sce.tree/1"


def tree_config(path: str | Path | None = None, *, mutations: int | None = None, prune_share: float | None = None,
                validate: bool | None = None, max_nodes: int | None = None) -> dict[str, Any]:
    """`config/mutation.yaml`, with the settings of `path` over it, and CLI overrides applied; a private copy the
    caller may change. A user's file need hold only what it changes: every setting it leaves out keeps the bundled
    value (before, a file without one key failed deep inside with a KeyError); a section the bundled file does not
    have is refused (a misspelled one would change nothing)."""
    cfg = copy.deepcopy(load_config("mutation"))
    if path is not None:
        given = load_config("mutation", path)
        check_sections(given, cfg, str(path))
        _merge_into(cfg, given)
    if mutations is not None:
        cfg["tree"]["mutations_per_block"] = int(mutations)
    if prune_share is not None:
        cfg["tree"]["prune_share"] = float(prune_share)
    if validate is not None:
        cfg["tree"]["validate"] = bool(validate)
    if max_nodes is not None:
        cfg["tree"]["max_nodes_per_tree"] = int(max_nodes)
    if not 0.0 < float(cfg["tree"]["prune_share"]) <= 1.0:
        raise InputError("prune share must be in (0, 1]", element="tree.prune_share")
    return cfg


def _merge_into(base: dict[str, Any], given: Mapping[str, Any]) -> None:
    """`given` over `base`, mapping by mapping (a user's value replaces a bundled one; lists are values)."""
    for key, value in given.items():
        if isinstance(value, Mapping) and isinstance(base.get(key), dict):
            _merge_into(base[key], value)
        else:
            base[key] = copy.deepcopy(value)


def expected_nodes(counts: Sequence[int]) -> int:
    """Sum = M(b1) + M(b1)M(b2) + … + ∏ M(bi)."""
    total, prod = 0, 1
    for m in counts:
        prod *= m
        total += prod
    return total


def seed_key(name: str) -> int:
    """Stable per-seed RNG key from the seed's file name (not its path: moving a seed keeps its tree)."""
    return zlib.crc32(name.encode("utf-8"))


@dataclass(frozen=True)
class TreeResult:
    """What one tree build did. `nodes` excludes the root; `expected` is the unpruned Sum formula; `truncated`
    means the node budget (`max_nodes_per_tree`) thinned some layer."""

    seed: str
    out_dir: Path
    block_counts: tuple[int, ...]
    expected: int
    nodes: int
    pruned: int
    invalid: int
    truncated: bool
    seconds: float
    errors: tuple[str, ...] = field(default=())


@dataclass
class _Node:
    id: str
    parent: str | None
    path: tuple[int, ...]


def _node_id(path: tuple[int, ...]) -> str:
    return "n" + "_".join(str(j) for j in path) if path else "root"


def _read_seed(seed_path: Path) -> tuple[bytes, etree._Element, SeedContext]:
    """The seed's bytes, parsed tree and context (map, roads, parties) for mutation."""
    try:
        data = seed_path.read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read seed: {exc.strerror}", source=str(seed_path)) from exc
    root = parse_bytes(data, str(seed_path))
    return data, root, build_context(root, source=str(seed_path), seed_path=seed_path)


def reachable_elements(seed_path: str | Path, *, seed: int = 0, cfg: dict[str, Any] | None = None
                       ) -> frozenset[str]:
    """Trigger conditions (in the analysis's element names) the tree can bring into this seed's scenarios, read
    from its block versions without building it: NPC categories, a party close to the AV at the start (WPM-near,
    NCM-new close_behind), a cyclist (NCM-new cyclist_ahead), a lead that brakes (`events:h`), a pedestrian who
    starts to cross the AV's path (`events:m`, NCM-new crossing), a dilemma-zone
    yellow (TLS, on the seed's signal or on a new one for the map's lights), and `start:standing` (TSM-start, or a seed that starts standing). What seed picking
    covers, so a seed is chosen for what its tree can test, not only for what its report held."""
    cfg = cfg or tree_config()
    seed_path = Path(seed_path)
    data, root, ctx, dis, key = _seed_blocks(seed_path, cfg)
    out: set[str] = set()
    for b in dis.blocks:
        for v in block_variants(b, ctx, cfg, seed=seed, seed_key=key):
            if b.kind.value == "npc":
                out.add(f"category:{v.features[1]}")
                if v.operator == "WPM-near":
                    out.add("near_start:yes")
            elif b.kind.value == "new_party":
                out |= {"NCM-new:cyclist_ahead": {"category:bicycle"}, "NCM-new:lead_brakes": {"events:h"},
                        "NCM-new:close_behind": {"near_start:yes"},
                        "NCM-new:crossing": {"category:pedestrian", "events:m"}}.get(v.operator, set())
            elif b.kind.value in ("signal", "new_signal") and any("TimeToCollisionCondition" in f
                                                                  for f in v.fragments):
                out.add("signal:yellow")
            elif b.kind.value == "ego" and v.operator == "TSM-start":
                out.add("start:standing")
    ego_v = root.find("Storyboard/Init/Actions/Private[@entityRef='ego']//AbsoluteTargetSpeed")
    if ego_v is not None and float(ego_v.get("value", "1") or 1) <= 0.0:
        out.add("start:standing")
    return frozenset(out)


def build_tree(seed_path: str | Path, out_dir: str | Path, *, seed: int = 0, cfg: dict[str, Any] | None = None,
               ) -> TreeResult:
    """Build the scenario tree of one seed under `out_dir` (`nodes/*.xosc`, `manifest.json`, `tree.graphml`,
    `tree.dot`). Deterministic: same seed file, config and `seed` give byte-identical output."""
    t0 = time.perf_counter()
    cfg = cfg or tree_config()
    seed_path = Path(seed_path)
    out = Path(out_dir)
    nodes_dir = out / "nodes"
    nodes_dir.mkdir(parents=True, exist_ok=True)
    for stale in nodes_dir.glob("*.xosc"):  # a rebuild into the same directory must not leave old nodes behind
        stale.unlink()
    data, root, ctx = _read_seed(seed_path)
    logic = root.find("RoadNetwork/LogicFile")
    if logic is not None and ctx.map_path is not None:
        # Generated files live elsewhere: point them at the same map, relative to where they are written.
        logic.set("filepath", os.path.relpath(ctx.map_path, nodes_dir.resolve()))
    rebased = etree.tostring(root, encoding="unicode")
    order = tuple(cfg["tree"]["order"])
    dis = disassemble(rebased, source=str(seed_path), **_slots(cfg))
    key = seed_key(seed_path.name)
    variants: list[list[Variant]] = [block_variants(b, ctx, cfg, seed=seed, seed_key=key) for b in dis.blocks]
    used = [i for i, v in enumerate(variants) if v]  # a block with no possible version is left as in the seed
    counts = tuple(len(variants[i]) for i in used)

    originals = dis.originals()
    # every node shares the seed's version: read it once, not from each node's FileHeader
    version = document_version(root, source=str(seed_path)) if cfg["tree"]["validate"] else None
    share = float(cfg["tree"]["prune_share"])
    cap = int(cfg["tree"]["max_nodes_per_tree"]) or sys.maxsize
    prune_rng = np.random.default_rng(np.random.SeedSequence([int(seed), key, 0x70726E]))

    # Compact records (id, parent id, path) only: the per-node metadata is expanded while the manifest streams
    # out, so memory grows by a few dozen bytes per node, not by its change list.
    records: list[tuple[str, str | None, tuple[int, ...]]] = [("root", None, ())]
    errors: list[str] = []
    root_text = assemble(dis.template, originals)
    (nodes_dir / "root.xosc").write_text(root_text, encoding="utf-8")
    frontier = [_Node("root", None, ())]
    written = pruned = invalid = 0
    truncated = False
    for depth, bi in enumerate(used, start=1):
        block = dis.blocks[bi]
        vs = variants[bi]
        cands = [(p, j) for p in frontier for j in range(len(vs))]
        keep, cut = _select_layer([p.path for p, _ in cands], [j for _, j in cands], variants, used, depth,
                                  enumerated=block.kind.value in cfg["tree"]["enumerate"], share=share, cap=cap,
                                  written=written, rng=prune_rng)
        pruned += len(cands) - len(keep)
        truncated = truncated or cut
        frontier = []
        for ci in keep:
            parent, j = cands[ci]
            path = parent.path + (j,)
            node_id = _node_id(path)
            frags = list(originals)
            for k, vi in enumerate(path):
                b = dis.blocks[used[k]]
                for slot, frag in zip(b.slots, variants[used[k]][vi].fragments):
                    frags[slot] = frag
            text = assemble(dis.template, frags)
            if version is not None:
                problems = _node_problems(text, version)
                if problems:
                    invalid += 1
                    errors.append(f"{node_id}: {problems[0]}")
                    continue
            rel = f"nodes/{node_id}.xosc"
            with open(out / rel, "wb") as fh:
                fh.write(text.encode("utf-8"))
            written += 1
            records.append((node_id, parent.id, path))
            frontier.append(_Node(node_id, parent.id, path))
        frontier = interleave(frontier, key=lambda n: n.path)
        if not frontier or written >= cap:
            break

    manifest = {
        "schema": MANIFEST_SCHEMA, "tree": seed_path.stem, "id": seed_path.stem, "seed_file": seed_path.name,
        "map": ctx.map_path.name if ctx.map_path else None, "rng_seed": int(seed),
        "settings": {"order": list(order), "mutations_per_block": cfg["tree"]["mutations_per_block"],
                     "enumerate": list(cfg["tree"]["enumerate"]), "prune_share": share, "bins": cfg["bins"],
                     "max_nodes_per_tree": cfg["tree"]["max_nodes_per_tree"]},
        "blocks": [_block_entry(dis, i, variants[i], ctx, cfg) for i in range(len(dis.blocks))],
        "insertion": [dis.blocks[i].index for i in used],
        "block_counts": list(counts), "expected_nodes": expected_nodes(counts), "nodes_written": written,
        "pruned": pruned, "invalid": invalid, "truncated": truncated, "errors": errors[:50],
    }

    def node_dicts() -> Iterator[dict[str, Any]]:
        for node_id, parent_id, path in records:
            if not path:
                yield {"id": "root", "parent": None, "depth": 0, "file": "nodes/root.xosc", "path": [],
                       "block": None, "block_kind": None, "block_key": None, "variant": None,
                       "operator": "seed", "changes": [], "rng_seed": int(seed)}
                continue
            b = dis.blocks[used[len(path) - 1]]
            v = variants[b.index][path[-1]]
            yield {"id": node_id, "parent": parent_id, "depth": len(path), "file": f"nodes/{node_id}.xosc",
                   "path": list(path), "block": b.index, "block_kind": b.kind.value, "block_key": b.key,
                   "variant": path[-1], "operator": v.operator,
                   "changes": [[c.path, c.old, c.new] for c in v.changes], "rng_seed": v.rng_seed}

    write_manifest(manifest, node_dicts(), out / "manifest.json")
    write_graphml(manifest["tree"], node_dicts(), out / "tree.graphml")
    write_dot(manifest["tree"], node_dicts(), out / "tree.dot")
    return TreeResult(seed=str(seed_path), out_dir=out, block_counts=counts, expected=expected_nodes(counts),
                      nodes=written, pruned=pruned, invalid=invalid, truncated=truncated,
                      seconds=time.perf_counter() - t0, errors=tuple(errors[:5]))


def interleave(nodes: list[Any], *, key: Any) -> list[Any]:
    """The next layer's parents in round-robin order over the versions this layer inserted: the first node of each
    version (in tree order), then the second… A budget keeps a layer's first candidates, so the new party's roles,
    say, go under a dry and a rainy road, a moving and a standing AV, not all under the first node's siblings; and
    a layer kept to one node extends the first of them, the node in the tree's first branch (the seed's own start
    state). `key(node)` is the node's path; its last entry is the version."""
    seen: dict[int, int] = {}
    rank = []
    for n in nodes:
        path = key(n)
        rank.append((seen.get(path[-1], 0), path))
        seen[path[-1]] = seen.get(path[-1], 0) + 1
    return [n for _, n in sorted(zip(rank, nodes), key=lambda t: t[0])]


def _holds(path_features: tuple, kind: str, value: str) -> bool:
    """Whether the earlier layers (their versions' feature tuples, kind first) hold `value` for the block `kind`;
    True when no earlier layer is of that kind (the seed's own content then stands, unrestricted)."""
    of_kind = [f for f in path_features if f and f[0] == kind]
    return not of_kind or any(value in f[1:] for f in of_kind)


def _has(path_features: tuple, kind: str, value: str) -> bool:
    """Whether an earlier layer of block `kind` holds `value` (its version's feature tuple, kind first)."""
    return any(f and f[0] == kind and value in f[1:] for f in path_features)


def _select_layer(parent_paths: list[tuple[int, ...]], choices: list[int], variants: list[list[Variant]],
                  used: list[int], depth: int, *, enumerated: bool, share: float, cap: int, written: int,
                  rng: np.random.Generator) -> tuple[list[int], bool]:
    """Which candidates of one layer become nodes (indices into the candidate list), and whether the node budget
    cut some: diversity-aware pruning, then the budget. One candidate = a parent's path + a version `choice` of
    the layer's block. Shared by `build_tree` and `estimate_tree`, so an estimate prunes exactly as a build."""
    vs = variants[used[depth - 1]]
    vectors = [tuple(variants[used[k]][i].features for k, i in enumerate(path)) + (vs[j].features,)
               for path, j in zip(parent_paths, choices)]
    keep = prune(vectors, share, rng)
    # A version whose exclusion an earlier layer holds would make an invalid scenario: never a node (dropped after
    # pruning, so the pruning's draws, and every tree without such a pair, stay as they were).
    keep = [i for i in keep if not any(_has(vectors[i][:-1], kind, value) for kind, value in vs[choices[i]].excludes)]
    # Node budget: the layers still to come share what is left of the cap, so every block is still inserted
    # (a plain cut would drop the deepest layers: events and obstacles). The kept versions are spread over the
    # parents along diagonals (`prune.diagonal`), so each version meets different earlier ones (a cyclist in the
    # rain, a standing start in the snow) rather than all of them sharing the first parent.
    layers_left = len(used) - depth + 1
    allowed = max(1, (cap - written) // layers_left) if layers_left > 1 else max(0, cap - written)
    if enumerated:
        # Every value of an enumerated block is a test condition of its own (a cyclist, a yellow light, snow):
        # keep one node per value while the cap still leaves a node for each layer to come.
        allowed = max(allowed, min(len(vs), cap - written - (layers_left - 1)))
    if len(keep) <= allowed:
        return keep, False
    # The budget chooses: not where a version's premise an earlier layer of the parent contradicts (a car standing
    # close behind an AV that drives off). Without a budget every combination is written (the paper's Sum).
    fits = [i for i in keep if all(_holds(vectors[i][:-1], kind, value) for kind, value in vs[choices[i]].needs)]
    return diagonal(fits or keep, len(vs), allowed, cover=enumerated), True


@dataclass(frozen=True)
class TreeEstimate:
    """What `build_tree` would write for one seed, found without assembling or writing any node: `nodes` counts
    the generated files (root excluded, as in TreeResult), `bytes` their size plus the tree's exports. Nodes
    that would fail validation (none in practice) are counted as written."""

    seed: str
    nodes: int
    bytes: int


def _slots(cfg: dict[str, Any]) -> dict[str, Any]:
    """The disassembly's settings from the tree config: block order and the empty slots for insertions."""
    t = cfg["tree"]
    return {"order": tuple(t["order"]), "new_obstacle_slots": int(t["new_obstacle_slots"]),
            "new_party_slots": int(t.get("new_party_slots", 0)),
            "new_signal_slot": bool(t.get("new_signal_slot", False))}


def _seed_blocks(seed_path: Path, cfg: dict[str, Any]) -> tuple[Any, etree._Element, Any, Any, int]:
    """The seed read and disassembled as the tree's layers see it: (data, root, context, disassembly, seed key)."""
    data, root, ctx = _read_seed(seed_path)
    dis = disassemble(etree.tostring(root, encoding="unicode"), source=str(seed_path), **_slots(cfg))
    return data, root, ctx, dis, seed_key(seed_path.name)


def estimate_tree(seed_path: str | Path, *, seed: int = 0, cfg: dict[str, Any] | None = None) -> TreeEstimate:
    """Run the layer selection of `build_tree` (same variants, pruning, budget, RNG) without writing anything;
    the size is the seed's own size per node plus a measured allowance for the manifest and the graph exports."""
    cfg = cfg or tree_config()
    seed_path = Path(seed_path)
    data, root, ctx, dis, key = _seed_blocks(seed_path, cfg)
    variants = [block_variants(b, ctx, cfg, seed=seed, seed_key=key) for b in dis.blocks]
    used = [i for i, v in enumerate(variants) if v]
    share = float(cfg["tree"]["prune_share"])
    cap = int(cfg["tree"]["max_nodes_per_tree"]) or sys.maxsize
    rng = np.random.default_rng(np.random.SeedSequence([int(seed), key, 0x70726E]))
    frontier: list[tuple[int, ...]] = [()]
    written = 0
    for depth, bi in enumerate(used, start=1):
        cands = [(p, j) for p in frontier for j in range(len(variants[bi]))]
        keep, _ = _select_layer([p for p, _ in cands], [j for _, j in cands], variants, used, depth,
                                enumerated=dis.blocks[bi].kind.value in cfg["tree"]["enumerate"], share=share,
                                cap=cap, written=written, rng=rng)
        frontier = interleave([cands[i][0] + (cands[i][1],) for i in keep], key=lambda p: p)
        written += len(frontier)
        if not frontier or written >= cap:
            break
    # a node is the seed with a few attributes changed, so about the seed's size; the manifest, GraphML and DOT
    # files add about 1 kB per node together
    per_node = len(data) + EXPORT_BYTES_PER_NODE
    return TreeEstimate(seed=str(seed_path), nodes=written, bytes=(written + 1) * per_node)


#: Bytes of manifest.json + tree.graphml + tree.dot per node: 945-1,125 measured on trees of six dev-gold seeds.
EXPORT_BYTES_PER_NODE = 1100

#: Files a tree writes besides its nodes: root.xosc, manifest.json, tree.graphml, tree.dot.
FILES_PER_TREE = 4


def estimate_trees(seed_paths: Sequence[str | Path], *, seed: int = 0, cfg: dict[str, Any] | None = None,
                   ) -> list[TreeEstimate]:
    """`estimate_tree` for each seed; a seed that cannot be read counts as 0 (the build will report it)."""
    out = []
    for p in seed_paths:
        try:
            out.append(estimate_tree(p, seed=seed, cfg=cfg))
        except Txt2SceError:
            out.append(TreeEstimate(seed=str(p), nodes=0, bytes=0))
    return out


def _node_problems(text: str, version: str) -> list[str]:
    """XSD errors of one assembled node as `line N: message` ([] when valid; the caller prefixes the node id). A
    node that is not well-formed (α only joins well-formed fragments, so it would be a bug) is reported like a
    schema error rather than ending the tree."""
    try:
        return validate_xosc(text, version=version)
    except InputError as exc:
        return [str(exc)]


def _block_entry(dis: Disassembly, i: int, vs: list[Variant], ctx: SeedContext, cfg: dict[str, Any],
                 ) -> dict[str, Any]:
    b = dis.blocks[i]
    return {"index": b.index, "kind": b.kind.value, "key": b.key,
            "original_features": list(original_features(b, ctx, cfg)),
            "variants": [{"index": v.index, "operator": v.operator, "features": list(v.features),
                          "rng_seed": v.rng_seed} for v in vs]}


def _build_one(args: tuple[str, str, int, dict[str, Any]]) -> TreeResult:
    seed_path, out_dir, seed, cfg = args
    try:
        return build_tree(seed_path, out_dir, seed=seed, cfg=cfg)
    except Txt2SceError as exc:  # a batch records the failure and carries on with the other seeds
        return TreeResult(seed=seed_path, out_dir=Path(out_dir), block_counts=(), expected=0, nodes=0, pruned=0,
                          invalid=0, truncated=False, seconds=0.0, errors=(str(exc),))


def tree_dir_name(seed_path: Path) -> str:
    return seed_path.stem


def build_trees(seed_paths: Sequence[str | Path], out_dir: str | Path, *, seed: int = 0,
                cfg: dict[str, Any] | None = None, jobs: int = 1) -> list[TreeResult]:
    """One tree per seed under `out_dir/<seed stem>/`, `jobs` processes; results in the order of `seed_paths`."""
    cfg = cfg or tree_config()
    paths = [Path(p) for p in seed_paths]
    stems = [tree_dir_name(p) for p in paths]
    if len(set(stems)) != len(stems):
        dup = sorted({s for s in stems if stems.count(s) > 1})
        raise InputError(f"two seeds share the file name {dup[0]}: their trees would collide", source=str(out_dir))
    work = [(str(p), str(Path(out_dir) / s), seed, cfg) for p, s in zip(paths, stems)]
    if jobs <= 1 or len(work) <= 1:
        return [_build_one(w) for w in work]
    import multiprocessing as mp

    with mp.get_context("fork").Pool(jobs) as pool:
        return pool.map(_build_one, work, chunksize=1)
