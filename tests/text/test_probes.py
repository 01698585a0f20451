"""Every wording of every probe (`tests/text/probes.py`) reads as wanted: a rule change that loses a wording shows
here even when no narrative of the gold sets uses it."""

from __future__ import annotations

import pytest

from .probes import PROBES, Probe, run


@pytest.mark.parametrize("probe", PROBES, ids=[p.name for p in PROBES])
def test_every_wording_reads_as_wanted(probe: Probe) -> None:
    assert run(probe) == []
