"""The good fixtures every catalogue case starts from, built once from the real shared data: a few real narratives
and hand-labelled sketches, the seeds built from them, a recorded run of one seed, the esmini maps and scenarios.
Each case then damages a copy of one of them in its own directory."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from txt2sce_ros.paths import shared_dir

N_REPORTS = 3


def data_dir() -> Path:
    return shared_dir() / "data"


def esmini(kind: str, name: str = "") -> Path:
    return data_dir() / "conformance" / "esmini" / kind / name


def _rows(path: Path, n: int) -> list[str]:
    lines = [ln for ln in path.read_text(encoding="utf-8").splitlines() if ln.strip()]
    return lines[:n]


def build(ws: Path) -> Path:
    """Create the workspace in `ws` (idempotent: a finished workspace has `.done`)."""
    if (ws / ".done").exists():
        return ws
    ws.mkdir(parents=True, exist_ok=True)
    reports = data_dir() / "reports"
    (ws / "reports.jsonl").write_text("\n".join(_rows(reports / "dev.jsonl", N_REPORTS)) + "\n", encoding="utf-8")
    gold = _rows(reports / "dev_gold.jsonl", 8)
    (ws / "sketches.jsonl").write_text("\n".join(gold[:N_REPORTS]) + "\n", encoding="utf-8")
    _seeds(ws)
    _bag(ws)
    (ws / ".done").touch()
    return ws


def _seeds(ws: Path) -> None:
    from txt2sce_ros.seed import write_seeds
    from txt2sce_ros.sketch import load_sketches

    manifest = write_seeds(load_sketches(ws / "sketches.jsonl"), ws / "seeds")
    if len(manifest["built"]) < 2:
        raise RuntimeError(f"catalogue workspace: only {len(manifest['built'])} seeds built")


def good_seed(ws: Path) -> Path:
    manifest = json.loads((ws / "seeds" / "manifest.json").read_text(encoding="utf-8"))
    return ws / "seeds" / manifest["built"][0]["file"]


def seed_ids(ws: Path) -> list[str]:
    manifest = json.loads((ws / "seeds" / "manifest.json").read_text(encoding="utf-8"))
    return [b["report_id"] for b in manifest["built"]]


def _bag(ws: Path) -> None:
    """One closed-loop run of the first seed, recorded as the monitor records it."""
    from oracle_monitor.runwriter import RunWriter
    from txt2sce_ros.closed_loop import run_closed_loop
    from txt2sce_ros.contract import RunStatus, ScenarioEnvelope

    seed = good_seed(ws)
    frames = []
    record, _ = run_closed_loop(seed, on_frame=frames.append)
    env = ScenarioEnvelope(id=seed.stem, xosc=seed.read_text(encoding="utf-8"))
    with RunWriter(ws / "bags" / "good", time_base_ns=1_700_000_000_000_000_000) as w:
        w.begin(env, None)
        for f in frames:
            w.frame(f)
        w.end(RunStatus(seed.stem, "finished", record.sim_time, record.end_reason))


def copy_bag(ws: Path, dest: Path) -> Path:
    shutil.copytree(ws / "bags" / "good", dest)
    return dest


def mcap_of(bag: Path) -> Path:
    return next(bag.glob("*.mcap"))
