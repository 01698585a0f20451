"""Effectiveness study: does the pipeline find a planted fault, and does its analysis name the right trigger?

For each stand-in planner fault mode the same scenarios run twice, with the nominal planner and with the fault
switched on. The fault is *found* when some scenario shows the fault's category with the fault and not without it.
The lift ranking is then computed over those differential runs (a scenario counts for the category when the fault
added it), within each scenario tree (`lift_table` strata: a tree's scenarios share its seed's parties, map and
events, so across trees those ride along with whatever a mutation caused; within a tree only what the mutations
changed tells a run that shows the category from one that does not), and the rank of the element the fault
depends on is reported: 1 means the analysis points straight at it. The ranking shrinks each lift by one
pseudo-run (`RANK_PRIOR`), leaves party counts out (`UNRANKED_PREFIXES`), and reports elements that occurred in
exactly the same runs as one joint condition (`analysis.lift`), which counts as right when any of its parts is.
"""

from __future__ import annotations

import json
import sys
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Mapping, Sequence

from ..analysis.lift import LiftRow, joint_parts, lift_table


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
    m) names what its parts `position:R5` and `events:m` name; a joint condition (elements that occurred in
    exactly the same runs, `analysis.lift.JOINT`) names what any of its elements names."""
    parts = []
    for one in joint_parts(element):
        parts.append(one)
        head, plus, codes = one.partition("+")
        if plus and head.startswith("R") and ":" not in head:
            parts += [f"position:{head}", f"events:{codes}"]
    return any(t in p for p in parts for t in triggers)


#: Element kinds left out of the trigger ranking: within a tree the number of parties changes only when the new-party
#: slot adds one, so `npcs:k` stands for "a party was added", whatever its role; that party's own elements (its
#: category, position, events, closeness) say which condition it brought in. (Seed picking leaves counts out too.)
UNRANKED_PREFIXES = ("npcs:",)


def ranked_elements(elements: frozenset[str]) -> frozenset[str]:
    """The elements of a scenario that the trigger ranking considers (`UNRANKED_PREFIXES` left out)."""
    return frozenset(e for e in elements if not e.startswith(UNRANKED_PREFIXES))


#: Pseudo-runs of shrinkage in the ranking (`lift_table` `prior`): one run expected and observed, so that two runs
#: that happen to share an element (14× on an expected 0.14) do not outrank the element twenty runs share.
RANK_PRIOR = 1.0


def assess(spec: FaultSpec, nominal: Mapping[str, frozenset[str]], faulty: Mapping[str, frozenset[str]],
           elements: Mapping[str, frozenset[str]], *, min_support: int = 2,
           trees: Mapping[str, str] | None = None, prior: float = RANK_PRIOR
           ) -> tuple[EffectivenessRow, list[LiftRow]]:
    """`nominal`/`faulty`: scenario id -> categories shown; `elements`: scenario id -> its scenario elements;
    `trees`: scenario id -> the tree it grew in, to rank by the lift within trees (`lift_table` strata: what the
    tree's mutations changed, not what its seed holds throughout); None ranks over all scenarios at once. `prior`:
    the ranking's shrinkage (`RANK_PRIOR`; 0 ranks by the plain lift)."""
    ids = sorted(set(nominal) & set(faulty) & set(elements))
    elements = {i: ranked_elements(elements[i]) for i in ids}
    with_fault = sum(1 for i in ids if spec.category in faulty[i])
    without = sum(1 for i in ids if spec.category in nominal[i])
    diff = {i for i in ids if spec.category in faulty[i] and spec.category not in nominal[i]}
    runs = [(elements[i], frozenset({spec.category}) if i in diff else frozenset()) for i in ids]
    strata = [trees[i] for i in ids] if trees is not None else None
    rows = lift_table(runs, min_support=min_support, strata=strata, prior=prior).get(spec.category, [])
    rank = next((k for k, r in enumerate(rows, 1) if names_trigger(r.element, spec.triggers)), None)
    top = f"{rows[0].element} ({rows[0].lift:.2f}×)" if rows else "–"
    return EffectivenessRow(spec.name, spec.category, bool(diff), with_fault, without, len(diff), top, rank), rows


def format_table(rows: Sequence[EffectivenessRow]) -> str:
    # a joint condition ('a & b & c') can be long: the column widens so the rank stays in its column
    w = max([34] + [len(r.top_trigger) for r in rows])
    head = f"{'fault':<27} {'category':<11} {'found':<6} {'faulty':>6} {'nominal':>7} {'diff':>5}  " \
           f"{'top trigger':<{w}} {'right rank':>10}"
    out = [head, "-" * len(head)]
    for r in rows:
        out.append(f"{r.fault:<27} {r.category:<11} {'yes' if r.found else 'no':<6} {r.runs_with_fault:>6} "
                   f"{r.runs_nominal:>7} {r.differential:>5}  {r.top_trigger:<{w}} "
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
    ray_address: str | None = None
    faults: tuple[str, ...] = tuple(f.name for f in FAULTS)
    seed: int = 0
    progress: bool = True
    draws: int = 0                  # random draws of `seeds` seeds (0: one covering pick, `pick_seeds`)
    draw_seed: int = 0              # seeds the draws' Generator


def pick_seeds(seed_files: Sequence[Path], n: int) -> list[Path]:
    """Greedy cover: each pick adds the most scenario elements not yet covered (ties: file name), so a handful of
    seeds spans cyclists, signals, parties close to the ego, obstacles... An element counts for a seed when the
    seed holds it or its tree can bring it in (`tree.build.reachable_elements`: a new cyclist, a standing start,
    a dilemma-zone yellow on the map's lights...). Deterministic."""
    from ..analysis.features import elements_of_file
    from ..errors import Txt2SceError
    from ..tree.build import reachable_elements

    # a party's category and position and the signal are what the faults depend on; counts are not
    def useful(f: Path) -> set[str]:
        try:
            reach = reachable_elements(f)
        except Txt2SceError:        # a seed the tree cannot read: what it holds still counts
            reach = frozenset()
        return {e for e in elements_of_file(str(f)) | reach
                if not e.startswith(("npcs:", "obstacle:no", "weather:"))}

    pool = {f: useful(f) for f in sorted(seed_files)}
    chosen: list[Path] = []
    covered: set[str] = set()
    while pool and len(chosen) < n:
        best = max(pool, key=lambda f: (len(pool[f] - covered), -sorted(pool).index(f)))
        chosen.append(best)
        covered |= pool.pop(best)
    return chosen


def draw_seeds(seed_files: Sequence[Path], n: int, draws: int, draw_seed: int) -> list[list[Path]]:
    """`draws` independent random draws of `n` seeds each (without replacement within a draw), from a Generator
    seeded by `draw_seed`: the honest test of whether the study finds the faults from *any* seeds, not only from
    seeds picked to hold the triggers. Files are sorted first, so the draws do not depend on listing order."""
    import numpy as np

    files = sorted(seed_files)
    rng = np.random.default_rng(np.random.SeedSequence([int(draw_seed), 0x64726177]))
    k = min(n, len(files))
    return [[files[int(i)] for i in sorted(rng.choice(len(files), size=k, replace=False))] for _ in range(draws)]


@dataclass(frozen=True)
class DrawResult:
    """One draw of a study: the seeds drawn and one row per fault."""

    index: int
    seeds: tuple[str, ...]
    rows: tuple[EffectivenessRow, ...]

    @property
    def found(self) -> int:
        return sum(r.found for r in self.rows)

    @property
    def right_first(self) -> int:
        return sum(r.right_rank == 1 for r in self.rows)


def format_draws(draws: Sequence[DrawResult]) -> str:
    """One line per draw (found, right trigger first, each fault's rank: `-` = not found, `x` = found but the
    right trigger unranked), then the minimum and median over draws."""
    import statistics

    if not draws:
        return "no draws"
    names = [r.fault for r in draws[0].rows]
    n = len(names)
    out = ["per fault: " + ", ".join(f"{i + 1}={name}" for i, name in enumerate(names)),
           f"{'draw':<5} {'found':>6} {'right 1st':>9}  ranks"]
    for d in draws:
        ranks = " ".join("-" if not r.found else ("x" if r.right_rank is None else str(r.right_rank))
                         for r in d.rows)
        out.append(f"{d.index:<5} {d.found:>4}/{n} {d.right_first:>7}/{n}  {ranks}")
    found = [d.found for d in draws]
    first = [d.right_first for d in draws]
    out.append(f"{'min':<5} {min(found):>4}/{n} {min(first):>7}/{n}")
    out.append(f"{'med':<5} {statistics.median(found):>4g}/{n} {statistics.median(first):>7g}/{n}")
    return "\n".join(out)


def _seed_dir(inputs: Sequence[str | Path], ccfg: Any) -> Path:
    """Reports or sketches are brought to a seed directory under the study directory; a seed directory is used as
    it is."""
    from ..errors import InputError
    from .pipeline import detect_stage, extract_stage, seed_stage

    stage = detect_stage(inputs)
    if stage == "reports":
        sketches, _ = extract_stage(inputs, ccfg)
        inputs, stage = [sketches], "sketches"
    if stage == "sketches" and len(inputs) > 1:
        # several sketch sets (dev_gold + dev_gold_study) are one pool to draw from
        joined = ccfg.out / "sketches_joined.jsonl"
        joined.write_text("".join(Path(f).read_text(encoding="utf-8").rstrip("\n") + "\n" for f in inputs),
                          encoding="utf-8")
        inputs = [joined]
    if stage == "sketches":
        seed_dir, _ = seed_stage(Path(inputs[0]), ccfg)
        inputs, stage = [seed_dir], "seeds"
    if stage != "seeds":
        raise InputError(f"effectiveness starts from reports, sketches or a seed directory, not {stage}",
                         source=str(inputs[0]))
    return Path(inputs[0])


def _chosen_seeds(seed_dir: Path, cfg: StudyConfig) -> list[list[Path]]:
    """The seeds of every draw (one covering pick without draws). Stored on first use, so a resumed study grows
    the same trees whatever a changed feature reader or seed set would pick now."""
    picked = cfg.out / "picked_seeds"
    record = picked / "draws.json"
    if record.is_file():
        return [[Path(f) for f in d] for d in json.loads(record.read_text(encoding="utf-8"))["draws"]]
    if not cfg.draws and (picked / "manifest.json").is_file():   # a study written before draws existed
        return [[Path(e["file"]) for e in json.loads((picked / "manifest.json").read_text(encoding="utf-8"))["built"]]]
    manifest = json.loads((seed_dir / "manifest.json").read_text(encoding="utf-8"))
    files = [seed_dir / e["file"] for e in manifest["built"]]
    if cfg.draws:
        if cfg.draws > 1 and len(files) <= cfg.seeds:
            print(f"[effectiveness] warning: {len(files)} seed(s) built, not more than --seeds {cfg.seeds}: every "
                  f"draw takes all of them, so the {cfg.draws} draws are one study repeated", file=sys.stderr)
        draws = draw_seeds(files, cfg.seeds, cfg.draws, cfg.draw_seed)
    else:
        draws = [pick_seeds(files, cfg.seeds)]
    union = sorted({p.resolve() for d in draws for p in d})
    picked.mkdir(parents=True, exist_ok=True)
    # the tree stage reads a seed manifest: the union of all draws, each tree grown once
    (picked / "manifest.json").write_text(json.dumps(
        {"built": [{"file": str(p)} for p in union], "refused": []}, indent=1), encoding="utf-8")
    record.write_text(json.dumps({"draws": [[str(p.resolve()) for p in d] for d in draws],
                                  "draw_seed": cfg.draw_seed}, indent=1), encoding="utf-8")
    return [[p.resolve() for p in d] for d in draws]


def _inert(path: str) -> frozenset[str]:
    """The faults that cannot act in the scenario file at `path` (`standin_planner.faults.inert_faults`)."""
    from standin_planner.faults import inert_faults

    from ..xosc.schema import parse_document

    return inert_faults(parse_document(Path(path).read_bytes(), source=path))


def run_study(inputs: Sequence[str | Path], cfg: StudyConfig) -> list[EffectivenessRow]:
    """Reports/sketches/seeds -> trees from a few covering seeds -> every scenario nominal and with each fault
    (one resumable store; nominal runs are shared by all faults) -> one row per fault. With `cfg.draws`, the
    rows of the first draw (`run_draws` gives them all)."""
    return list(run_draws(inputs, cfg)[0].rows)


def run_draws(inputs: Sequence[str | Path], cfg: StudyConfig) -> list[DrawResult]:
    """The study once per draw of seeds (once, on covering seeds, without `cfg.draws`). Trees and runs are shared
    by draws that share a seed (one store); each draw is assessed on its own trees only."""
    from .pipeline import CampaignConfig, tree_stage
    from .runs import make_tasks, run_all
    from .store import ResultStore

    from standin_planner.faults import Faults

    Faults.from_names(cfg.faults)
    specs = [s for s in FAULTS if s.name in cfg.faults]
    cfg.out.mkdir(parents=True, exist_ok=True)
    ccfg = CampaignConfig(out=cfg.out, seed=cfg.seed, mutations=cfg.mutations, max_nodes=cfg.nodes,
                          executor=cfg.executor, workers=cfg.workers, ray_address=cfg.ray_address,
                          progress=cfg.progress)
    draws = _chosen_seeds(_seed_dir(inputs, ccfg), cfg)
    tree_dir = tree_stage(cfg.out / "picked_seeds", ccfg)

    by_config: dict[str, list[Any]] = {}
    for fault in ("", *(s.name for s in specs)):
        by_config[fault] = make_tasks([tree_dir], faults=(fault,) if fault else (), seed=cfg.seed,
                                      time_limit=cfg.time_limit)
    # a fault that cannot act in a scenario (no cyclist, no yellow) would repeat the nominal run step for step:
    # not run, the nominal verdict stands for it
    inert = {t.scenario_path: _inert(t.scenario_path) for t in by_config[""]}
    for fault in by_config:
        if fault:
            by_config[fault] = [t for t in by_config[fault] if fault not in inert[t.scenario_path]]
    from ..analysis.features import elements_of_file

    stored: dict[str, Any] = {}

    def cats(tasks: Sequence[Any], trees: set[str]) -> dict[str, frozenset[str]]:
        # errors are not judged: a scenario the player could not run counts for neither side
        return {f"{t.tree}/{t.scenario_id}": frozenset(stored[t.key].categories) for t in tasks
                if t.tree in trees and t.key in stored and stored[t.key].verdict != "error"}

    def fault_cats(fault: str, trees: set[str]) -> dict[str, frozenset[str]]:
        # the nominal verdict stands for the runs skipped as inert
        skipped = {f"{t.tree}/{t.scenario_id}" for t in by_config[""] if fault in inert[t.scenario_path]}
        nominal = cats(by_config[""], trees)
        return {**{i: c for i, c in nominal.items() if i in skipped}, **cats(by_config[fault], trees)}

    results: list[DrawResult] = []
    report: list[dict[str, Any]] = []
    for k, seeds in enumerate(draws):
        trees = {p.stem for p in seeds}
        # draw by draw: each draw's rows are final (and printed, with `progress`) as soon as its own runs are in,
        # so a long study that is stopped still has its first draws; a later draw reuses shared trees' runs
        with ResultStore(cfg.out / "results.sqlite") as store:
            run_all([t for ts in by_config.values() for t in ts if t.tree in trees], store, executor=cfg.executor,
                    workers=cfg.workers, progress=cfg.progress, ray_address=cfg.ray_address)
            stored = {r.run_key: r for r in store.runs()}
        nominal = cats(by_config[""], trees)
        elements = {f"{t.tree}/{t.scenario_id}": elements_of_file(t.scenario_path) for t in by_config[""]
                    if t.tree in trees}
        tree_of = {f"{t.tree}/{t.scenario_id}": str(t.tree) for t in by_config[""] if t.tree in trees}
        rows, details = [], {}
        for spec in specs:
            row, lift = assess(spec, nominal, fault_cats(spec.name, trees), elements, trees=tree_of)
            rows.append(row)
            details[spec.name] = {"row": asdict(row), "why": spec.why, "right_triggers": list(spec.triggers),
                                  "lift": [asdict(r) for r in lift[:10]]}
        results.append(DrawResult(k, tuple(p.name for p in seeds), tuple(rows)))
        report.append({"draw": k, "scenarios": len(elements), "seeds": [p.name for p in seeds], "faults": details})
        if cfg.draws:
            print(f"[effectiveness] draw {k}: {results[-1].found}/{len(rows)} found, {results[-1].right_first}/"
                  f"{len(rows)} right trigger first ({len(elements)} scenarios)\n{format_table(rows)}",
                  file=sys.stderr, flush=True)
    head = {"time_limit": cfg.time_limit, "nodes": cfg.nodes}
    if cfg.draws:
        (cfg.out / "effectiveness.json").write_text(json.dumps(
            {**head, "draw_seed": cfg.draw_seed, "draws": report}, indent=1, sort_keys=True), encoding="utf-8")
        (cfg.out / "effectiveness.txt").write_text(
            "\n\n".join(f"draw {d.index}: {', '.join(d.seeds)}\n{format_table(d.rows)}" for d in results)
            + "\n\n" + format_draws(results) + "\n", encoding="utf-8")
    else:
        (cfg.out / "effectiveness.json").write_text(json.dumps({**head, **report[0]}, indent=1, sort_keys=True),
                                                    encoding="utf-8")
        (cfg.out / "effectiveness.txt").write_text(format_table(results[0].rows) + "\n", encoding="utf-8")
    return results
