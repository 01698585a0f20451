"""`txt2sce tree`: build scenario trees from seeds, or draw one.

    txt2sce tree SEEDS... --out DIR [--seed N] [--mutations 2] [--prune 0.5] [--max-nodes 2000] [--jobs 2]
                               [--check-sample N]
    txt2sce tree show TREE_DIR [--png FILE] [--depth 3]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from ..errors import InputError

from .argtypes import count, SHARE

HELP = "build scenario trees from seeds (δ, Table III mutations, α, pruning) — or `tree show DIR` to draw one"


def register(parser: argparse.ArgumentParser) -> None:
    parser.epilog = __doc__
    parser.add_argument("inputs", nargs="+", metavar="SEEDS",
                        help="seed .xosc files or directories of them; or `show TREE_DIR`")
    parser.add_argument("--out", help="output directory: one tree per seed in OUT/<seed name>/")
    parser.add_argument("--seed", type=count(ge=0), default=0, help="RNG seed (default 0)")
    parser.add_argument("--mutations", type=count(ge=0), default=None, help="M(b) for non-enumerated blocks (default 2)")
    parser.add_argument("--prune", type=SHARE, default=None, help="share kept per cluster, 1 = no pruning (0.5)")
    parser.add_argument("--max-nodes", type=count(), default=None,
                        help="node budget per tree, 0 = none (default 2000: later layers share what is left)")
    parser.add_argument("--jobs", type=count(), default=2, help="processes (default 2)")
    parser.add_argument("--config", help="mutation config YAML (default config/mutation.yaml)")
    parser.add_argument("--no-validate", action="store_true", help="skip XSD validation of generated files")
    parser.add_argument("--check-sample", type=count(ge=0), default=0, metavar="N",
                        help="after building, run the ASAM quality checker and the scenario player on N random files")
    parser.add_argument("--dry-run", action="store_true",
                        help="only say how many files and MB the trees would take, and where; write nothing")
    parser.add_argument("--png", help="show: PNG path (default TREE_DIR/tree.png)")
    parser.add_argument("--depth", type=count(ge=0), default=3, help="show: outline depth (default 3)")


def _seed_files(items: list[str]) -> list[Path]:
    out: list[Path] = []
    for item in items:
        p = Path(item)
        if p.is_dir():
            out.extend(sorted(p.rglob("*.xosc")))
        elif p.is_file():
            out.append(p)
        else:
            raise InputError("no such seed file or directory", source=item)
    if not out:
        raise InputError("no .xosc seeds found", source=" ".join(items))
    return out


def _show(args: argparse.Namespace) -> int:
    from ..tree.diversity import find_trees, load_manifest
    from ..tree.draw import draw_png, layer_summary, outline

    if len(args.inputs) < 2:
        raise InputError("usage: txt2sce tree show TREE_DIR", element="show")
    for d in find_trees(args.inputs[1:]):
        m = load_manifest(d)
        print("\n".join(layer_summary(m)))
        print("\n".join(outline(m, max_depth=args.depth)))
        png = Path(args.png) if args.png and len(args.inputs) == 2 else d / "tree.png"
        print(f"drawn: {draw_png(m, png)}")
        print(f"exports: {d / 'tree.graphml'}  {d / 'tree.dot'}  {d / 'manifest.json'}\n")
    return 0


def _announce(seeds: list[Path], out: Path, *, seed: int, cfg: dict, dry_run: bool) -> bool:
    """Say how much the build will write and where before writing it (the dev seeds make ~37k files, ~0.8 GB);
    False when nothing should be written (a dry run, or not enough free disk)."""
    import shutil

    from ..tree.build import FILES_PER_TREE, estimate_trees

    est = estimate_trees(seeds, seed=seed, cfg=cfg)
    files = sum(e.nodes for e in est) + FILES_PER_TREE * len(est)
    mb = sum(e.bytes for e in est) / 1e6
    where = out.resolve()
    probe = next((p for p in (where, *where.parents) if p.exists()), Path("/"))
    free_mb = shutil.disk_usage(probe).free / 1e6
    print(f"tree: {len(seeds)} seeds -> about {files:,} files, {mb:,.0f} MB in {where}/<seed>/ "
          f"({free_mb:,.0f} MB free there)", file=sys.stderr, flush=True)
    if dry_run:
        return False
    if mb > free_mb:
        raise InputError(f"not enough disk: the trees need about {mb:,.0f} MB, {free_mb:,.0f} MB free",
                         source=str(where))
    return True


def run(args: argparse.Namespace) -> int:
    if args.inputs[0] == "show":
        return _show(args)
    from ..tree.build import build_trees, tree_config

    if not args.out:
        raise InputError("--out DIR is required to build trees", element="--out")
    cfg = tree_config(args.config, mutations=args.mutations, prune_share=args.prune,
                      validate=False if args.no_validate else None, max_nodes=args.max_nodes)
    seeds = _seed_files(args.inputs)
    if not _announce(seeds, Path(args.out), seed=args.seed, cfg=cfg, dry_run=args.dry_run):
        return 0
    t0 = time.perf_counter()
    results = build_trees(seeds, args.out, seed=args.seed, cfg=cfg, jobs=args.jobs)
    wall = time.perf_counter() - t0
    total = failed = 0
    print(f"{'seed':<48} {'M(b) per layer':<30} {'Sum':>7} {'written':>8} {'pruned':>7} {'invalid':>7}")
    for r in results:
        name = Path(r.seed).stem
        if not r.block_counts and r.errors:
            failed += 1
            print(f"{name:<48} FAILED: {r.errors[0]}", file=sys.stderr)
            continue
        total += r.nodes
        counts = "x".join(str(c) for c in r.block_counts)
        print(f"{name:<48} {counts:<30} {r.expected:>7} {r.nodes:>8} {r.pruned:>7} {r.invalid:>7}"
              + ("  (budget)" if r.truncated else ""))
    print(f"\n{len(results) - failed} trees, {total} generated files in {wall:.1f} s "
          f"({total / wall if wall else 0:.0f} files/s, {args.jobs} jobs); "
          f"prune share {cfg['tree']['prune_share']}, M(b) = {cfg['tree']['mutations_per_block']}, "
          f"RNG seed {args.seed} -> {args.out}")
    if args.check_sample:
        from ..tree.checks import check_sample

        dirs = [r.out_dir for r in results if r.nodes]
        chk = check_sample(dirs, args.check_sample, seed=args.seed)
        player = (f"{chk.checked - chk.player_failed}/{chk.checked} load in the scenario player"
                  if chk.player_available else "scenario player not installed")
        print(f"sample check: {chk.checked - chk.qc_failed}/{chk.checked} ASAM-QC clean, {player}")
        for p in chk.problems:
            print(f"  {p}")
        if chk.qc_failed or chk.player_failed:
            return 1
    # 2: no seed could be grown (unusable input); 1: some failed (each printed), the other trees are written.
    if failed and failed == len(results):
        return 2
    return 1 if failed else 0
