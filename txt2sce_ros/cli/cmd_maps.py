"""`txt2sce maps`: inspect OpenDRIVE maps and check the road model against esmini's reference trajectories.

  txt2sce maps check DIR --reference DIR   load every map in DIR, then per reference CSV the share of rows whose
                                           (roadId, s, t) and (roadId, laneId, s, offset) give esmini's (x, y)
                                           within 5 cm
  txt2sce maps info FILE                   roads, junctions, lanes, signals and extent of one map
  txt2sce maps locate FILE X Y [--heading] the lane under a world point
"""

from __future__ import annotations

import argparse
import math
import time
from collections import Counter
from pathlib import Path

import numpy as np

from ..errors import InputError, Txt2SceError

from .argtypes import number, COORD, POSITIVE

HELP = "inspect OpenDRIVE maps (info, locate) and check the road model against esmini (check)"


def register(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="maps_command", metavar="SUBCOMMAND")
    chk = sub.add_parser("check", help="load every map in DIR and compare road/lane coordinates with esmini CSVs",
                         description="Loads every *.xodr in DIR, then for every CSV in --reference compares "
                                     "(roadId, s, t) -> (x, y) and (roadId, laneId, s, offset) -> (x, y) with "
                                     "esmini's x, y. The map of each CSV is the one its scenario (in --scenarios, "
                                     "default: the xosc folder beside --reference) names in RoadNetwork/LogicFile.")
    chk.add_argument("dir", type=Path, help="folder of OpenDRIVE maps")
    chk.add_argument("--reference", type=Path, required=True, help="folder of esmini reference CSVs")
    chk.add_argument("--scenarios", type=Path, default=None, help="folder of the scenarios (.xosc) of the CSVs")
    chk.add_argument("--tol", type=POSITIVE, default=0.05, help="tolerance in metres (default 0.05)")
    chk.add_argument("--min-share", type=number(ge=0.0, le=1.0), default=0.99,
                     help="exit status 1 if a file's share is below this (default 0.99)")
    info = sub.add_parser("info", help="summarise one OpenDRIVE map")
    info.add_argument("file", type=Path)
    loc = sub.add_parser("locate", help="the lane under a world point")
    loc.add_argument("file", type=Path)
    loc.add_argument("x", type=COORD)
    loc.add_argument("y", type=COORD)
    loc.add_argument("--heading", type=COORD, default=None, help="prefer lanes driving this way (radians)")
    loc.add_argument("--all-types", action="store_true", help="consider every lane type, not only driving")


def run(args: argparse.Namespace) -> int:
    cmd = getattr(args, "maps_command", None)
    if cmd == "check":
        return _check(args)
    if cmd == "info":
        return _info(args)
    if cmd == "locate":
        return _locate(args)
    print("usage: txt2sce maps {check,info,locate} ... (see txt2sce maps --help)")
    return 1


def _check(args: argparse.Namespace) -> int:
    from ..road import load_network
    from ..road.conformance import check_reference

    maps = sorted(Path(args.dir).glob("*.xodr"))
    if not maps:
        raise InputError("no *.xodr files", source=str(args.dir))
    print(f"Loading {len(maps)} maps from {args.dir}")
    failed = 0
    for p in maps:
        t0 = time.perf_counter()
        try:
            net = load_network(p)
            print(f"  ok    {p.name:36s} {len(net.roads):4d} roads {len(net.junctions):3d} junctions "
                  f"{time.perf_counter() - t0:6.3f} s")
        except Txt2SceError as exc:
            failed += 1
            print(f"  FAIL  {p.name:36s} {exc}")
    print(f"\nesmini reference rows within {args.tol * 100:.0f} cm (rows with roadId -1 are off-road and skipped)")
    head = (f"{'reference':34s} {'map':30s} {'rows':>6s} {'skip':>5s} {'(road,s,t)':>11s} {'(lane,s,off)':>13s} "
            f"{'max err m':>10s} {'inverse':>8s}")
    print(head)
    print("-" * len(head))
    results = check_reference(args.dir, args.reference, args.scenarios, tol=args.tol)
    low = 0
    tot = Counter()
    for r in results:
        if r.error:
            low += 1
            print(f"{r.name:34s} FAIL  {r.error}")
            continue
        worst = max(r.road_max_err, r.lane_max_err)
        print(f"{r.name:34s} {r.map_name:30s} {r.rows:6d} {r.skipped:5d} {100 * r.road_share:10.2f}% "
              f"{100 * r.lane_share:12.2f}% {worst:10.4f} {100 * r.inverse_share:7.2f}%")
        low += min(r.road_share, r.lane_share) < args.min_share
        tot.update(rows=r.rows, road=r.road_ok, lane=r.lane_ok, inv=r.inverse_ok, skip=r.skipped)
    print("-" * len(head))
    n = max(tot["rows"], 1)
    print(f"{'all':34s} {'':30s} {tot['rows']:6d} {tot['skip']:5d} {100 * tot['road'] / n:10.2f}% "
          f"{100 * tot['lane'] / n:12.2f}% {'':10s} {100 * tot['inv'] / n:7.2f}%")
    print("inverse = (x, y) -> same road with s, t within tolerance (informative: where junction roads overlap, "
          "another road is an equally valid answer)")
    if failed or low:
        print(f"{failed} map(s) failed to load, {low} file(s) below {100 * args.min_share:.0f}%")
        return 1
    return 0


def _info(args: argparse.Namespace) -> int:
    from ..road import load_network

    t0 = time.perf_counter()
    net = load_network(args.file)
    dt = time.perf_counter() - t0
    types: Counter[str] = Counter()
    for road in net.roads.values():
        for sec in road.sections:
            types.update(ln.type for i, ln in sec.lanes.items() if i != 0)
    pts = np.vstack([net.lane_index(None).tree.data])
    rules = Counter(r.rule for r in net.roads.values())
    total = sum(r.length for r in net.roads.values())
    print(f"{args.file} (OpenDRIVE {net.header.get('revMajor', '?')}.{net.header.get('revMinor', '?')}), "
          f"loaded in {dt:.3f} s")
    print(f"  roads: {len(net.roads)} ({sum(r.in_junction for r in net.roads.values())} in junctions), "
          f"total length {total:.1f} m, traffic rule {dict(rules)}")
    print(f"  junctions: {len(net.junctions)}, connections "
          f"{sum(len(j.connections) for j in net.junctions.values())}")
    print(f"  lanes (per section): {dict(types.most_common())}")
    lights = [s for s in net.signals.values() if s.is_traffic_light]
    print(f"  signals: {len(net.signals)} ({len(lights)} dynamic), controllers: {len(net.controllers)}")
    g = net.routing_graph
    print(f"  routing graph: {g.number_of_nodes()} lanes, {g.number_of_edges()} edges")
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    print(f"  extent: x [{lo[0]:.1f}, {hi[0]:.1f}], y [{lo[1]:.1f}, {hi[1]:.1f}]")
    return 0


def _locate(args: argparse.Namespace) -> int:
    from ..road import load_network

    net = load_network(args.file)
    p = net.locate(args.x, args.y, args.heading, lane_types=None if args.all_types else ("driving",))
    if p is None:
        print("no lane")
        return 1
    print(f"road {p.road_id} section {p.ref.section} lane {p.lane_id} ({net.lane_type(p.road_id, p.lane_id, p.s)})"
          f": s={p.s:.3f} t={p.t:.3f} offset={p.offset:.3f} heading={math.degrees(p.heading):.1f} deg "
          f"distance={p.distance:.3f} inside={p.inside}")
    return 0
