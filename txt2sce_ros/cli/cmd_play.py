"""`txt2sce play FILE.xosc [--csv OUT] [--ego-mode storyboard]`: run one scenario in batch (no ROS) and print the
result. In planner mode (default) with no planner attached the ego holds its initial speed and heading, which is
enough to smoke-test a seed; `--ego-mode storyboard` lets the storyboard drive the ego too (conformance runs)."""

from __future__ import annotations

import argparse
import csv
import time
from pathlib import Path

HELP = "run one OpenSCENARIO file in the batch player and print its result (optionally write a CSV trajectory)"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", type=Path, help="the .xosc scenario")
    parser.add_argument("--csv", type=Path, help="write the trajectory: time,name,x,y,heading,speed per entity")
    parser.add_argument("--ego-mode", choices=("planner", "storyboard"), default="planner",
                        help="who drives the ego (default planner: no planner here, it keeps speed and heading)")
    parser.add_argument("--time-limit", type=float, help="s of simulation time (default: config/player.yaml)")
    parser.add_argument("--dt", type=float, default=0.05, help="step in s (default 0.05)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--map", type=Path, help="OpenDRIVE file to use instead of RoadNetwork/LogicFile")


def run(args: argparse.Namespace) -> int:
    from scenario_player import Simulation, SimulationConfig, load_scenario

    scenario = load_scenario(args.file, map_path=str(args.map) if args.map else None)
    config = SimulationConfig.from_config(dt=args.dt, ego_mode=args.ego_mode, seed=args.seed,
                                          time_limit=args.time_limit, scenario_id=args.file.stem)
    sim = Simulation(scenario, config)
    t0 = time.perf_counter()
    status = sim.run()
    wall = time.perf_counter() - t0
    traj = sim.trajectory
    print(f"scenario   {args.file}")
    print(f"map        {scenario.map_path}")
    print(f"entities   {', '.join(scenario.entity_names)} (ego: {sim.ego_name}, driven by {args.ego_mode})")
    if sim.goal is not None:
        print(f"goal       x={sim.goal.x:.2f} y={sim.goal.y:.2f} tolerance {sim.goal.tolerance:g} m")
    print(f"finished   t={status.t:.2f} s, end reason: {status.end_reason or '-'}"
          f"{', verdict hint: ' + status.verdict_hint if status.verdict_hint else ''}")
    print(f"speed      {status.t / wall if wall > 0 else float('inf'):.0f}x real time ({wall * 1000:.1f} ms wall)")
    for name, rows in traj.items():
        last = rows[-1]
        print(f"  {name:20s} rows {len(rows):5d}  final x={last[1]:9.2f} y={last[2]:9.2f} "
              f"heading={last[3]:6.3f} speed={last[4]:6.2f}")
    for note in status.unsupported:
        print(f"  {note}")
    if args.csv:
        args.csv.parent.mkdir(parents=True, exist_ok=True)
        with open(args.csv, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(["time", "name", "x", "y", "heading", "speed"])
            rows_all = sorted(((r[0], n, r) for n, rows in traj.items() for r in rows), key=lambda x: (x[0], x[1]))
            for t, n, r in rows_all:
                w.writerow([f"{t:.4f}", n, f"{r[1]:.4f}", f"{r[2]:.4f}", f"{r[3]:.4f}", f"{r[4]:.4f}"])
        print(f"wrote {args.csv}")
    return 0
