"""Turn a campaign's stored results (and its trees) into the report of `txt2sce_ros.analysis.report`."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Sequence

from ..analysis.report import CampaignResults, write_report
from .runs import RunTask
from .store import ResultStore

#: How many representative failures get a top-down trajectory plot (one per category, most severe first).
FAILURE_PLOTS = 5


def _tree_nodes(tree_dir: Path) -> dict[str, dict[str, Any]]:
    """Manifest nodes keyed by id, with the fields derivation analysis reads (block, operator, changes)."""
    data = json.loads((tree_dir / "manifest.json").read_text(encoding="utf-8"))
    nodes = {}
    for n in data.get("nodes", []):
        block = f"{n['block_kind']}:{n['block_key']}" if n.get("block_kind") else "seed"
        changes = [{"path": c[0], "old": c[1], "new": c[2]} if isinstance(c, list) else c
                   for c in n.get("changes", [])]
        nodes[str(n["id"])] = {"parent": n.get("parent"), "block": block, "operator": n.get("operator", ""),
                               "changes": changes, "file": n.get("file")}
    return nodes


def _tree_dirs(inputs: Sequence[str | Path]) -> list[Path]:
    out = []
    for item in inputs:
        p = Path(item)
        if (p / "manifest.json").is_file():
            data = json.loads((p / "manifest.json").read_text(encoding="utf-8"))
            if "nodes" in data:
                out.append(p)
        elif p.is_dir():
            out += sorted(c for c in p.iterdir() if (c / "manifest.json").is_file())
    return out


def _violation_label(v: dict[str, Any]) -> str:
    """'Smooth: smooth_jerk'; a violation of no category (reported beside the verdict) by its rule alone."""
    cat, rule = v.get("category"), v.get("rule")
    return f"{cat}: {rule}" if cat and rule else str(cat or rule or "violation")


def failure_plots(runs: list[dict[str, Any]], faults: tuple[str, ...], limit: int = FAILURE_PLOTS, *,
                  time_limit: float | None = None) -> list[tuple[str, bytes]]:
    """Re-run a few failures keeping trajectories (runs are deterministic) and draw them over the lanes."""
    from ..closed_loop import run_closed_loop

    picked: list[dict[str, Any]] = []
    seen: set[str] = set()
    for r in runs:
        cats = [c for c in r["categories"] if c not in seen]
        if r["verdict"] == "fail" and cats and r.get("file"):
            picked.append(r)
            seen.update(r["categories"])
        if len(picked) >= limit:
            break
    out = []
    for r in picked:
        record, traj = run_closed_loop(r["file"], scenario_id=r["scenario_id"], faults=faults, keep_trajectory=True,
                                       time_limit=time_limit)
        if traj is None:
            continue
        out.append(_failure_plot(r, traj, record.details.get("violations", [])))
    return out


def _failure_plot(r: dict[str, Any], traj: dict[str, Any], violations: list[dict[str, Any]]) -> tuple[str, bytes]:
    """One failure's top-down plot: the lanes near it, every path, up to three violations marked."""
    import numpy as np

    from ..analysis.plots import lane_borders_near, trajectory_plot

    marks = []
    for v in violations:
        if len(marks) >= 3:
            break
        if "x" in v and "y" in v:
            marks.append((float(v["x"]), float(v["y"]), _violation_label(v)))
        elif "t" in v and len(traj.get("ego", ())):
            # violations carry a time, not a place: mark where the ego was then
            ego = traj["ego"]
            t = float(v["t"])
            marks.append((float(np.interp(t, ego[:, 0], ego[:, 1])), float(np.interp(t, ego[:, 0], ego[:, 2])),
                          f"{_violation_label(v)} @ {t:.1f} s"))
    where = f"{r['tree']}/{r['scenario_id']}" if r.get("tree") else r["scenario_id"]
    caption = f"{where}: {', '.join(r['categories'])}"
    return caption, trajectory_plot(traj, lane_borders_near(r["file"], traj), caption, marks)


