from __future__ import annotations

import pytest

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches

DEV_GOLD = shared_dir() / "data" / "reports" / "dev_gold.jsonl"


@pytest.fixture(scope="session")
def gold() -> dict[str, Sketch]:
    if not DEV_GOLD.is_file():
        pytest.skip(f"shared data missing: {DEV_GOLD}")
    return {s.report_id: s for s in load_sketches(DEV_GOLD) if isinstance(s, Sketch)}


@pytest.fixture(scope="session")
def buildable(gold) -> list[Sketch]:
    return [s for s in gold.values() if not s.missing]
