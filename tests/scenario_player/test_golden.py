"""Behaviour frozen across code changes: the 18 esmini examples, in storyboard mode and driven by a fixed toy
policy in planner mode, give the same trajectories and frames as when `golden_digests.json` was recorded.

The digests were recorded before the player's speed-ups (commit 7f210da) and are of values rounded to 1e-6, so
another libm's last bits do not matter. A deliberate behaviour change re-records them:
`python -m scenario_player.fingerprint record /tmp/fp.json <esmini xosc dir>` and copy the `rounded` fields."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from scenario_player.fingerprint import digests

from .conftest import ESMINI

GOLDEN = json.loads((Path(__file__).with_name("golden_digests.json")).read_text())


def _strip(d: dict[str, object]) -> dict[str, object]:
    return {k: v for k, v in d.items() if k != "exact"}


@pytest.mark.parametrize("name", sorted({k.split("/")[0] for k in GOLDEN}))
def test_runs_match_the_recorded_digests(esmini, name: str) -> None:
    now = digests([esmini / "xosc" / f"{name}.xosc"])
    for key, value in now.items():
        assert _strip(value) == GOLDEN[key], key


def test_the_digest_sees_a_change(esmini) -> None:
    # A run one step shorter has another digest: the comparison is not vacuous.
    from scenario_player.fingerprint import run_digest

    full = run_digest(ESMINI / "xosc" / "cut-in.xosc", "storyboard")
    short = run_digest(ESMINI / "xosc" / "cut-in.xosc", "storyboard", time_limit=full.steps * 0.05 - 0.05)
    assert full.rounded != short.rounded and full.exact != short.exact
