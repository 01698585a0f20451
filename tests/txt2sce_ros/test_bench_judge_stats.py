"""`txt2sce bench judge`'s paired-overhead statistics: the quartiles are numpy's (linear interpolation)."""

from __future__ import annotations

import numpy as np
import pytest

from txt2sce_ros.bench.judge import _pct, _quantile


@pytest.mark.parametrize("values", [[1.0], [1.2, 1.0], [1.05, 0.9, 1.3, 1.1, 1.02], list(np.linspace(0.8, 1.4, 12))])
@pytest.mark.parametrize("q", [0.0, 0.25, 0.5, 0.75, 1.0])
def test_quantile_is_numpys_linear_quantile(values: list[float], q: float) -> None:
    assert _quantile(values, q) == pytest.approx(float(np.quantile(values, q)), abs=1e-12)


def test_percent_of_a_ratio() -> None:
    assert _pct(1.081) == "+8.1 %" and _pct(0.95) == "-5.0 %"
