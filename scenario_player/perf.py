"""Where the in-process closed loop spends its time: a measuring tool, not part of a run.

`python -m scenario_player.perf DIR [--repeat N]` runs every .xosc of DIR as `txt2sce_ros.closed_loop` does
(player core <-> stand-in planner core, oracle core observing; no faults, seed 0) and prints:

- runs/s of the whole loop (CPU seconds of this process, which a shared machine does not inflate, and wall);
- the CPU split: scenario load, player (Simulation set-up, steps and frames), planner (set-up and steps),
  oracle (set-up, observe, finish), and the rest (the loop itself and the timers);
- the player alone: the planner's commands of each run are recorded once and replayed through fresh
  Simulations (best of 3), so the player's µs per step are measured without the planner's noise.

The planner and the oracle are imported here only, lazily: the player core does not depend on them.
"""

from __future__ import annotations

import argparse
import time
from dataclasses import dataclass
from pathlib import Path

from txt2sce_ros.contract import ControlCommand

from .simulation import Simulation, SimulationConfig
from .syntax.scenario import Scenario, load_scenario


@dataclass(frozen=True, slots=True)
class LoopSplit:
    """CPU seconds per part of the closed loop over `runs` runs of `steps` steps in all."""

    runs: int
    steps: int
    total: float
    wall: float
    load: float
    player: float
    planner: float
    oracle: float

    @property
    def rest(self) -> float:
        return self.total - self.load - self.player - self.planner - self.oracle


def closed_loop_split(files: list[Path], repeat: int = 1) -> LoopSplit:
    """Run the files `repeat` times through the in-process closed loop, timing each part with the process clock."""
    from oracle_monitor import Oracle, OracleParams
    from standin_planner import Faults, Planner, PlannerParams

    clock = time.process_time
    load = player = planner_t = oracle_t = 0.0
    steps = 0
    w0, t0 = time.perf_counter(), clock()
    for _ in range(repeat):
        for path in files:
            a = clock()
            scen = load_scenario(str(path))
            b = clock()
            sim = Simulation(scen, SimulationConfig(ego_mode="planner", seed=0))
            frame = sim.reset()
            c = clock()
            planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults.from_names(()))
            d = clock()
            oracle = Oracle(sim.network, sim.goal, OracleParams.from_config())
            oracle.observe(frame)
            e = clock()
            load += b - a
            player += c - b
            planner_t += d - c
            oracle_t += e - d
            while not sim.done:
                t1 = clock()
                cmd = planner.step(frame)
                t2 = clock()
                frame = sim.step(cmd)
                t3 = clock()
                oracle.observe(frame)
                t4 = clock()
                planner_t += t2 - t1
                player += t3 - t2
                oracle_t += t4 - t3
                steps += 1
            a = clock()
            oracle.finish(sim.status)
            oracle_t += clock() - a
    return LoopSplit(len(files) * repeat, steps, clock() - t0, time.perf_counter() - w0, load, player, planner_t,
                     oracle_t)


def record_commands(files: list[Path]) -> list[tuple[Scenario, list[ControlCommand]]]:
    """Each file's scenario and the stand-in planner's commands of its closed-loop run."""
    from standin_planner import Faults, Planner, PlannerParams

    out = []
    for path in files:
        scen = load_scenario(str(path))
        sim = Simulation(scen, SimulationConfig(ego_mode="planner", seed=0))
        frame = sim.reset()
        planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults.from_names(()))
        cmds = []
        while not sim.done:
            cmd = planner.step(frame)
            cmds.append(cmd)
            frame = sim.step(cmd)
        out.append((scen, cmds))
    return out


def replay_player(runs: list[tuple[Scenario, list[ControlCommand]]], repeat: int = 3) -> tuple[float, int]:
    """Best CPU seconds over `repeat` passes of replaying the commands through fresh Simulations (set-up, steps
    and frames), and the number of steps of one pass."""
    steps = sum(len(cmds) for _, cmds in runs)
    best = float("inf")
    for _ in range(repeat):
        t0 = time.process_time()
        for scen, cmds in runs:
            sim = Simulation(scen, SimulationConfig(ego_mode="planner", seed=0))
            sim.reset()
            for cmd in cmds:
                sim.step(cmd)
        best = min(best, time.process_time() - t0)
    return best, steps


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m scenario_player.perf", description=__doc__.split("\n")[0])
    ap.add_argument("dir", type=Path, help="directory of .xosc files (e.g. the output of `txt2sce seed`)")
    ap.add_argument("--repeat", type=int, default=2, help="passes over the files for the loop split")
    args = ap.parse_args(argv)
    files = sorted(args.dir.glob("*.xosc"))
    if not files:
        print(f"no .xosc files in {args.dir}")
        return 2
    closed_loop_split(files[:3])        # warm the per-map caches (lane tracks, routes) outside the figures
    sp = closed_loop_split(files, args.repeat)
    print(f"closed loop: {sp.runs} runs, {sp.steps} steps: {sp.runs / sp.total:.2f} runs/s CPU "
          f"({sp.total:.2f} s), {sp.runs / sp.wall:.2f} runs/s wall")
    for name in ("load", "player", "planner", "oracle", "rest"):
        v = getattr(sp, name)
        print(f"  {name:8s} {v:7.2f} s CPU  {100 * v / sp.total:5.1f} %  {1e6 * v / sp.steps:7.1f} us/step")
    runs = record_commands(files)
    best, steps = replay_player(runs)
    print(f"player alone (replayed commands, best of 3): {steps} steps in {best:.3f} s CPU = "
          f"{1e6 * best / steps:.1f} us/step, {len(runs) / best:.0f} runs/s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
