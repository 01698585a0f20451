"""Shared fixtures of the scenario-tree tests: the hand-written seeds (docs/seed_format.md) and the tree config."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.tree.build import tree_config

FIXTURES = Path(__file__).parent / "fixtures"
JUNCTION = FIXTURES / "junction_left_turn_seed.xosc"
CUT_IN = FIXTURES / "highway_cut_in_seed.xosc"


@pytest.fixture
def cfg():
    return tree_config()


@pytest.fixture(scope="module")
def junction_bytes() -> bytes:
    return JUNCTION.read_bytes()
