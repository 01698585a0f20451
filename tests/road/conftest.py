"""Shared fixtures of the road-model tests: esmini's third-party maps and reference trajectories."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.road import RoadNetwork, load_network

ESMINI = shared_dir() / "data" / "conformance" / "esmini"
XODR = ESMINI / "xodr"


def esmini_map(name: str) -> RoadNetwork:
    return load_network(XODR / f"{name}.xodr")


@pytest.fixture(scope="session")
def esmini_dir() -> Path:
    if not XODR.is_dir():
        pytest.skip(f"shared esmini data not found at {ESMINI}")
    return ESMINI
