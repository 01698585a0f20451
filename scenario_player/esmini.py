"""Run a scenario in the reference player (esmini, headless) and compare it with ours.

esmini is an external program (`../shared/tools/esmini/esmini` and `dat2csv`, or the directory named by
`$TXT2SCE_ESMINI`). One run: `esmini --headless --osc FILE --fixed_timestep 0.05 --record sim.dat`, then
`dat2csv --extended` gives the CSV format `conformance.read_reference` reads. esmini marks problems in its log with
`[error]` (a scenario element it could not execute) and `[warn]`; a portable scenario logs no `[error]`.
"""

from __future__ import annotations

import os
import re
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir

from .conformance import FileResult, run_file
from .simulation import Simulation, SimulationConfig
from .syntax.document import parse_xml
from .syntax.scenario import load_scenario

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


def run_esmini(xosc: Path, out_dir: Path, *, dt: float = STEP, cwd: Path | None = None) -> EsminiRun:
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
        subprocess.run(cmd, cwd=(cwd or xosc.resolve().parent), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
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


#: A light change: (time in s, OpenDRIVE signal id, state text).
Change = tuple[float, str, str]
_PROBE = "txt2sce_light_probe"
_PROBE_START = re.compile(r"^\[(\d+\.\d+)\] \[info\] " + _PROBE + r"_(\d+) standbyState -> startTransition")


@dataclass(frozen=True)
class LightCheck:
    """When each light changed state (after t = 0) in our player and in esmini, up to the end both ran to."""

    ours: tuple[Change, ...]
    esmini: tuple[Change, ...]
    errors: tuple[str, ...] = ()

    @property
    def agree(self) -> bool:
        return not self.errors and self.ours == self.esmini

    def first_difference(self) -> str:
        if self.errors:
            return self.errors[0]
        for a, b in zip(self.ours, self.esmini):
            if a != b:
                return f"light change ours {a[1]}={a[2]} at {a[0]:.2f} s, esmini {b[1]}={b[2]} at {b[0]:.2f} s"
        if len(self.ours) != len(self.esmini):
            longer, who = (self.ours, "ours") if len(self.ours) > len(self.esmini) else (self.esmini, "esmini")
            extra = longer[min(len(self.ours), len(self.esmini))]
            return f"light change {extra[1]}={extra[2]} at {extra[0]:.2f} s only in {who}"
        return ""


def signal_pairs(root: etree._Element) -> list[tuple[str, str]]:
    """Every (signal id, state) a TrafficSignalStateAction of the scenario sets, in document order, once each."""
    seen: dict[tuple[str, str], None] = {}
    for a in root.iter("TrafficSignalStateAction"):
        seen.setdefault((a.get("name", ""), a.get("state", "")), None)
    return list(seen)


def _probe_xml(root: etree._Element, pairs: list[tuple[str, str]], base: Path) -> bytes:
    """A copy of the scenario with a Story whose event k starts each time light k reaches its state (a rising
    TrafficSignalCondition): esmini logs those starts, so its log says when each light changed. The map path is
    made absolute so the copy runs from anywhere."""
    root = etree.fromstring(etree.tostring(root))
    logic = root.find("RoadNetwork/LogicFile")
    if logic is not None and not Path(logic.get("filepath", "")).is_absolute():
        logic.set("filepath", str((base / logic.get("filepath", "")).resolve()))
    decls = root.find("ParameterDeclarations")
    if decls is None:
        decls = etree.Element("ParameterDeclarations")
        root.find("FileHeader").addnext(decls)
    etree.SubElement(decls, "ParameterDeclaration", name=_PROBE, parameterType="integer", value="0")
    sb = root.find("Storyboard")
    story = etree.Element("Story", name=_PROBE)
    act = etree.SubElement(story, "Act", name=f"{_PROBE}_act")
    mg = etree.SubElement(act, "ManeuverGroup", name=f"{_PROBE}_mg", maximumExecutionCount="1")
    etree.SubElement(mg, "Actors", selectTriggeringEntities="false")
    man = etree.SubElement(mg, "Maneuver", name=f"{_PROBE}_maneuver")
    for k, (sid, state) in enumerate(pairs):
        ev = etree.SubElement(man, "Event", name=f"{_PROBE}_{k}", priority="parallel", maximumExecutionCount="10000")
        pa = etree.SubElement(etree.SubElement(etree.SubElement(ev, "Action", name=f"{_PROBE}_{k}_set"),
                                               "GlobalAction"), "ParameterAction", parameterRef=_PROBE)
        etree.SubElement(pa, "SetAction", value=str(k))
        cond = etree.SubElement(etree.SubElement(etree.SubElement(ev, "StartTrigger"), "ConditionGroup"), "Condition",
                                name=f"{_PROBE}_{k}_seen", delay="0", conditionEdge="rising")
        etree.SubElement(etree.SubElement(cond, "ByValueCondition"), "TrafficSignalCondition", name=sid, state=state)
    start = etree.SubElement(etree.SubElement(etree.SubElement(act, "StartTrigger"), "ConditionGroup"), "Condition",
                             name=f"{_PROBE}_start", delay="0", conditionEdge="none")
    # Started at t = 0 (before any story acts), so a change in the first step is a rising edge too.
    etree.SubElement(etree.SubElement(start, "ByValueCondition"), "SimulationTimeCondition", value="-1",
                     rule="greaterThan")
    stop = sb.find("StopTrigger")
    if stop is not None:
        stop.addprevious(story)
    else:
        sb.append(story)
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8")


def light_changes_ours(xosc: Path, *, dt: float = STEP, end: float | None = None) -> tuple[Change, ...]:
    """Our player's light changes (storyboard mode), stamped with the time whose triggers set them (esmini's
    convention: an action started at step time t has taken effect at t)."""
    cfg = SimulationConfig(dt=dt, ego_mode="storyboard", **({"time_limit": end} if end is not None else {}))
    sim = Simulation(load_scenario(xosc), cfg)
    sim.reset()
    before = dict(sim.world.signals.states)
    out: list[Change] = []
    while not sim.done:
        t = sim.world.t
        sim.advance(None)
        now = sim.world.signals.states
        if now != before:
            out.extend((round(t, 3), sid, st) for sid, st in sorted(now.items()) if before.get(sid) != st)
            before = dict(now)
    return tuple(out)


def check_lights(xosc: Path, work: Path, *, dt: float = STEP) -> LightCheck | None:
    """Run a probe copy of `xosc` in esmini (`_probe_xml`) and compare its light changes with ours; None for a
    scenario that sets no light."""
    root = parse_xml(xosc.read_bytes(), str(xosc))
    pairs = signal_pairs(root)
    if not pairs:
        return None
    work.mkdir(parents=True, exist_ok=True)
    probe = work / f"{xosc.stem}.{_PROBE}.xosc"
    probe.write_bytes(_probe_xml(root, pairs, xosc.resolve().parent))
    run = run_esmini(probe, work, dt=dt, cwd=xosc.resolve().parent)
    log = (work / f"{probe.stem}.log").read_text(encoding="utf-8", errors="replace") \
        if (work / f"{probe.stem}.log").is_file() else ""
    seen: list[Change] = []
    end = 0.0
    for line in log.splitlines():
        m = _PROBE_START.match(line)
        if m and float(m.group(1)) > 0.0:     # t = 0: the states Init sets, not changes
            seen.append((round(float(m.group(1)), 3), *pairs[int(m.group(2))]))
        stamp = re.match(r"^\[(\d+\.\d+)\]", line)
        if stamp:
            end = max(end, float(stamp.group(1)))
    ours = tuple(c for c in light_changes_ours(xosc, dt=dt) if c[0] <= end + 1e-9)
    theirs = tuple(sorted(seen, key=lambda c: (c[0], c[1])))
    return LightCheck(ours, theirs, run.errors)


@dataclass(frozen=True)
class CheckResult:
    """esmini's log verdict, our player's agreement with esmini's trajectory, and (for a scenario that sets lights)
    whether every light changed at the same time in both, for one file."""

    run: EsminiRun
    compared: FileResult | None
    lights: LightCheck | None = None

    @property
    def worst_max(self) -> float:
        return self.compared.max if self.compared is not None and self.compared.ran else float("inf")

    def ok(self, target: float) -> bool:
        return (not self.run.errors and self.worst_max < target
                and (self.lights is None or self.lights.agree))


def check_file(xosc: Path, *, work: Path | None = None, dt: float = STEP) -> CheckResult:
    """Run `xosc` in esmini and in our player (storyboard driving every entity) and compare positions step by
    step (`conformance.compare`: per entity RMS and max over the times both recorded) and light changes
    (`check_lights`)."""
    with tempfile.TemporaryDirectory(prefix="txt2sce-esmini-") as tmp:
        run = run_esmini(xosc, work or Path(tmp), dt=dt)
        if run.csv is None:
            return CheckResult(run, None)
        compared, _ = run_file(xosc, run.csv, dt=dt)
        lights = check_lights(xosc, (work or Path(tmp)) / "lights", dt=dt)
        # The CSV lives in a temporary directory: keep the run's verdict, not the path.
        return CheckResult(EsminiRun(run.xosc, run.errors, run.warnings, run.csv if work else None), compared, lights)
