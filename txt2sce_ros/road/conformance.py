"""Geometry conformance against esmini's reference trajectories.

esmini logs, per entity and step, its world pose and its road coordinates (roadId, laneId, s, t, offset). For every
row that places the entity on a road (roadId != -1) we recompute (x, y) twice — from (roadId, s, t) and from
(roadId, laneId, s, offset) — and count the rows within tolerance. A third, informative figure runs the inverse:
(x, y) -> (road, s, t) with `world_to_lane`, which can legitimately pick another road where junction roads overlap.

What the comparison established about esmini's conventions (all 17,620 on-road rows agree within 5 cm):
- `offset` is measured from the lane centre toward +t of the road whatever the lane's side or driving direction
  (a car in lane -1 with offset +3.07 sits at t = +1.535, in lane 1's area); `t` includes laneOffset.
- Rows keep the lane esmini assigned (a lane change in progress reports the old lane with a growing offset), so the
  inverse lookup may name the neighbour lane for the same point.
- The largest residuals (2.8 cm on soderleden's paramPoly3 curves, 2.4 cm on curves_elevation's clothoids) are for
  entities far off the lane centre on curves: esmini derives s from its own polyline approximation of the road,
  so its s is a few centimetres off the exact projection there; elevation plays no part (x, y are 2D).
- No row has roadId -1 in the shipped references; such rows (entities off any road) would be skipped and counted.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from lxml import etree

from ..errors import InputError
from ..xmlsafe import refuse_doctype
from .network import RoadNetwork, load_network

TOLERANCE_M = 0.05
_REQUIRED = ("x", "y", "roadId", "laneId", "offset", "t", "s")


@dataclass(frozen=True, slots=True)
class FileConformance:
    """Agreement of one reference CSV with the road model."""

    name: str                 # reference CSV stem (= scenario name)
    map_name: str
    rows: int                 # rows that place an entity on a road
    skipped: int              # rows with roadId -1 (entity off any road)
    road_ok: int              # (roadId, s, t) -> (x, y) within tolerance
    lane_ok: int              # (roadId, laneId, s, offset) -> (x, y) within tolerance
    inverse_ok: int           # (x, y) -> same road with s and t within tolerance
    road_max_err: float
    lane_max_err: float
    error: str = ""           # the map or reference could not be read: nothing was compared

    @property
    def road_share(self) -> float:
        return self.road_ok / self.rows if self.rows else 1.0

    @property
    def lane_share(self) -> float:
        return self.lane_ok / self.rows if self.rows else 1.0

    @property
    def inverse_share(self) -> float:
        return self.inverse_ok / self.rows if self.rows else 1.0


def scenario_map(xosc: Path, xodr_dir: Path) -> Path:
    """The OpenDRIVE file a scenario names in RoadNetwork/LogicFile, looked up by file name in `xodr_dir`
    (falling back to the path relative to the scenario)."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False, load_dtd=False)
    try:
        refuse_doctype(xosc.read_bytes(), str(xosc))
        root = etree.parse(str(xosc), parser).getroot()
    except (OSError, etree.XMLSyntaxError) as exc:
        raise InputError(f"cannot read scenario: {exc}", source=str(xosc)) from exc
    el = root.find("RoadNetwork/LogicFile")
    if el is None or not el.get("filepath"):
        raise InputError("scenario names no map", source=str(xosc), element="RoadNetwork/LogicFile")
    rel = el.get("filepath", "")
    by_name = xodr_dir / Path(rel).name
    if by_name.is_file():
        return by_name
    relative = (xosc.parent / rel).resolve()
    if relative.is_file():
        return relative
    raise InputError(f"map {rel!r} not found in {xodr_dir}", source=str(xosc), element="LogicFile")


