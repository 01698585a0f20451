"""`txt2sce bench maps`: road-model speed on esmini's multi_intersections.xodr (63 roads, 5 junctions).

1. Load + map-database build, wall time (target < 1 s), beside the bare lxml parse of the same file.
2. (x, y) -> lane lookup throughput on 100k random points in the map's extent (target >= 100k points/s), beside a
   naive per-point nearest search (numpy argmin over every lane-centre sample) on a 1k sample.
3. LanePath.position / project per call, the player's and planner's inner loop.
"""

from __future__ import annotations

import argparse
import inspect
import statistics
import time
from pathlib import Path

import numpy as np

from ..paths import shared_dir

DESCRIPTION = "road model: load + map database of multi_intersections.xodr, (x, y) -> lane throughput"

MAP_NAME = "multi_intersections.xodr"


def _map_path() -> Path:
    return shared_dir() / "data" / "conformance" / "esmini" / "xodr" / MAP_NAME


def _timed(fn, repeat: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def _build_database(net):  # noqa: ANN001, ANN202 - the map database's types belong to txt2sce_ros.mapdb
    try:
        from ..mapdb import build_map_database  # lazy: written by the map-database owner
    except ImportError as exc:
        return None, f"not available ({exc})"
    kwargs = {}
    params = inspect.signature(build_map_database).parameters
    if "use_cache" in params:       # measure a cold build, not a disk-cache hit
        kwargs["use_cache"] = False
    elif "cache" in params:
        kwargs["cache"] = False
    return (lambda: build_map_database(net, **kwargs)), ""


def run(args: argparse.Namespace) -> int:
    from ..road import LanePath, RoadNetwork
    from ..road.lookup import LaneIndex

    path = _map_path()
    data = path.read_bytes()
    repeat = 3 if args.quick else 5
    print(f"bench maps: {path.name} ({len(data) / 1e3:.0f} kB), median of {repeat} runs, seed {args.seed}")

    # 1. load + database build
    from lxml import etree

    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False)
    t_xml, _ = _timed(lambda: etree.fromstring(data, parser), repeat)
    t_load, net = _timed(lambda: RoadNetwork(data, str(path)), repeat)
    t_index, _ = _timed(lambda: LaneIndex(net, ("driving",)), repeat)
    t_graph, _ = _timed(lambda: __import__("txt2sce_ros.road.topology", fromlist=["x"]).build_routing_graph(
        RoadNetwork(data, str(path))), repeat)
    build, why = _build_database(net)
    print("\n1. load + map database (target < 1 s)")
    print(f"   baseline: lxml parse only                 {t_xml * 1e3:8.1f} ms")
    print(f"   load_network (parse + records + signals)  {t_load * 1e3:8.1f} ms")
    print(f"   lane spatial index (driving lanes)        {t_index * 1e3:8.1f} ms")
    print(f"   load + lane routing graph                 {t_graph * 1e3:8.1f} ms")
    if build is None:
        print(f"   map database build                        {why}")
    else:
        def load_and_build():  # noqa: ANN202
            fresh = RoadNetwork(data, str(path))
            fn, _ = _build_database(fresh)
            return fn()

        t_db, _ = _timed(load_and_build, repeat)
        verdict = "meets" if t_db < 1.0 else "MISSES"
        print(f"   load + build_map_database                 {t_db * 1e3:8.1f} ms  ({verdict} target, "
              f"{t_db / t_xml:.0f}x the bare XML parse)")

    # 2. lookup throughput
    n = 10_000 if args.quick else 100_000
    rng = np.random.default_rng(args.seed)
    idx = net.lane_index(("driving",))
    lo, hi = idx.tree.mins, idx.tree.maxes
    xs = rng.uniform(lo[0], hi[0], n)
    ys = rng.uniform(lo[1], hi[1], n)
    net.world_to_lane(xs[:100], ys[:100])      # warm-up (index already built)
    t_q, match = _timed(lambda: net.world_to_lane(xs, ys), max(1, repeat - 2))
    rate = n / t_q
    m = 1000
    pts = idx.tree.data
    t0 = time.perf_counter()
    naive = np.empty(m, dtype=np.int64)
    for i in range(m):
        naive[i] = int(np.argmin((pts[:, 0] - xs[i]) ** 2 + (pts[:, 1] - ys[i]) ** 2))
    t_naive = time.perf_counter() - t0
    naive_rate = m / t_naive
    print(f"\n2. (x, y) -> lane, {n:,} random points in the map extent, {len(pts):,} lane-centre samples "
          f"(target >= 100k points/s)")
    print(f"   baseline: naive per-point nearest sample (1k points)  {naive_rate:12,.0f} points/s")
    print(f"   world_to_lane (cKDTree + exact projection)            {rate:12,.0f} points/s "
          f"({rate / naive_rate:.0f}x baseline; {'meets' if rate >= 1e5 else 'MISSES'} target)")
    print(f"   points inside a driving lane: {100 * float(np.mean(match.inside)):.1f}%")
    pick = rng.integers(0, len(pts), n)
    nx_ = pts[pick, 0] + rng.uniform(-2.0, 2.0, n)
    ny_ = pts[pick, 1] + rng.uniform(-2.0, 2.0, n)
    t_near, near = _timed(lambda: net.world_to_lane(nx_, ny_), max(1, repeat - 2))
    print(f"   world_to_lane, {n:,} points within 2 m of lane centres   {n / t_near:12,.0f} points/s "
          f"({100 * float(np.mean(near.inside)):.1f}% inside a driving lane)")
    on_lane = np.flatnonzero(match.inside)[:2000]
    t0 = time.perf_counter()
    for i in on_lane:
        net.locate(float(xs[i]), float(ys[i]), float(match.heading[i]))
    t_loc = (time.perf_counter() - t0) / max(len(on_lane), 1)
    print(f"   locate(x, y, heading), scalar, points on lanes         {t_loc * 1e6:12.1f} us/call")

    # 3. LanePath inner loop
    g = net.routing_graph
    start = max(g.nodes, key=lambda r: nx_reach(g, r))
    far = list(_bfs_path(g, start))
    lp = LanePath.from_lanes(net, far)
    k = 2_000 if args.quick else 20_000
    ss = rng.uniform(0, lp.length, k)
    t0 = time.perf_counter()
    for s in ss:
        lp.position(float(s), 0.5)
    t_pos = (time.perf_counter() - t0) / k
    probe = lp.positions(ss, 0.7)
    t0 = time.perf_counter()
    for (x, y, _), s in zip(probe, ss):
        lp.project(float(x), float(y), s_hint=float(s))
    t_proj = (time.perf_counter() - t0) / k
    t0 = time.perf_counter()
    lp.positions(ss, 0.5)
    t_vec = (time.perf_counter() - t0) / k
    print(f"\n3. LanePath over {len(lp.lanes)} lanes, {lp.length:.0f} m")
    print(f"   position(s, offset)      {t_pos * 1e6:7.2f} us/call")
    print(f"   positions(array)         {t_vec * 1e6:7.2f} us/point")
    print(f"   project(x, y, s_hint)    {t_proj * 1e6:7.2f} us/call")
    return 0


def nx_reach(g, ref) -> int:  # noqa: ANN001
    """Number of lanes reachable by following lanes from `ref` (to pick a long path for the benchmark)."""
    return len(list(_bfs_path(g, ref)))


def _bfs_path(g, start):  # noqa: ANN001, ANN202
    """A simple non-repeating chain of 'follow' edges from `start` (first successor each time)."""
    seen = {start}
    cur = start
    yield cur
    while True:
        nxt = [v for _, v, d in g.out_edges(cur, data=True) if d["kind"] == "follow" and v not in seen]
        if not nxt:
            return
        cur = sorted(nxt)[0]
        seen.add(cur)
        yield cur
