"""The reliability catalogue (tests/reliability/cases.py): every case must end clean — bounded time and memory, the
documented exit status, a one-line message, no traceback, every good item kept. The runner's own classification is
tested first on commands that really crash, hang and hog memory, so a clean catalogue means something."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from .cases import cases
from .runner import Case, run_case
from .workspace import build

CASES = cases()
#: Cases run at once: most of a case is interpreter start-up and file I/O, so a little over the 2 cores pays.
JOBS = 3


def test_catalogue_covers_every_command_with_at_least_60_cases() -> None:
    assert len(CASES) >= 60
    assert len({c.name for c in CASES}) == len(CASES)
    commands = {c.name.split("-")[0] for c in CASES}
    for cmd in ("extract", "seed", "play", "maps", "conformance", "judge", "replay", "tree", "xosc",
                "eval", "fidelity", "campaign", "config"):
        assert cmd in commands, cmd


@pytest.fixture(scope="module")
def outcomes(tmp_path_factory) -> dict:
    from concurrent.futures import ThreadPoolExecutor

    root = tmp_path_factory.mktemp("reliability")
    ws = build(root / "workspace")
    with ThreadPoolExecutor(max_workers=JOBS) as pool:
        return {o.case: o for o in pool.map(lambda c: run_case(c, ws, root), CASES)}


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_case_is_clean(case: Case, outcomes: dict) -> None:
    o = outcomes[case.name]
    if case.expected_to_fail_until and o.kind != "clean":
        pytest.xfail(f"{case.expected_to_fail_until}: {o.kind} {o.detail}")
    assert o.kind == "clean", f"{o.kind}: {o.detail} (exit {o.exit}, {o.seconds:.1f} s, {o.max_rss_mb:.0f} MB)"


# -- the runner detects what it is meant to detect ----------------------------------------------------------------

def _py(code: str):
    return lambda ws, d: [sys.executable, "-c", code]


@pytest.mark.parametrize("code,kind", [
    ("raise ValueError('boom')", "crash"),
    ("import time; time.sleep(30)", "hang"),
    ("x = bytearray(4 * 2**30)", "hang"),              # past the address-space cap: MemoryError
    ("import os; os.kill(os.getpid(), 9)", "crash"),
    ("import sys; print('txt2sce x: error: bad thing'); sys.exit(2)", "clean"),
    ("import sys; print('txt2sce x: internal error: KeyError: 1', file=sys.stderr); sys.exit(2)", "crash"),
    ("import sys; sys.exit(0)", "crash"),           # wrong exit status for a case expecting 2
])
def test_runner_classifies_real_failures(tmp_path: Path, code: str, kind: str) -> None:
    case = Case(f"probe-{kind}", _py(code), exit=(2,), message=r"error", timeout=5.0)
    assert run_case(case, tmp_path, tmp_path).kind == kind


def test_runner_detects_a_lost_item(tmp_path: Path) -> None:
    case = Case("probe-loss", _py("import sys; print('error: one bad row'); sys.exit(2)"),
                kept=lambda ws, d, out: "" if (d / "good.txt").exists() else "good.txt lost")
    assert run_case(case, tmp_path, tmp_path).kind == "loss"
