"""One closed-loop run in-process: scenario player core <-> planner core, judged by the oracle core.

The same cores run behind the ROS nodes; this path has no DDS round trip, which is what lets a campaign run
thousands of scenarios on two cores. Faults are mapped to verdicts by who is at fault: a scenario that cannot be
loaded or a harness fault gives verdict *error*; only the oracle's categories give *fail*.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .contract import Frame, RunStatus, ScenarioEnvelope, Verdict
from .errors import Txt2SceError


@dataclass(frozen=True)
class RunRecord:
    """What a campaign stores of one run (JSON-serialisable through `to_dict`)."""

    scenario_id: str
    verdict: Verdict
    categories: tuple[str, ...] = ()
    end_reason: str = ""
    sim_time: float = 0.0
    wall_time: float = 0.0
    steps: int = 0
    details: dict[str, Any] = field(default_factory=dict)
    unsupported: tuple[str, ...] = ()
    error: str = ""

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["verdict"] = self.verdict.value
        d["categories"] = list(self.categories)
        d["unsupported"] = list(self.unsupported)
        return d


def run_closed_loop(scenario: str | Path | ScenarioEnvelope, *, scenario_id: str | None = None,
                    faults: tuple[str, ...] = (), seed: int = 0, dt: float | None = None,
                    time_limit: float | None = None, keep_trajectory: bool = False, on_frame: Callable[[Frame], None] | None = None,
                    ) -> tuple[RunRecord, dict[str, np.ndarray] | None]:
    """Run one scenario (a file, or an envelope carrying the scenario's and its map's text: what a campaign ships to
    a worker) against the stand-in planner (with `faults` switched on) and judge it.

    `on_frame` gets every frame the oracle judges, in order: the frames a recording of the same run over ROS holds
    (one per dt from t = 0, each once)."""
    from oracle_monitor import Oracle, OracleParams
    from scenario_player import Simulation, SimulationConfig, load_scenario
    from standin_planner import Faults, Planner, PlannerParams, friction_from_xosc

    envelope = scenario if isinstance(scenario, ScenarioEnvelope) else None
    sid = scenario_id or (envelope.id if envelope else Path(scenario).stem)
    t0 = time.perf_counter()
    try:
        if envelope is not None:
            # Messages name the driver's file (`meta['file']`) as a file-path run's would. Only catalogs are looked
            # up beside it (they are not shipped: on a cluster they must sit at the same path on every node).
            file = envelope.meta.get("file") or ""
            scen = load_scenario(envelope.xosc, source=file or envelope.id, map_text=envelope.map_xodr or None,
                                 map_path=envelope.map_path or None, base_dir=Path(file).parent if file else None)
            xosc_text = envelope.xosc
        else:
            scen = load_scenario(str(scenario))
            xosc_text = Path(scenario).read_text(encoding="utf-8")
        cfg_kwargs: dict[str, Any] = {"ego_mode": "planner", "seed": seed}
        if dt is not None:
            cfg_kwargs["dt"] = dt
        if time_limit is not None:
            cfg_kwargs["time_limit"] = time_limit
        sim = Simulation(scen, SimulationConfig(**cfg_kwargs))
        frame: Frame = sim.reset()
        # The planner node reads the road friction from the scenario envelope; do the same here so both paths agree.
        friction = friction_from_xosc(xosc_text)
        planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults.from_names(faults),
                          road_friction=friction)
        oracle = Oracle(sim.network, sim.goal, OracleParams.from_config())

        def observe(f: Frame) -> None:
            if on_frame is not None:
                on_frame(f)
            oracle.observe(f)

        observe(frame)
        steps = 0
        while not sim.done:
            cmd = planner.step(frame)
            nxt = sim.step(cmd)
            # A stop trigger ends the run at the start of a step: the last frame comes again with the same time.
            # The wire carries it once (receivers drop a repeated stamp), so the oracle sees it once here too.
            if nxt.t > frame.t:
                observe(nxt)
                steps += 1
            frame = nxt
        status: RunStatus = sim.status
        verdict = oracle.finish(status)
    except Txt2SceError as exc:
        return RunRecord(sid, Verdict.ERROR, error=str(exc), wall_time=time.perf_counter() - t0), None
    traj = sim.trajectory if keep_trajectory else None
    return RunRecord(
        scenario_id=sid, verdict=Verdict(verdict.verdict), categories=tuple(verdict.category_names()),
        end_reason=status.end_reason, sim_time=frame.t, wall_time=time.perf_counter() - t0, steps=steps,
        details=verdict.to_dict(), unsupported=tuple(sim.unsupported),
    ), traj
