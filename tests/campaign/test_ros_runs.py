"""`--ros`: each run goes through the node graph (own ROS domain per worker), judged from its recorded bag; the
verdicts agree with the in-process closed loop on the same scenarios."""

from __future__ import annotations

import os
from pathlib import Path

from txt2sce_ros.campaign.pipeline import CampaignConfig, run_campaign
from txt2sce_ros.campaign.store import ResultStore
from txt2sce_ros.closed_loop import run_closed_loop

#: two short seeds (the first 8 dev-gold sketches): one passes in ~10 s simulated, one is a start failure
SHORT = ("dmvca-apple-20211111-r241", "dmvca-apple-20190919-r70")


def test_ros_campaign_matches_in_process_verdicts(seed_dir: Path, tmp_path: Path) -> None:
    files = [seed_dir / f"{name}.xosc" for name in SHORT]
    cfg = CampaignConfig(out=tmp_path / "ros", ros=True, executor="pool", workers=2, progress=False,
                         report=False)
    summary = run_campaign(files, cfg)
    assert summary.runs is not None and summary.runs.ran == 2
    with ResultStore(tmp_path / "ros" / "results.sqlite") as store:
        stored = {r.scenario_id: r for r in store.runs()}
    for f in files:
        rec, _ = run_closed_loop(f)
        over_ros = stored[f.stem]
        assert over_ros.verdict != "error", over_ros.record["error"]
        assert (over_ros.verdict, over_ros.categories) == (rec.verdict.value, rec.categories)
        assert abs(over_ros.record["sim_time"] - rec.sim_time) < 0.2


def test_a_whole_run_has_one_frame_per_step_from_zero() -> None:
    from txt2sce_ros.campaign.ros_runs import expected_frames

    assert expected_frames(0.0) == 1
    assert expected_frames(40.05) == 802            # t = 0, 0.05, ..., 40.05 at the player's dt
    assert expected_frames(6.45) == 130
    assert expected_frames(2.3, dt=0.1) == 24       # 2.3 / 0.1 = 22.999...: rounded, not truncated


def test_concurrent_holders_never_share_a_domain() -> None:
    from txt2sce_ros.campaign.ros_runs import reserved_domain

    tag = f"test:{os.getpid()}"
    with reserved_domain(tag) as a, reserved_domain(tag) as b, reserved_domain(tag) as c:
        assert len({a, b, c}) == 3 and all(1 <= d <= 100 for d in (a, b, c))
    with reserved_domain(tag) as again:             # released on exit: the first id is free again
        assert again == a
