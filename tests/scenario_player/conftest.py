"""Shared paths: the esmini conformance examples in ../shared (real third-party files)."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.paths import shared_dir

ESMINI = shared_dir() / "data" / "conformance" / "esmini"


@pytest.fixture(scope="session")
def esmini() -> Path:
    if not (ESMINI / "xosc").is_dir():
        pytest.skip("shared esmini conformance data not present")
    return ESMINI


def xosc(name: str) -> Path:
    return ESMINI / "xosc" / f"{name}.xosc"
