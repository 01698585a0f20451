"""`txt2sce bench judge`'s paired-overhead statistics: overheads are printed as signed percentages of a ratio."""

from __future__ import annotations

from txt2sce_ros.bench.judge import _pct


def test_percent_of_a_ratio() -> None:
    assert _pct(1.081) == "+8.1 %" and _pct(0.95) == "-5.0 %"
