"""`txt2sce bench tree`: scenario-tree generation + XSD validation throughput on 2 processes, beside baselines
measured in the same run, and peak memory at two tree sizes (memory must stay flat: files stream to disk).

- ours: `build_trees` (string-join assembly of pre-serialised blocks, validate, write), 2 processes
- baseline "deepcopy": per node, deep-copy the parsed seed, splice the node's block versions in as elements,
  serialise, validate, write — the obvious implementation, 1 process, node loop only (ours is timed whole,
  disassembly and mutation included, and also reported on 1 process)
- baseline "validate only": read + XSD-validate the files we wrote, 1 process

Each measurement runs in its own child process so peak RSS (ru_maxrss) is its own.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

DESCRIPTION = "scenario trees: generation + validation files/s on 2 processes vs deepcopy baseline; peak RSS"
MAX_NODES = 1000  # per tree, so one deep seed does not dominate the run


def _seeds(tmp: Path) -> list[Path]:
    """Seeds written by the seed stage from the dev sketches when it is available, else the tree test fixtures."""
    try:
        from txt2sce_ros.tree.seeds import dev_seeds

        seeds = dev_seeds(tmp / "seeds")
        if seeds:
            return seeds
    except ImportError:
        pass
    fixtures = Path(__file__).resolve().parents[2] / "tests" / "tree" / "fixtures"
    return sorted(fixtures.glob("*.xosc"))


def _child(mode: str, seeds: list[str], out: str, mutations: int, prune: float, jobs: int) -> dict:
    from txt2sce_ros.tree.build import build_trees, tree_config

    cfg = tree_config(mutations=mutations, prune_share=prune, max_nodes=MAX_NODES)
    t0 = time.perf_counter()
    if mode == "ours":
        res = build_trees(seeds, out, seed=0, cfg=cfg, jobs=jobs)
        files = sum(r.nodes for r in res)
        invalid = sum(r.invalid for r in res)
    elif mode == "deepcopy":
        files, invalid, timed = _deepcopy_baseline(seeds, out, cfg)
    else:
        files, invalid = _validate_only(out)
    dt = time.perf_counter() - t0
    if mode == "deepcopy":
        dt = timed
    rss = max(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
    return {"files": files, "seconds": dt, "invalid": invalid, "peak_rss_mb": rss / 1024.0}


def _deepcopy_baseline(seeds: list[str], out: str, cfg: dict) -> tuple[int, int]:
    """The same trees (same nodes, same block versions) made the obvious way: per node, deep-copy the parsed
    seed, replace the node's block elements by (copies of) the parsed versions, serialise, validate, write.
    Preparation (disassembly, mutation, parsing the versions once) is not timed; the node loop is."""
    import copy

    from lxml import etree

    from txt2sce_ros.tree.build import seed_key
    from txt2sce_ros.seed.context import build_context
    from txt2sce_ros.tree.disassembly import disassemble
    from txt2sce_ros.tree.mutate import block_variants
    from txt2sce_ros.tree.xml import parse_bytes, parse_fragment
    from txt2sce_ros.xosc.validate import validate_xosc

    files = invalid = 0
    elapsed = 0.0
    dst = Path(out) / "_deepcopy"
    dst.mkdir(parents=True, exist_ok=True)
    for seed in seeds:
        tree_dir = Path(out) / Path(seed).stem
        manifest = json.loads((tree_dir / "manifest.json").read_text())
        data = (tree_dir / "nodes" / "root.xosc").read_bytes()
        seed_root = parse_bytes(data, seed)
        ctx = build_context(parse_bytes(Path(seed).read_bytes(), seed), source=seed, seed_path=Path(seed))
        dis = disassemble(data, order=tuple(cfg["tree"]["order"]),
                          new_obstacle_slots=int(cfg["tree"]["new_obstacle_slots"]))
        blocks = {b.key: b for b in dis.blocks}
        versions = {}
        for bi, b in enumerate(manifest["blocks"]):
            if b["key"] in blocks:
                vs = block_variants(blocks[b["key"]], ctx, cfg, seed=0, seed_key=seed_key(Path(seed).name))
                versions[bi] = [[parse_fragment(f) for f in v.fragments if f] for v in vs]
        insertion = manifest["insertion"]
        t0 = time.perf_counter()
        for n in manifest["nodes"]:
            if n["depth"] == 0:
                continue
            root = copy.deepcopy(seed_root)
            for k, j in enumerate(n["path"]):
                for new in versions.get(insertion[k], [[]] * (j + 1))[j]:
                    old = _find(root, new)
                    if old is not None:
                        old.getparent().replace(old, copy.deepcopy(new))
                    else:  # an inserted obstacle: entity under Entities, its Private under Init/Actions
                        parent = root.find("Entities" if new.tag == "ScenarioObject" else "Storyboard/Init/Actions")
                        parent.append(copy.deepcopy(new))
            text = etree.tostring(root, encoding="utf-8", xml_declaration=True)
            if validate_xosc(text):
                invalid += 1
            (dst / f"{Path(seed).stem}_{n['id']}.xosc").write_bytes(text)
            files += 1
        elapsed += time.perf_counter() - t0
    return files, invalid, elapsed


def _find(root, el):
    """The element of `root` that version `el` replaces, by tag and name (None: a new obstacle)."""
    tag = el.tag
    if tag == "Private":
        return root.find(f"Storyboard/Init/Actions/Private[@entityRef='{el.get('entityRef')}']")
    if tag == "Environment":
        return root.find("Storyboard/Init/Actions/GlobalAction/EnvironmentAction/Environment")
    if tag == "ScenarioObject":
        return root.find(f"Entities/ScenarioObject[@name='{el.get('name')}']")
    if tag == "Story":
        return root.find(f"Storyboard/Story[@name='{el.get('name')}']")
    if tag == "GlobalAction":     # a signal block's Init action: the one setting the same light
        sid = next(el.iter("TrafficSignalStateAction")).get("name")
        return next(g for g in root.iterfind("Storyboard/Init/Actions/GlobalAction")
                    if any(a.get("name") == sid for a in g.iter("TrafficSignalStateAction")))
    return root.find(f".//Maneuver/Event[@name='{el.get('name')}']")


def _validate_only(out: str) -> tuple[int, int]:
    from txt2sce_ros.xosc.validate import validate_xosc

    files = invalid = 0
    for f in sorted(Path(out).glob("*/nodes/n*.xosc")):
        if validate_xosc(f.read_bytes()):
            invalid += 1
        files += 1
    return files, invalid


def _spawn(mode: str, seeds: list[Path], out: Path, mutations: int, prune: float, jobs: int) -> dict:
    args = json.dumps([mode, [str(s) for s in seeds], str(out), mutations, prune, jobs])
    proc = subprocess.run([sys.executable, "-m", "txt2sce_ros.bench.tree", "--child", args], capture_output=True,
                          text=True, env=dict(os.environ), check=False)
    if proc.returncode != 0:
        raise RuntimeError(f"bench child {mode} failed: {proc.stderr[-2000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def _row(name: str, r: dict) -> str:
    return (f"{name:<50} {r['files']:>7} {r['seconds']:>7.2f} {r['files'] / r['seconds']:>9.0f} "
            f"{r['peak_rss_mb']:>12.0f} {r['invalid']:>8}")


def run(args: argparse.Namespace) -> int:
    shm = Path("/dev/shm")
    with tempfile.TemporaryDirectory(prefix="txt2sce-bench-tree-") as disk_s, \
            tempfile.TemporaryDirectory(prefix="txt2sce-bench-tree-", dir=shm if shm.is_dir() else None) as ram_s:
        disk, ram = Path(disk_s), Path(ram_s)
        seeds = _seeds(disk)[: 8 if args.quick else 24]
        small_m, big_m = 1, 2
        print(f"bench tree: {len(seeds)} seeds, prune 1.0, <= {MAX_NODES} nodes a tree, every node written and "
              "XSD-validated; "
              f"disk {disk}, RAM {ram}")
        rows: list[tuple[str, dict]] = []
        small = _spawn("ours", seeds, ram / "small", small_m, 1.0, 2)
        big = _spawn("ours", seeds, ram / "big", big_m, 1.0, 2)
        rows.append((f"ours, 2 processes, M(b)={small_m}, RAM disk", small))
        rows.append((f"ours, 2 processes, M(b)={big_m}, RAM disk", big))
        on_disk = _spawn("ours", seeds, disk / "big", big_m, 1.0, 2)
        rows.append((f"ours, 2 processes, M(b)={big_m}, disk", on_disk))
        one = _spawn("ours", seeds, ram / "one", big_m, 1.0, 1)
        rows.append((f"ours, 1 process,   M(b)={big_m}, RAM disk", one))
        base = None
        if not args.quick:
            base = _spawn("deepcopy", seeds, ram / "big", big_m, 1.0, 1)
            rows.append(("baseline deepcopy+serialise+validate, 1 proc, RAM", base))
        rows.append(("baseline validate only (read+XSD), 1 process, RAM", _spawn("validate", seeds, ram / "big",
                                                                                big_m, 1.0, 1)))
        print(f"{'measurement':<50} {'files':>7} {'s':>7} {'files/s':>9} {'peak RSS MB':>12} {'invalid':>8}")
        for name, r in rows:
            print(_row(name, r))
        rate = big["files"] / big["seconds"]
        rate_disk = on_disk["files"] / on_disk["seconds"]
        print(f"\nthroughput ours, 2 processes: {rate:.0f} files/s (RAM disk), {rate_disk:.0f} files/s (disk); "
              f"goal >= 1000: {'met' if rate >= 1000 else 'NOT met'} / {'met' if rate_disk >= 1000 else 'NOT met'}")
        if base is not None:
            print(f"ours vs deepcopy baseline, 1 process each: "
                  f"{(one['files'] / one['seconds']) / (base['files'] / base['seconds']):.1f}x")
        print(f"peak RSS: {small['files']} files {small['peak_rss_mb']:.0f} MB, {big['files']} files "
              f"{big['peak_rss_mb']:.0f} MB (x{big['files'] / max(1, small['files']):.1f} files, "
              f"x{big['peak_rss_mb'] / small['peak_rss_mb']:.2f} memory: only the manifest grows)")
    return 0


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--child":
        mode, seeds, out, mutations, prune, jobs = json.loads(sys.argv[2])
        print(json.dumps(_child(mode, seeds, out, mutations, prune, jobs)))
    else:
        print("internal entry point of `txt2sce bench tree`", file=sys.stderr)
        sys.exit(2)
