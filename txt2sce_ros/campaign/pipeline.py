"""A whole campaign: reports -> sketches -> seeds -> trees -> closed-loop runs -> verdicts -> report.

Every stage writes its output under the campaign directory and a `.done` stamp when complete; a rerun (after a
crash or a kill) skips finished stages and, within the run stage, finished runs, so nothing is done twice and
nothing finished is lost. A campaign can start from any stage: report files, a sketch JSONL, a seed directory,
tree directories or plain scenario files.

    out/sketches.jsonl   out/seeds/   out/trees/<seed>/   out/results.sqlite   out/report/
"""

from __future__ import annotations

import json
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Sequence

from ..errors import InputError
from .runs import RunsSummary, count_duplicates, make_tasks, run_all
from .store import ResultStore

STAGES = ("reports", "sketches", "seeds", "trees", "scenarios")


@dataclass
class CampaignConfig:
    out: Path
    seed: int = 0
    backend: str = "offline"
    mutations: int | None = None          # per block; None = config/mutation.yaml (the paper's 2)
    prune: float | None = None            # kept share per cluster; None = config (0.5)
    executor: str = "pool"
    workers: int | None = None
    ray_address: str | None = None        # --executor ray: the cluster (None: RAY_ADDRESS, `ray start`'s, local)
    faults: tuple[str, ...] = ()
    ros: bool = False
    max_seeds: int | None = None          # the first N seeds only (quick demos)
    limit: int | None = None              # stop after N new runs (resume testing)
    time_limit: float | None = None       # simulated seconds per run (None: the player's limit)
    max_nodes: int | None = None          # node budget per tree; None = config/mutation.yaml
    progress: bool = True
    report: bool = True
    retry_errors: bool = False            # run again the runs stored with verdict error
    planner: str = "standin"              # the planner under test: standin | commonroad | none
    planner_settings: str = ""            # a third-party adapter's settings YAML ('' = its defaults)
    baseline: str | None = None           # also run this planner (the stand-in) on the same scenarios


@dataclass
class CampaignSummary:
    start_stage: str
    sketches: int = 0
    refused: list[dict[str, Any]] = field(default_factory=list)
    seeds: int = 0
    trees: int = 0
    scenarios: int = 0
    runs: RunsSummary | None = None
    baseline_runs: RunsSummary | None = None
    planner: dict[str, Any] = field(default_factory=dict)
    report: Path | None = None


def detect_stage(inputs: Sequence[str | Path]) -> str:
    """What the inputs are, from their content: the stage the campaign starts at."""
    kinds = {_kind(Path(p)) for p in inputs}
    if len(kinds) != 1:
        raise InputError(f"inputs mix stages ({', '.join(sorted(kinds))}); give one kind at a time")
    return kinds.pop()


def _kind(p: Path) -> str:
    if not p.exists():
        raise InputError("no such file or directory", source=str(p))
    if p.is_dir():
        manifest = p / "manifest.json"
        if manifest.is_file():
            data = _read_manifest(manifest)
            return "trees" if "nodes" in data else "seeds"
        if any(c.is_dir() and (c / "manifest.json").is_file() for c in p.iterdir()):
            return "trees"
        if any(p.rglob("*.xosc")):
            return "scenarios"
        return "reports"  # a directory of .txt / .pdf narratives
    if p.suffix == ".xosc":
        return "scenarios"
    if p.suffix == ".jsonl":
        from ..sketch import iter_jsonl

        # The first row that is a JSON object decides; bad rows are recorded later by the stage that reads them.
        first_problem = ""
        for lineno, first in iter_jsonl(p):
            if isinstance(first, dict):
                return "sketches" if str(first.get("schema", "")).startswith("txt2sce.sketch") else "reports"
            if not first_problem:
                first_problem = (f"first line is not JSON ({first.message})" if isinstance(first, InputError)
                                 else f"line {lineno} is not a JSON object")
        raise InputError(f"no row is a JSON object: {first_problem}" if first_problem else "empty JSON Lines file",
                         source=str(p))
    return "reports"


def _check_settings(cfg: CampaignConfig) -> None:
    """Every run reads the player, planner and oracle settings: a bad one is the user's error, said once now,
    not an *error* verdict on every run (nor, worse, a *fail* recorded against the stack)."""
    from oracle_monitor import OracleParams
    from scenario_player import SimulationConfig
    from standin_planner import PlannerParams

    SimulationConfig.from_config(time_limit=cfg.time_limit)
    PlannerParams.from_config()
    OracleParams.from_config()
    if cfg.workers is not None and cfg.workers < 1:
        raise InputError(f"workers must be >= 1, got {cfg.workers}", element="--workers")
    if cfg.prune is not None and not 0.0 < cfg.prune <= 1.0:
        raise InputError(f"prune share must be in (0, 1], got {cfg.prune}", element="--prune")


