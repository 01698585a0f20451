"""Run a scenario in the reference player (esmini, headless) and compare it with ours.

esmini is an external program (`../shared/tools/esmini/esmini` and `dat2csv`, or the directory named by
`$TXT2SCE_ESMINI`). One run: `esmini --headless --osc FILE --fixed_timestep 0.05 --record sim.dat`, then
`dat2csv --extended` gives the CSV format `conformance.read_reference` reads. esmini marks problems in its log with
`[error]` (a scenario element it could not execute) and `[warn]`; a portable scenario logs no `[error]`.
"""

from __future__ import annotations

import os
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir

from .conformance import FileResult, run_file

STEP = 0.05              # s, the step the shared reference trajectories were recorded with
RUN_TIMEOUT = 120.0      # s of wall time for one esmini run (a 60 s scenario takes well under a second)


def esmini_dir() -> Path:
    """Directory holding the `esmini` and `dat2csv` executables ($TXT2SCE_ESMINI, else ../shared/tools/esmini)."""
    env = os.environ.get("TXT2SCE_ESMINI")
    return Path(env) if env else shared_dir() / "tools" / "esmini"


def available() -> bool:
    d = esmini_dir()
    return (d / "esmini").is_file() and (d / "dat2csv").is_file()


@dataclass(frozen=True)
class EsminiRun:
    """One esmini run of one file: its `[error]` lines, `[warn]` lines and the recorded trajectory CSV."""

    xosc: Path
    errors: tuple[str, ...]
    warnings: tuple[str, ...]
    csv: Path | None


def run_esmini(xosc: Path, out_dir: Path, *, dt: float = STEP) -> EsminiRun:
    """Run `xosc` in esmini (from the file's own directory, so relative map paths resolve as in our player) and
    convert the recording to `out_dir/<stem>.csv`. Raises InputError when esmini is not installed."""
    d = esmini_dir()
    if not available():
        raise InputError(f"esmini not found in {d} (set $TXT2SCE_ESMINI to the directory of esmini and dat2csv)",
                         source=str(xosc))
    out_dir.mkdir(parents=True, exist_ok=True)
    dat, log, csv = out_dir / f"{xosc.stem}.dat", out_dir / f"{xosc.stem}.log", out_dir / f"{xosc.stem}.csv"
    cmd = [str(d / "esmini"), "--headless", "--osc", str(xosc.resolve()), "--fixed_timestep", f"{dt:g}",
           "--record", str(dat.resolve()), "--logfile_path", str(log.resolve())]
    try:
        subprocess.run(cmd, cwd=xosc.resolve().parent, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       timeout=RUN_TIMEOUT, check=False)
    except subprocess.TimeoutExpired:
        return EsminiRun(xosc, (f"esmini did not finish within {RUN_TIMEOUT:g} s",), (), None)
    text = log.read_text(encoding="utf-8", errors="replace") if log.is_file() else ""
    errors = tuple(ln.strip() for ln in text.splitlines() if "[error]" in ln)
    warnings = tuple(ln.strip() for ln in text.splitlines() if "[warn]" in ln)
    if not dat.is_file():
        return EsminiRun(xosc, errors or ("esmini wrote no recording",), warnings, None)
    subprocess.run([str(d / "dat2csv"), str(dat), "--extended", "--precision", "4", "--csv", str(csv)],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=RUN_TIMEOUT, check=False)
    return EsminiRun(xosc, errors, warnings, csv if csv.is_file() else None)


@dataclass(frozen=True)
class CheckResult:
    """esmini's log verdict and our player's agreement with esmini's trajectory for one file."""

    run: EsminiRun
    compared: FileResult | None

    @property
    def worst_max(self) -> float:
        return self.compared.max if self.compared is not None and self.compared.ran else float("inf")

    def ok(self, target: float) -> bool:
        return not self.run.errors and self.worst_max < target


def check_file(xosc: Path, *, work: Path | None = None, dt: float = STEP) -> CheckResult:
    """Run `xosc` in esmini and in our player (storyboard driving every entity) and compare positions step by
    step (`conformance.compare`: per entity RMS and max over the times both recorded)."""
    with tempfile.TemporaryDirectory(prefix="txt2sce-esmini-") as tmp:
        run = run_esmini(xosc, work or Path(tmp), dt=dt)
        if run.csv is None:
            return CheckResult(run, None)
        compared, _ = run_file(xosc, run.csv, dt=dt)
        # The CSV lives in a temporary directory: keep the run's verdict, not the path.
        return CheckResult(EsminiRun(run.xosc, run.errors, run.warnings, run.csv if work else None), compared)
