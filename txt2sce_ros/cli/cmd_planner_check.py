"""`txt2sce planner-check`: run the stand-in planner in closed loop (scenario player + planner + oracle, in-process)
on a set of scenarios and print a table of runs, goals reached and oracle violations.

Default set: the benign scenarios shipped in `examples/scenarios/benign_*.xosc` (no conflicting party: the nominal
planner must reach every goal with no violation). `--faults` switches fault modes on; `--scenarios` takes files or
directories (e.g. generated seeds); `--strip-npcs` runs each of them with every party and obstacle removed (the
benign variant of a generated seed: same map, route, signals and weather, no conflicting party):

    txt2sce seed ../shared/data/reports/dev_gold.jsonl --out seeds
    txt2sce planner-check --scenarios seeds --strip-npcs
"""

from __future__ import annotations

import argparse
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from ..errors import Txt2SceError
from ..paths import REPO_ROOT
from ..xosc.schema import safe_parser

from .argtypes import count, TIME_LIMIT

HELP = "run the stand-in planner on benign scenarios; print runs, goals reached and oracle violations"

#: The benign check scenarios written by examples/scenarios/build.py.
DEFAULT_DIR = REPO_ROOT / "examples" / "scenarios"


@dataclass(frozen=True, slots=True)
class CheckRun:
    """One closed-loop run as the check reports it."""

    scenario: str
    verdict: str                      # pass | fail | error
    goal_reached: bool
    end_reason: str
    categories: tuple[str, ...]
    sim_time: float
    wall_time: float
    summary: str
    min_gap: float                    # closest the ego's footprint came to any other footprint (m), inf if alone


def run_scenario(path: str | Path, *, faults: tuple[str, ...] = (), seed: int = 0,
                 time_limit: float | None = None) -> CheckRun:
    """One closed-loop run of the planner on `path` judged by the oracle; an unloadable scenario is an error run."""
    from oracle_monitor import Oracle, OracleParams
    from scenario_player import Simulation, SimulationConfig, load_scenario
    from standin_planner import Faults, Planner, PlannerParams, friction_from_xosc

    name = Path(path).stem
    t0 = time.perf_counter()
    try:
        text = Path(path).read_text(encoding="utf-8")
        scenario = load_scenario(str(path))
        sim = Simulation(scenario, SimulationConfig.from_config(ego_mode="planner", seed=seed, time_limit=time_limit,
                                                                scenario_id=name))
        frame = sim.reset()
        # The stack's road-condition input: the scenario's environment, as the planner node reads it.
        planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults.from_names(faults),
                          road_friction=friction_from_xosc(text, source=str(path)))
        oracle = Oracle(sim.network, sim.goal, OracleParams.from_config(), scenario_id=name)
        oracle.observe(frame)
        min_gap = float("inf")
        while not sim.done:
            frame = sim.step(planner.step(frame))
            oracle.observe(frame)
            min_gap = min(min_gap, _min_gap(frame))
        status = sim.status
        verdict = oracle.finish(status)
    except Txt2SceError as exc:
        return CheckRun(name, "error", False, "", (), 0.0, time.perf_counter() - t0, f"error: {exc}", float("inf"))
    return CheckRun(name, verdict.verdict.value, status.end_reason == "goal_reached", status.end_reason,
                    tuple(verdict.category_names()), frame.t, time.perf_counter() - t0, verdict.summary(), min_gap)


def _min_gap(frame) -> float:
    """Smallest centre-to-centre distance minus the two half-diagonals' lower bound (half widths): a cheap,
    conservative closeness measure for the table (the oracle does the exact collision check)."""
    import math

    e = frame.ego
    ex = e.x + e.center_x * math.cos(e.heading)
    ey = e.y + e.center_x * math.sin(e.heading)
    best = float("inf")
    for o in frame.objects:
        ox = o.x + o.center_x * math.cos(o.heading)
        oy = o.y + o.center_x * math.sin(o.heading)
        d = math.hypot(ox - ex, oy - ey) - 0.5 * (e.length + o.length)
        best = min(best, d)
    return best




def strip_npcs(path: Path, out_dir: Path, ego: str = "ego") -> Path:
    """Write the benign variant of scenario `path` into `out_dir`: every entity but the ego removed with its Init
    actions, stories and stop conditions; the map reference made absolute so the copy loads from anywhere."""
    try:
        tree = etree.parse(str(path), safe_parser())
    except (OSError, etree.XMLSyntaxError) as exc:
        raise Txt2SceError(f"cannot read scenario: {exc}", source=str(path)) from exc
    root = tree.getroot()
    gone = {o.get("name") for o in root.iterfind("Entities/ScenarioObject") if o.get("name") != ego}
    for obj in root.iterfind("Entities/ScenarioObject"):
        if obj.get("name") in gone:
            obj.getparent().remove(obj)
    for priv in root.iterfind("Storyboard/Init/Actions/Private"):
        if priv.get("entityRef") in gone:
            priv.getparent().remove(priv)

    def mentions_gone(el: etree._Element) -> bool:
        return any(ref.get("entityRef") in gone for ref in el.iter("EntityRef")) or any(
            v in gone for node in el.iter() for k, v in node.attrib.items() if k in ("entityRef", "masterEntityRef"))

    for story in root.iterfind("Storyboard/Story"):
        if mentions_gone(story):
            story.getparent().remove(story)
    for group in root.iterfind("Storyboard/StopTrigger/ConditionGroup"):
        if mentions_gone(group):
            group.getparent().remove(group)
    logic = root.find("RoadNetwork/LogicFile")
    if logic is not None and logic.get("filepath") and not Path(logic.get("filepath")).is_absolute():
        logic.set("filepath", str((path.parent / logic.get("filepath")).resolve()))
    target = out_dir / path.name
    tree.write(str(target), xml_declaration=True, encoding="UTF-8")
    return target