def _read_manifest(path: Path) -> dict[str, Any]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        raise InputError(f"unreadable manifest: {exc}", source=str(path)) from exc
    if not isinstance(data, dict):
        raise InputError("a manifest must be a JSON object", source=str(path))
    return data


def _stamp(path: Path) -> Path:
    return path.parent / f".{path.name}.done"


def _log(cfg: CampaignConfig, text: str) -> None:
    if cfg.progress:
        print(f"[campaign] {text}", file=sys.stderr)


def extract_stage(inputs: Sequence[str | Path], cfg: CampaignConfig) -> tuple[Path, int]:
    from ..sketch import SCHEMA_ID
    from ..text.pipeline import echo_errors, run_batch
    from ..text.readers import iter_inputs

    out = cfg.out / "sketches.jsonl"
    if not _stamp(out).exists():
        with out.open("w", encoding="utf-8") as fh:
            for item in echo_errors(run_batch(iter_inputs(inputs), backend=cfg.backend), "txt2sce campaign",
                                    where=str(out)):
                fh.write(json.dumps(item.to_dict(), sort_keys=True) + "\n")
        _stamp(out).touch()
    # sketches only: the error records written in place of unreadable reports carry a "schema" key too
    schemas = [json.loads(line).get("schema") for line in out.open(encoding="utf-8") if line.strip()]
    count = schemas.count(SCHEMA_ID)
    unread = len(schemas) - count
    _log(cfg, f"sketches: {count} -> {out}" + (f" ({unread} reports unreadable, see the errors above)" if unread
                                               else ""))
    return out, count


def seed_stage(sketches: Path, cfg: CampaignConfig) -> tuple[Path, dict[str, Any]]:
    from ..seed import write_seeds
    from ..sketch import load_sketches

    out = cfg.out / "seeds"
    if not _stamp(out).exists():
        write_seeds(load_sketches(sketches), out, seed=cfg.seed)
        _stamp(out).touch()
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    _log(cfg, f"seeds: {len(manifest['built'])} built, {len(manifest['refused'])} refused -> {out}")
    if not manifest["built"]:
        # Every later stage would fail on an empty directory with a message about that directory, not the cause.
        raise InputError(f"no seed could be built from the {len(manifest['refused'])} sketch(es): nothing to run "
                         f"(why each was refused: {out / 'manifest.json'})", source=str(sketches))
    return out, manifest


def tree_stage(seed_dir: Path, cfg: CampaignConfig) -> Path:
    from ..tree.build import build_trees, tree_config

    out = cfg.out / "trees"
    manifest = _read_manifest(seed_dir / "manifest.json")
    try:
        seeds = [seed_dir / e["file"] for e in manifest["built"]]
    except (KeyError, TypeError) as exc:
        raise InputError("not a seed manifest (no built[].file)", source=str(seed_dir / "manifest.json")) from exc
    if cfg.max_seeds is not None:
        seeds = seeds[: cfg.max_seeds]
    if not _stamp(out).exists():
        tcfg = tree_config(mutations=cfg.mutations, prune_share=cfg.prune, max_nodes=cfg.max_nodes)
        results = build_trees(seeds, out, seed=cfg.seed, cfg=tcfg, jobs=cfg.workers or 2)
        _log(cfg, f"trees: {len(results)} built, {sum(r.nodes for r in results)} nodes "
                  f"({sum(r.pruned for r in results)} pruned) -> {out}")
        _stamp(out).touch()
    return out


def planner_info(name: str, settings_file: str = "", faults: Sequence[str] = ()) -> dict[str, Any]:
    """What the result store, the console and the report say of the planner under test: name, version, settings.
    Raises InputError (one line) when the planner cannot run here."""
    if name == "standin":
        from importlib.metadata import PackageNotFoundError, version

        try:
            ver = version("txt2sce_ros")
        except PackageNotFoundError:
            ver = "checkout"
        return {"name": "standin", "version": ver, "settings": {"faults": sorted(faults),
                                                               "config": "config/planner.yaml"}}
    if name == "commonroad":
        from sut_adapters.commonroad.settings import AdapterSettings
        from sut_adapters.commonroad.venv import available, planner_version

        why = available()
        if why:
            raise InputError(why)
        try:
            ver = planner_version()
        except (FileNotFoundError, OSError) as exc:
            raise InputError(str(exc)) from exc
        settings = AdapterSettings.from_yaml(settings_file or None).to_dict()
        return {"name": "commonroad", "package": "commonroad-reactive-planner", "version": ver,
                "adapter": "sut_adapters/commonroad", "settings": settings}
    if name == "none":
        return {"name": "none", "version": "external", "settings": {"ROS_DOMAIN_ID": os.environ.get("ROS_DOMAIN_ID",
                                                                                                  "0")}}
    raise InputError(f"unknown planner {name!r} (choose standin, commonroad or none)")


