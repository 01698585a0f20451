"""Checks of generated trees beyond the XSD validation done while writing: on every node, that the AV does not
start overlapping another entity (`StartOverlapCheck`, used by `build_tree`); on a seeded sample, the ASAM quality
checker (5–13 ms a file) and loading in the scenario player (`scenario_player.syntax.load_scenario`)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import Txt2SceError


@dataclass(frozen=True)
class SampleCheck:
    checked: int
    qc_failed: int
    player_failed: int
    player_available: bool
    problems: tuple[str, ...]


def sample_files(tree_dirs: list[Path], n: int, seed: int) -> list[Path]:
    files = sorted(f for d in tree_dirs for f in (d / "nodes").glob("n*.xosc"))
    if len(files) <= n:
        return files
    idx = np.random.default_rng(seed).choice(len(files), size=n, replace=False)
    return [files[int(i)] for i in sorted(idx)]


def check_sample(tree_dirs: list[Path], n: int, *, seed: int = 0) -> SampleCheck:
    """QC errors and player load failures over `n` generated files drawn with a seeded Generator."""
    from ..xosc.validate import qc_errors

    try:
        from scenario_player.syntax.scenario import load_scenario
    except ImportError:  # the player is another package; without it only QC is checked
        load_scenario = None
    files = sample_files(tree_dirs, n, seed)
    qc_bad = player_bad = 0
    problems: list[str] = []
    for f in files:
        errs = qc_errors(f)
        if errs:
            qc_bad += 1
            problems.append(f"QC {f}: {errs[0]}")
        if load_scenario is not None:
            try:
                load_scenario(f)
            except (Txt2SceError, ValueError, KeyError) as exc:
                player_bad += 1
                problems.append(f"player {f}: {exc}")
    return SampleCheck(checked=len(files), qc_failed=qc_bad, player_failed=player_bad,
                       player_available=load_scenario is not None, problems=tuple(problems[:10]))


#: The Init's private actions (positions, speeds, routes): what decides where the entities stand at t=0.
_PRIVATE_INIT = re.compile(r"<Init>.*?</Init>", re.S)
_PRIVATE = re.compile(r"<Private\b.*?</Private>", re.S)


class StartOverlapCheck:
    """Whether an assembled node starts with the AV overlapping another entity: the closed loop would end every
    run of it as an invalid scenario (the oracle's `overlap_at_start`), so it is no test of the planner. Mutations
    of initial positions (the AV's start state and approach start, a party placed close at the start, a new party)
    are made per block, and a combination of two can land two footprints on one spot. The player's own first
    frame is judged with the oracle's footprints, once per distinct set of initial private actions (most versions
    leave them alone, so a tree of 150 nodes needs a handful of loads). Without the player or the oracle (other
    packages) no node is refused."""

    def __init__(self, base_dir: Path) -> None:
        self.base_dir = base_dir
        self._seen: dict[int, str] = {}
        try:
            from oracle_monitor.geometry import footprint, overlaps
            from scenario_player import Simulation, SimulationConfig, load_scenario
        except ImportError:
            self._tools = None
        else:
            self._tools = (footprint, overlaps, Simulation, SimulationConfig, load_scenario)

    def problem(self, text: str, source: str) -> str:
        """'' when the node starts with every entity clear of the AV, else why not."""
        if self._tools is None:
            return ""
        init = _PRIVATE_INIT.search(text)
        key = hash(tuple(_PRIVATE.findall(init.group(0)))) if init else hash(text)
        if key not in self._seen:
            self._seen[key] = self._judge(text, source)
        return self._seen[key]

    def _judge(self, text: str, source: str) -> str:
        footprint, overlaps, Simulation, SimulationConfig, load_scenario = self._tools
        try:
            sim = Simulation(load_scenario(text, source=source, base_dir=self.base_dir),
                             SimulationConfig(ego_mode="storyboard"))
            frame = sim.reset()
        except (Txt2SceError, ValueError, KeyError):
            return ""       # what the player cannot load is reported by the sample check and the runs themselves
        ego = footprint(frame.ego)
        hit = [o.name for o in frame.objects if overlaps(ego, footprint(o))]   # the oracle's contact test
        return f"entities overlap at t=0 (ego and {', '.join(hit)}): an invalid scenario" if hit else ""
