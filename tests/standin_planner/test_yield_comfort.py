"""A crossing party seen early enough is yielded to within the comfort band: the demo's r271 seed (the AV goes
straight through a junction that a car crossing from its left reaches at about the same time) used to brake at
emergency jerk for the junction entry (Smooth) because the 5 s prediction saw the car too late."""

from __future__ import annotations

import pytest

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches

pytest.importorskip("scenario_player")

from txt2sce_ros.closed_loop import run_closed_loop  # noqa: E402
from txt2sce_ros.seed import generate_seed  # noqa: E402

DEV_GOLD = shared_dir() / "data" / "reports" / "dev_gold.jsonl"


def test_the_crossing_car_is_yielded_to_smoothly(tmp_path) -> None:
    if not DEV_GOLD.is_file():
        pytest.skip(f"shared data missing: {DEV_GOLD}")
    sketch = next(s for s in load_sketches(DEV_GOLD) if isinstance(s, Sketch)
                  and s.report_id == "dmvca-waymo-20220118-r271")
    path = tmp_path / "r271.xosc"
    path.write_bytes(generate_seed(sketch, seed=0).xosc)
    speeds: list[float] = []
    record, _ = run_closed_loop(path, on_frame=lambda f: speeds.append(f.ego.speed))
    assert min(speeds[20:]) < 0.5 * speeds[0]          # it did give way (slowed to under half its start speed)
    assert record.verdict.value == "pass", record.details.get("categories")
