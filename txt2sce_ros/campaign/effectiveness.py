"""Effectiveness study: does the pipeline find a planted fault, and does its analysis name the right trigger?

For each stand-in planner fault mode the same scenarios run twice, with the nominal planner and with the fault
switched on. The fault is *found* when some scenario shows the fault's category with the fault and not without it.
The lift ranking is then computed over those differential runs (a scenario counts for the category when the fault
added it), and the rank of the element the fault depends on is reported: 1 means the analysis points straight at it.
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Mapping, Sequence

from ..analysis.lift import LiftRow, lift_table


@dataclass(frozen=True)
class FaultSpec:
    name: str
    category: str                   # the category the fault should cause (Table VI)
    triggers: tuple[str, ...]       # element substrings it depends on (any counts as right)
    why: str


#: Ground truth for the stand-in planner's fault modes (standin_planner/faults.py documents the mechanisms).
FAULTS: tuple[FaultSpec, ...] = (
    FaultSpec("ignore_cyclists", "Collisions", ("category:bicycle", "category:scooter"),
              "bicycles and scooters are not treated as obstacles"),
    FaultSpec("late_braking_low_friction", "Collisions", ("weather:rain", "weather:fog", "weather:snow"),
              "braking distance ignores road friction"),
    FaultSpec("no_start_when_close", "StartFail", ("near_start:yes", "position:R5/same", "position:R6/same"),
              "refuses to start with a party within a few metres ahead or behind"),
    FaultSpec("stale_tracking", "Collisions", ("position:R5", "events:ah", "events:ac", "events:h", "events:c",
                                              "events:m", "events:f", "events:g"),
              "object states delayed: a lead that brakes, or a party that cuts in or crosses into the path, is "
              "seen late"),
    FaultSpec("aggressive_start", "StartFail", ("weather:rain", "weather:fog", "weather:snow"),
              "high throttle and steering at start slip on low friction"),
    FaultSpec("red_light_misread", "Misinterp", ("signal:yellow",),
              "yellow read as green"),
)


@dataclass(frozen=True)
class EffectivenessRow:
    fault: str
    category: str
    found: bool
    runs_with_fault: int            # runs showing the category with the fault
    runs_nominal: int               # runs showing it with the nominal planner
    differential: int               # scenarios where only the faulty planner showed it
    top_trigger: str
    right_rank: int | None          # rank of the first right trigger in the differential lift ranking


def names_trigger(element: str, triggers: Sequence[str]) -> bool:
    """Whether a lift element names one of the fault's triggers. A combined element `R5+m` (a party at R5 doing
    m) names what its parts `position:R5` and `events:m` name."""
    parts = [element]
    head, plus, codes = element.partition("+")
    if plus and head.startswith("R") and ":" not in head:
        parts += [f"position:{head}", f"events:{codes}"]
    return any(t in p for p in parts for t in triggers)


def assess(spec: FaultSpec, nominal: Mapping[str, frozenset[str]], faulty: Mapping[str, frozenset[str]],
           elements: Mapping[str, frozenset[str]], *, min_support: int = 2) -> tuple[EffectivenessRow, list[LiftRow]]:
    """`nominal`/`faulty`: scenario id -> categories shown; `elements`: scenario id -> its scenario elements."""
    ids = sorted(set(nominal) & set(faulty) & set(elements))
    with_fault = sum(1 for i in ids if spec.category in faulty[i])
    without = sum(1 for i in ids if spec.category in nominal[i])
    diff = {i for i in ids if spec.category in faulty[i] and spec.category not in nominal[i]}
    runs = [(elements[i], frozenset({spec.category}) if i in diff else frozenset()) for i in ids]
    rows = lift_table(runs, min_support=min_support).get(spec.category, [])
    rank = next((k for k, r in enumerate(rows, 1) if names_trigger(r.element, spec.triggers)), None)
    top = f"{rows[0].element} ({rows[0].lift:.2f}×)" if rows else "–"
    return EffectivenessRow(spec.name, spec.category, bool(diff), with_fault, without, len(diff), top, rank), rows


def format_table(rows: Sequence[EffectivenessRow]) -> str:
    head = f"{'fault':<27} {'category':<11} {'found':<6} {'faulty':>6} {'nominal':>7} {'diff':>5}  " \
           f"{'top trigger':<34} {'right rank':>10}"
    out = [head, "-" * len(head)]
    for r in rows:
        out.append(f"{r.fault:<27} {r.category:<11} {'yes' if r.found else 'no':<6} {r.runs_with_fault:>6} "
                   f"{r.runs_nominal:>7} {r.differential:>5}  {r.top_trigger:<34} "
                   f"{r.right_rank if r.right_rank is not None else '–':>10}")
    return "\n".join(out)


@dataclass
class StudyConfig:
    out: Path
    seeds: int = 10                 # seeds grown into trees (picked to cover the most scenario elements)
    nodes: int = 150                # node budget per tree (every enumerated value still gets its nodes)
    mutations: int = 1              # per non-enumerated block; weather, signal and NPC category are enumerated
    time_limit: float | None = 25.0
    executor: str = "pool"
    workers: int | None = None
    faults: tuple[str, ...] = tuple(f.name for f in FAULTS)
    seed: int = 0
    progress: bool = True


def pick_seeds(seed_files: Sequence[Path], n: int) -> list[Path]:
    """Greedy cover: each pick adds the most scenario elements not yet covered (ties: file name), so a handful of
    seeds spans cyclists, signals, parties close to the ego, obstacles... Deterministic."""
    from ..analysis.features import elements_of_file

    # a party's category and position and the signal are what the faults depend on; counts are not
    def useful(f: Path) -> set[str]:
        return {e for e in elements_of_file(str(f)) if not e.startswith(("npcs:", "obstacle:no", "weather:"))}

    pool = {f: useful(f) for f in sorted(seed_files)}
    chosen: list[Path] = []
    covered: set[str] = set()
    while pool and len(chosen) < n:
        best = max(pool, key=lambda f: (len(pool[f] - covered), -sorted(pool).index(f)))
        chosen.append(best)
        covered |= pool.pop(best)
    return chosen


def run_study(inputs: Sequence[str | Path], cfg: StudyConfig) -> list[EffectivenessRow]:
    """Reports/sketches/seeds -> trees from a few covering seeds -> every scenario nominal and with each fault
    (one resumable store; nominal runs are shared by all faults) -> one row per fault."""
    from ..errors import InputError
    from .pipeline import CampaignConfig, detect_stage, extract_stage, seed_stage, tree_stage
    from .runs import make_tasks, run_all
    from .store import ResultStore

    from standin_planner.faults import Faults

    Faults.from_names(cfg.faults)
    specs = [s for s in FAULTS if s.name in cfg.faults]
    cfg.out.mkdir(parents=True, exist_ok=True)
    ccfg = CampaignConfig(out=cfg.out, seed=cfg.seed, mutations=cfg.mutations, max_nodes=cfg.nodes,
                          executor=cfg.executor, workers=cfg.workers, progress=cfg.progress)
    stage = detect_stage(inputs)
    if stage == "reports":
        sketches, _ = extract_stage(inputs, ccfg)
        inputs, stage = [sketches], "sketches"
    if stage == "sketches":
        seed_dir, _ = seed_stage(Path(inputs[0]), ccfg)
        inputs, stage = [seed_dir], "seeds"
    if stage != "seeds":
        raise InputError(f"effectiveness starts from reports, sketches or a seed directory, not {stage}",
                         source=str(inputs[0]))
    seed_dir = Path(inputs[0])
    manifest = json.loads((seed_dir / "manifest.json").read_text(encoding="utf-8"))
    picked = cfg.out / "picked_seeds"
    if (picked / "manifest.json").is_file():
        # resuming: the seeds the trees were grown from, whatever a changed feature reader would pick now
        chosen = [Path(e["file"]) for e in json.loads((picked / "manifest.json").read_text(encoding="utf-8"))["built"]]
    else:
        chosen = pick_seeds([seed_dir / e["file"] for e in manifest["built"]], cfg.seeds)
        picked.mkdir(exist_ok=True)
        (picked / "manifest.json").write_text(json.dumps(
            {"built": [{"file": str(p.resolve())} for p in chosen], "refused": []}, indent=1), encoding="utf-8")
    tree_dir = tree_stage(picked, ccfg)

    by_config: dict[str, list[Any]] = {}
    for fault in ("", *(s.name for s in specs)):
        by_config[fault] = make_tasks([tree_dir], faults=(fault,) if fault else (), seed=cfg.seed,
                                      time_limit=cfg.time_limit)
    all_tasks = [t for ts in by_config.values() for t in ts]
    with ResultStore(cfg.out / "results.sqlite") as store:
        run_all(all_tasks, store, executor=cfg.executor, workers=cfg.workers, progress=cfg.progress)
        stored = {r.run_key: r for r in store.runs()}

    from ..analysis.features import elements_of_file

    def cats(tasks: Sequence[Any]) -> dict[str, frozenset[str]]:
        # errors are not judged: a scenario the player could not run counts for neither side
        return {f"{t.tree}/{t.scenario_id}": frozenset(stored[t.key].categories) for t in tasks
                if t.key in stored and stored[t.key].verdict != "error"}

    nominal = cats(by_config[""])
    elements = {f"{t.tree}/{t.scenario_id}": elements_of_file(t.scenario_path) for t in by_config[""]}
    rows, details = [], {}
    for spec in specs:
        row, lift = assess(spec, nominal, cats(by_config[spec.name]), elements)
        rows.append(row)
        details[spec.name] = {"row": asdict(row), "why": spec.why, "right_triggers": list(spec.triggers),
                              "lift": [asdict(r) for r in lift[:10]]}
    (cfg.out / "effectiveness.json").write_text(json.dumps(
        {"scenarios": len(by_config[""]), "seeds": [p.name for p in chosen], "time_limit": cfg.time_limit,
         "faults": details}, indent=1, sort_keys=True), encoding="utf-8")
    (cfg.out / "effectiveness.txt").write_text(format_table(rows) + "\n", encoding="utf-8")
    return rows