def run_campaign(inputs: Sequence[str | Path], cfg: CampaignConfig) -> CampaignSummary:
    """Run the campaign from whatever stage the inputs are at; resumable (see the module docstring)."""
    from standin_planner.faults import Faults

    # An unknown fault name is the user's mistake: say so now, not as an 'error' verdict on every run.
    Faults.from_names(cfg.faults)
    _check_settings(cfg)
    if cfg.planner != "standin" and cfg.faults:
        raise InputError("--fault switches stand-in faults; it cannot be combined with --planner " + cfg.planner)
    if cfg.baseline not in (None, "standin"):
        raise InputError(f"--baseline {cfg.baseline}: only the stand-in can be the baseline")
    planner = planner_info(cfg.planner, cfg.planner_settings, cfg.faults)
    if not inputs:
        raise InputError("no inputs given")
    stage = detect_stage(inputs)
    cfg.out.mkdir(parents=True, exist_ok=True)
    summary = CampaignSummary(start_stage=stage)
    scenario_inputs: list[str | Path] = list(inputs)
    if stage == "reports":
        sketches, summary.sketches = extract_stage(inputs, cfg)
        stage, scenario_inputs = "sketches", [sketches]
    if stage == "sketches":
        seed_dir, manifest = seed_stage(Path(scenario_inputs[0]), cfg)
        summary.seeds, summary.refused = len(manifest["built"]), manifest["refused"]
        stage, scenario_inputs = "seeds", [seed_dir]
    if stage == "seeds":
        tree_dir = tree_stage(Path(scenario_inputs[0]), cfg)
        stage, scenario_inputs = "trees", [tree_dir]
    third_party = cfg.planner != "standin"
    tasks = make_tasks(scenario_inputs, faults=cfg.faults, seed=cfg.seed, ros=cfg.ros, time_limit=cfg.time_limit,
                       planner=cfg.planner, planner_settings=planner["settings"] if third_party else None,
                       planner_settings_file=cfg.planner_settings,
                       trajectory_dir=str(cfg.out / "trajectories") if third_party else None)
    baseline_tasks = []
    if cfg.baseline and cfg.baseline != cfg.planner:
        # the stand-in in-process: the same verdicts as over ROS (tested), without slowing the campaign
        baseline_tasks = make_tasks(scenario_inputs, seed=cfg.seed, time_limit=cfg.time_limit)
    summary.scenarios = len(tasks)
    summary.trees = len({t.tree for t in tasks if t.tree})
    summary.planner = planner
    dup = count_duplicates(tasks)
    _log(cfg, f"closed loop: {len(tasks)} scenarios"
              + (f" ({dup} byte-identical to another one, judged once: {len(tasks) - dup} runs)" if dup else "")
              + f", executor {cfg.executor}, planner {planner['name']} {planner['version']}"
              + (f", faults {', '.join(cfg.faults)}" if cfg.faults else "")
              + (f", baseline {cfg.baseline}" if baseline_tasks else ""))
    # a user's stack on one domain serves one run at a time
    executor = "serial" if cfg.planner == "none" else cfg.executor
    with ResultStore(cfg.out / "results.sqlite") as store:
        if cfg.retry_errors:
            _log(cfg, f"retrying {store.drop_errors()} stored error run(s)")
        store.set_meta("faults", list(cfg.faults))
        store.set_meta("planner", planner)
        # what the report says was tested (settings of the run that wrote it; the run key covers the rest)
        store.set_meta("settings", {
            "inputs": [str(p) for p in inputs], "start_stage": summary.start_stage, "rng_seed": cfg.seed,
            "backend": cfg.backend, "mutations": cfg.mutations, "prune": cfg.prune, "max_nodes": cfg.max_nodes,
            "max_seeds": cfg.max_seeds, "time_limit": cfg.time_limit, "executor": cfg.executor, "ros": cfg.ros})
        if baseline_tasks:
            store.set_meta("baseline", planner_info(cfg.baseline))
            summary.baseline_runs = run_all(baseline_tasks, store, executor=cfg.executor, workers=cfg.workers,
                                            progress=cfg.progress, limit=cfg.limit,
                                            ray_address=cfg.ray_address)
        summary.runs = run_all(tasks, store, executor=executor, workers=cfg.workers, progress=cfg.progress,
                               limit=cfg.limit, ray_address=cfg.ray_address)
        if cfg.report:
            from .reporting import report_from_store

            partial = None
            if summary.runs.left:
                # a --limit run still gets its report, marked partial, so the first look needs no second command
                judged = summary.runs.total - summary.runs.duplicates - summary.runs.left
                partial = (f"partial campaign: {judged} of {judged + summary.runs.left} distinct scenarios judged "
                           f"so far (--limit {cfg.limit}); rerun without --limit to finish and update this report")
            summary.report = report_from_store(store, scenario_inputs, cfg.out / "report", tasks=tasks,
                                               partial=partial, baseline_tasks=baseline_tasks)
    return summary