def scenario_files(inputs: list[str] | None, pattern: str = "benign_*.xosc") -> list[Path]:
    """Files named on the command line (directories expanded to their .xosc files), else the benign set."""
    if not inputs:
        return sorted(DEFAULT_DIR.glob(pattern))
    out: list[Path] = []
    for item in inputs:
        p = Path(item)
        if p.is_dir():
            out.extend(sorted(p.rglob("*.xosc")))
        elif p.is_file():
            out.append(p)
        else:
            raise Txt2SceError("no such scenario file or directory", source=item)
    return out


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--scenarios", nargs="*", metavar="PATH",
                        help=f"scenario files or directories (default: {DEFAULT_DIR}/benign_*.xosc)")
    from standin_planner.faults import Faults

    parser.add_argument("--faults", default="", help="comma-separated fault modes to switch on (default: none): "
                                                     f"{', '.join(Faults.names())}")
    parser.add_argument("--seed", type=count(ge=0), default=0, help="simulation seed (default 0)")
    parser.add_argument("--time-limit", type=TIME_LIMIT, default=None, help="override the runs' time limit (s)")
    parser.add_argument("--fault-matrix", action="store_true",
                        help="run each fault_<mode>.xosc of the shipped set with its fault off and on; print both")
    parser.add_argument("--strip-npcs", action="store_true",
                        help="run the benign variant of each scenario (all parties and obstacles removed)")


def fault_matrix() -> int:
    """Each fault mode on the scenario built to expose it: nominal vs faulty verdicts side by side."""
    from standin_planner import Faults

    print(f"{'fault mode':<26}  {'nominal':<28}  {'with the fault':<40}")
    ok = 0
    for name in Faults.names():
        path = DEFAULT_DIR / f"fault_{name}.xosc"
        if not path.exists():
            print(f"{name:<26}  (no scenario {path.name})")
            continue
        nominal, faulty = run_scenario(path), run_scenario(path, faults=(name,))
        cell_n = f"{nominal.verdict} {'goal' if nominal.goal_reached else 'no goal'} {','.join(nominal.categories)}"
        cell_f = f"{faulty.verdict} {faulty.end_reason} {','.join(faulty.categories)}"
        shown = bool(set(faulty.categories) - set(nominal.categories))
        ok += shown and nominal.goal_reached and "Collisions" not in nominal.categories
        print(f"{name:<26}  {cell_n:<28}  {cell_f:<40}")
    print(f"fault modes whose behaviour shows only with the fault on: {ok}/{len(Faults.names())}")
    return 0 if ok == len(Faults.names()) else 1


def run(args: argparse.Namespace) -> int:
    from standin_planner import Faults

    if args.fault_matrix:
        return fault_matrix()

    faults = tuple(f for f in args.faults.split(",") if f.strip())
    Faults.from_names(faults)                     # an unknown name is the user's error, not an error run
    files = scenario_files(args.scenarios)
    if not files:
        raise Txt2SceError("no scenarios to run", source=str(DEFAULT_DIR))
    with tempfile.TemporaryDirectory(prefix="planner_check_") as tmp:
        if args.strip_npcs:
            files = [strip_npcs(f, Path(tmp)) for f in files]
        rows = [run_scenario(f, faults=faults, seed=args.seed, time_limit=args.time_limit) for f in files]
    width = max(len(r.scenario) for r in rows)
    print(f"planner-check: {len(rows)} runs, faults: {', '.join(faults) or 'none (nominal)'}")
    print(f"{'scenario':<{width}}  {'verdict':<7}  {'goal':<4}  {'end':<14}  {'t_sim':>6}  {'wall':>5}  violations")
    for r in rows:
        viol = ", ".join(r.categories) if r.categories else ("-" if r.verdict == "pass" else r.summary)
        print(f"{r.scenario:<{width}}  {r.verdict:<7}  {'yes' if r.goal_reached else 'no':<4}  {r.end_reason:<14}  "
              f"{r.sim_time:6.1f}  {r.wall_time:5.2f}  {viol}")
    goals = sum(r.goal_reached for r in rows)
    violated = sum(bool(r.categories) for r in rows)
    errors = sum(r.verdict == "error" for r in rows)
    print(f"runs {len(rows)}  goals reached {goals}/{len(rows)}  runs with violations {violated}  errors {errors}")
    return 0 if goals == len(rows) and violated == 0 and errors == 0 else 1