def _read_rows(path: Path) -> dict[str, np.ndarray]:
    try:
        with open(path, newline="", encoding="utf-8") as fh:
            reader = csv.DictReader(fh, skipinitialspace=True)
            fields = [f.strip() for f in (reader.fieldnames or [])]
            missing = [c for c in _REQUIRED if c not in fields]
            if missing:
                raise InputError(f"missing columns {missing}", source=str(path))
            rows = [{k.strip(): v.strip() for k, v in r.items() if k} for r in reader]
    except OSError as exc:
        raise InputError(f"cannot read reference: {exc.strerror}", source=str(path)) from exc
    try:
        return {
            "x": np.array([float(r["x"]) for r in rows]), "y": np.array([float(r["y"]) for r in rows]),
            "road": np.array([r["roadId"] for r in rows], dtype=object),
            "lane": np.array([int(float(r["laneId"])) for r in rows]),
            "s": np.array([float(r["s"]) for r in rows]), "t": np.array([float(r["t"]) for r in rows]),
            "offset": np.array([float(r["offset"]) for r in rows]),
        }
    except ValueError as exc:
        raise InputError(f"non-numeric value: {exc}", source=str(path)) from exc


def check_file(net: RoadNetwork, reference: Path, *, tol: float = TOLERANCE_M) -> FileConformance:
    data = _read_rows(reference)
    on_road = data["road"] != "-1"
    idx = np.flatnonzero(on_road)
    road_err = np.full(len(idx), np.inf)
    lane_err = np.full(len(idx), np.inf)
    # Grouped by (road, lane) so each group is one vectorised evaluation; a group that spans lane sections is
    # evaluated per section, as the lane id may mean a different lane in each.
    keys = {}
    for j, i in enumerate(idx):
        keys.setdefault(str(data["road"][i]), []).append(j)
    for rid, js in keys.items():
        js_arr = np.array(js)
        rows = idx[js_arr]
        if rid not in net.roads:
            continue
        x, y, _ = net.road_to_world_array(rid, data["s"][rows], data["t"][rows])
        road_err[js_arr] = np.hypot(x - data["x"][rows], y - data["y"][rows])
        for j, i in zip(js_arr, rows):
            try:
                lx, ly, _ = net.lane_to_world(rid, int(data["lane"][i]), float(data["s"][i]), float(data["offset"][i]))
            except InputError:
                continue
            lane_err[j] = math.hypot(lx - data["x"][i], ly - data["y"][i])
    inv_ok = 0
    if len(idx):
        m = net.world_to_lane(data["x"][idx], data["y"][idx], lane_types=None)
        inv_ok = int(np.sum((m.road_id == data["road"][idx]) & (np.abs(m.s - data["s"][idx]) < tol)
                            & (np.abs(m.t - data["t"][idx]) < tol)))
    finite = lambda a: float(np.max(a[np.isfinite(a)])) if np.any(np.isfinite(a)) else math.inf  # noqa: E731
    return FileConformance(
        name=reference.stem, map_name=Path(net.source).name, rows=len(idx), skipped=int(np.sum(~on_road)),
        road_ok=int(np.sum(road_err < tol)), lane_ok=int(np.sum(lane_err < tol)), inverse_ok=inv_ok,
        road_max_err=finite(road_err), lane_max_err=finite(lane_err))


def check_reference(xodr_dir: str | Path, reference_dir: str | Path, scenario_dir: str | Path | None = None,
                    *, tol: float = TOLERANCE_M) -> list[FileConformance]:
    """Check every `*.csv` in `reference_dir` against its scenario's map (scenarios default to the `xosc`
    folder beside `reference_dir`)."""
    xodr_dir, reference_dir = Path(xodr_dir), Path(reference_dir)
    scen_dir = Path(scenario_dir) if scenario_dir else reference_dir.parent / "xosc"
    csvs = sorted(reference_dir.glob("*.csv"))
    if not csvs:
        raise InputError("no reference CSV files", source=str(reference_dir))
    out = []
    for ref in csvs:
        xosc = scen_dir / f"{ref.stem}.xosc"
        if not xosc.is_file():
            raise InputError(f"no scenario {xosc.name} for reference {ref.name}", source=str(scen_dir))
        try:
            out.append(check_file(load_network(scenario_map(xosc, xodr_dir)), ref, tol=tol))
        except InputError as exc:
            # One unreadable map or reference is that file's failure; the other files are still checked.
            out.append(FileConformance(ref.stem, "", 0, 0, 0, 0, 0, math.inf, math.inf, error=str(exc)))
    return out
