"""`txt2sce bench extract` runs on dev.jsonl and prints every loop beside its baselines (no speed is asserted:
figures come from the bench itself)."""

from __future__ import annotations

import argparse

import pytest

from txt2sce_ros.bench import extract as bench


def test_bench_prints_extractor_batch_and_baselines(capsys: pytest.CaptureFixture[str]) -> None:
    assert bench.run(argparse.Namespace(quick=True)) == 0
    out = capsys.readouterr().out
    for loop in ("regex pass (baseline)", "schema validation (baseline)", "offline extractor",
                 "extract + validate (batch)"):
        assert any(line.startswith(loop) for line in out.splitlines()), (loop, out)
    assert "per CPU second" in out and "180 reports" in out
