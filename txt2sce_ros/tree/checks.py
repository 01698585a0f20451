"""Sample checks of generated trees beyond the XSD validation done while writing: the ASAM quality checker
(5–13 ms a file, so a seeded sample) and loading in the scenario player (`scenario_player.syntax.load_scenario`)."""

from __future__ import annotations

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