def _git_commit() -> str:
    """The checkout's commit (with '+changes' when the tree differs from it), or 'unknown' outside a checkout."""
    import subprocess

    from ..paths import REPO_ROOT

    try:
        head = subprocess.run(["git", "-C", str(REPO_ROOT), "rev-parse", "--short=10", "HEAD"], capture_output=True,
                              text=True, timeout=10, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(REPO_ROOT), "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, timeout=10, check=True).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return head + (" +changes" if dirty else "")


def _config_digest(name: str) -> str:
    import hashlib

    from ..paths import config_dir

    path = config_dir() / f"{name}.yaml"
    try:
        return f"{path} (sha256 {hashlib.sha256(path.read_bytes()).hexdigest()[:12]})"
    except OSError:
        return f"{path} (not found)"


def tested_rows(settings: dict[str, Any], faults: Sequence[str], tasks: Sequence[RunTask],
                trees: Sequence[str], planner: dict[str, Any] | None = None) -> list[tuple[str, str]]:
    """What the campaign tested, as (what, value) rows: planner, faults, seeds, settings, versions."""
    import platform
    import sys

    from .. import __version__

    def opt(key: str, default: str) -> str:
        value = settings.get(key)
        return default if value is None else str(value)

    from ..tree.build import tree_config

    tree = tree_config()["tree"]      # the defaults the campaign used where no option was given
    shown = ", ".join(trees[:12]) + (f" and {len(trees) - 12} more" if len(trees) > 12 else "")
    return [
        ("system under test", "stand-in planner (standin_planner: IDM + pure pursuit), "
                              + _config_digest("planner") if not planner or planner.get("name") == "standin" else
                              f"{planner.get('package', planner.get('name'))} {planner.get('version', '')} through "
                              f"{planner.get('adapter', 'the topic interface')}; settings "
                              + ", ".join(f"{k}={v}" for k, v in sorted(planner.get("settings", {}).items()))),
        ("faults switched on", ", ".join(faults) or "none (nominal planner)"),
        ("inputs", ", ".join(settings.get("inputs", [])) or "–"),
        ("seeds / trees", f"{len(trees)}: {shown}" if trees else "none (plain scenario files)"),
        ("scenarios", f"{len(tasks)} files, {len({t.key for t in tasks})} distinct runs"),
        ("tree settings", f"mutations per block {opt('mutations', str(tree['mutations_per_block']))}, prune share "
                          f"{opt('prune', str(tree['prune_share']))}, node budget "
                          f"{opt('max_nodes', str(tree['max_nodes_per_tree']))}, first {opt('max_seeds', 'all')} "
                          f"seeds; {_config_digest('mutation')}"),
        ("run settings", f"RNG seed {opt('rng_seed', '0')}, simulated time limit {opt('time_limit', 'player default')}"
                         f" s, {'ROS 2 node graph over DDS' if settings.get('ros') else 'in-process cores'}, "
                         f"executor {opt('executor', '?')}, extractor {opt('backend', 'offline')}"),
        ("oracle", _config_digest("oracle")),
        ("versions", f"txt2sce {__version__} (git {_git_commit()}), Python {sys.version.split()[0]}, "
                     f"{platform.system()} {platform.machine()}"),
    ]


def _runs(store: ResultStore, tasks: Sequence[RunTask]) -> list[dict[str, Any]]:
    files = {t.key: t.scenario_path for t in tasks}
    return [{"scenario_id": r.scenario_id, "tree": r.tree, "parent": r.parent, "verdict": r.verdict,
             "categories": list(r.categories), "file": files.get(r.run_key), "record": r.record, "key": r.run_key}
            for r in store.runs() if not files or r.run_key in files]


def differential(runs: list[dict[str, Any]], baseline: list[dict[str, Any]]) -> dict[str, Any]:
    """Scenario by scenario, the planner under test against the baseline: its own failures (the baseline passes),
    failures of both, the baseline's alone, and errors (either side), with the categories of each."""
    base = {(r["tree"], r["scenario_id"]): r for r in baseline}
    rows: dict[str, list[dict[str, Any]]] = {"own": [], "both": [], "baseline_only": [], "both_pass": [],
                                            "error": [], "unmatched": []}
    for r in runs:
        b = base.get((r["tree"], r["scenario_id"]))
        if b is None:
            rows["unmatched"].append(r)
        elif "error" in (r["verdict"], b["verdict"]):
            rows["error"].append(r)
        elif r["verdict"] == "fail" and b["verdict"] == "pass":
            rows["own"].append(r)
        elif r["verdict"] == "fail":
            rows["both"].append({**r, "baseline_categories": b["categories"]})
        elif b["verdict"] == "fail":
            rows["baseline_only"].append({**r, "baseline_categories": b["categories"]})
        else:
            rows["both_pass"].append(r)
    return rows


def trajectory_failure_plots(runs: list[dict[str, Any]], traj_dir: Path, limit: int = FAILURE_PLOTS
                             ) -> list[tuple[str, bytes]]:
    """Failure plots of graph runs from the trajectories they kept (a third-party planner cannot be re-run
    in-process): one per category, most frequent first."""
    import numpy as np

    out: list[tuple[str, bytes]] = []
    seen: set[str] = set()
    for r in runs:
        cats = [c for c in r["categories"] if c not in seen]
        path = traj_dir / f"{r['key']}.npz"
        if r["verdict"] != "fail" or not cats or not r.get("file") or not path.is_file():
            continue
        seen.update(r["categories"])
        with np.load(path) as data:
            traj = {k: data[k] for k in data.files}
        out.append(_failure_plot(r, traj, r["record"].get("details", {}).get("violations", [])))
        if len(out) >= limit:
            break
    return out


def report_from_store(store: ResultStore, inputs: Sequence[str | Path], out_dir: Path,
                      tasks: Sequence[RunTask] = (), *, partial: str | None = None,
                      baseline_tasks: Sequence[RunTask] = ()) -> Path:
    """Write the campaign report from the stored runs; `partial` (a sentence) marks a report of an unfinished
    campaign; `baseline_tasks` (a differential campaign) adds the differential triage."""
    from ..analysis.features import ElementsReading

    runs = _runs(store, tasks)
    # the lift table's scenario elements (the report's biggest part) are read on the cores while this process
    # gathers the trees and draws the failure plots
    with ElementsReading([r["file"] for r in runs if r["verdict"] in ("pass", "fail") and r.get("file")]) as reading:
        return _report(store, inputs, out_dir, tasks, runs, reading, partial=partial, baseline_tasks=baseline_tasks)


def _report(store: ResultStore, inputs: Sequence[str | Path], out_dir: Path, tasks: Sequence[RunTask],
            runs: list[dict[str, Any]], reading: Any, *, partial: str | None,
            baseline_tasks: Sequence[RunTask]) -> Path:
    trees = {d.name: _tree_nodes(d) for d in _tree_dirs(inputs)}
    faults = tuple(store.meta("faults", []) or ())
    res = CampaignResults(runs=runs, trees=trees, partial=partial,
                          tested=tested_rows(store.meta("settings", {}) or {}, faults, tasks, sorted(trees),
                                             store.meta("planner", None)), elements=reading.result)
    if trees:
        from ..tree.diversity import diversity

        table = diversity(list(_tree_dirs(inputs)))
        res.diversity = [(row.level, row.abstract, row.variants) for row in table.rows]
        res.unique_categories = table.unique_categories
    res.planner = store.meta("planner", None)
    if baseline_tasks:
        res.baseline = store.meta("baseline", None)
        res.baseline_runs = _runs(store, baseline_tasks)
        res.differential = differential(runs, res.baseline_runs)
    traj_dir = next((Path(t.trajectory_dir) for t in tasks if t.trajectory_dir), None)
    if traj_dir is not None:
        res.failure_plots = trajectory_failure_plots(runs, traj_dir)
    else:
        # the same time limit as the stored runs, so the re-run draws what was judged
        time_limit = next((t.time_limit for t in tasks), None)
        res.failure_plots = failure_plots(runs, faults, time_limit=time_limit)
    md, _html = write_report(res, out_dir)
    return md
