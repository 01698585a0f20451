"""`txt2sce mapdb`: regenerate the bundled maps, show a map's database, query it the way road matching does."""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from ..errors import InputError
from ..paths import BUNDLED_MAPS

from .argtypes import count

HELP = "map database: build-maps (regenerate bundled .xodr), show FILE (summary), query FILE (road matching)"

_LAYOUTS = ["straight", "curve", "junction4", "junction3", "roundabout", "parking", "junction"]
_JUNCTION_LAYOUTS = {"junction4", "junction3", "roundabout", "junction"}


def register(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="mapdb_command", metavar="ACTION", required=True)
    b = sub.add_parser("build-maps", help="regenerate the bundled maps deterministically and validate them (XSD)")
    b.add_argument("--out", type=Path, default=None, help=f"output directory (default {BUNDLED_MAPS})")
    b.add_argument("--check", action="store_true",
                   help="write nothing; exit 1 if a committed bundled map differs from what the generator makes")

    s = sub.add_parser("show", help="print the map database summary of an OpenDRIVE file")
    s.add_argument("file", help="an .xodr path, or the name of a bundled map (e.g. junction4_signal.xodr)")
    s.add_argument("--no-cache", action="store_true", help="rebuild instead of reading the disk cache")
    s.add_argument("--json", action="store_true", help="print the graph as node-link JSON instead")

    q = sub.add_parser("query", help="list the segments or junction approaches that match road constraints",
                       description="Examples:\n  txt2sce mapdb query junction4_signal.xodr --layout junction4 "
                                   "--lanes 2 --control signal --turn left\n  txt2sce mapdb query straight_3x3.xodr "
                                   "--layout straight --lanes 3 --two-way --need bike_lane --need parking_lane",
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    q.add_argument("file", help="an .xodr path, or the name of a bundled map")
    q.add_argument("--layout", choices=_LAYOUTS, default=None)
    q.add_argument("--lanes", type=count(), default=None, help="at least this many driving lanes in the direction")
    q.add_argument("--control", choices=["signal", "stop_sign", "none"], default=None, help="junction approaches")
    way = q.add_mutually_exclusive_group()
    way.add_argument("--one-way", dest="one_way", action="store_const", const=True, default=None)
    way.add_argument("--two-way", dest="one_way", action="store_const", const=False)
    q.add_argument("--turn", action="append", default=[], choices=["straight", "left", "right", "uturn"],
                   help="a turn the approach must offer (repeatable)")
    q.add_argument("--need", action="append", default=[],
                   help="a required feature (repeatable): road needs such as left_neighbour, oncoming, bike_lane, "
                        "parking_lane; approach needs such as dedicated_left, left_with_left_neighbour")
    q.add_argument("--no-cache", action="store_true")


def _resolve(name: str) -> Path:
    p = Path(name)
    if p.is_file():
        return p
    bundled = BUNDLED_MAPS / name
    if bundled.is_file():
        return bundled
    raise InputError("no such map file (nor a bundled map of that name)", source=name)


def run(args: argparse.Namespace) -> int:
    if args.mapdb_command == "build-maps":
        return _build_maps(args)
    from ..mapdb import load_map_database

    path = _resolve(args.file)
    t0 = time.perf_counter()
    db = load_map_database(path, cache=not args.no_cache)
    elapsed = time.perf_counter() - t0
    if args.mapdb_command == "show":
        if args.json:
            print(json.dumps(db.to_json(), indent=1, sort_keys=True))
            return 0
        print(db.summary())
        print(f"  ({'cache hit' if db.from_cache else 'built'} in {elapsed * 1000:.1f} ms)")
        for note in db.notes:
            print(f"  note: {note}")
        return 0
    return _query(db, args)


def _build_maps(args: argparse.Namespace) -> int:
    from ..mapdb.bundled import BUNDLED, build_bundled_maps, render
    from ..mapdb.xsd import validation_errors

    if args.check:
        stale = [n for n in BUNDLED if not (BUNDLED_MAPS / n).is_file() or (BUNDLED_MAPS / n).read_bytes() != render(n)]
        for name in stale:
            print(f"differs from the generator: {BUNDLED_MAPS / name}")
        print("bundled maps up to date" if not stale else "run `txt2sce mapdb build-maps` to regenerate")
        return 1 if stale else 0
    failed = 0
    for path in build_bundled_maps(args.out):
        errors = validation_errors(path)
        failed += bool(errors)
        status = "XSD-valid (OpenDRIVE 1.7)" if not errors else f"INVALID: {errors[0]}"
        print(f"{path}  {path.stat().st_size:>7} bytes  {status}")
    return 1 if failed else 0


def _query(db, args: argparse.Namespace) -> int:  # noqa: ANN001 - MapDatabase, imported lazily
    road_needs = [n for n in args.need if n not in {"dedicated_left", "left_with_left_neighbour",
                                                    "right_with_right_neighbour", "two_way"}]
    if args.layout in _JUNCTION_LAYOUTS or args.control or args.turn:
        if road_needs:
            raise InputError(f"road needs {road_needs} do not apply to junction approaches", element="--need")
        count = 0
        for info in db.junctions(args.layout, control=args.control, min_lanes=args.lanes, one_way=args.one_way,
                                 turns=args.turn, needs=args.need):
            print(f"junction {info.id} {info.name!r}: {info.layout.value}, {info.legs} legs, control "
                  f"{info.control.value}")
            for app in db.approaches(info.id, control=args.control, min_lanes=args.lanes, one_way=args.one_way,
                                     turns=args.turn, needs=args.need):
                count += 1
                lanes = ", ".join(f"lane {ln.lane_id}: {'/'.join(sorted(t.value for t in ln.turns)) or '-'}"
                                  for ln in app.lanes)
                print(f"  approach road {app.road_id} ({app.control.value}, heading {app.heading:+.2f} rad): {lanes}")
        print(f"{count} matching approaches")
        return 0 if count else 1
    matches = db.roads(args.layout, min_lanes=args.lanes, one_way=args.one_way, needs=args.need)
    for m in matches:
        print(f"road {m.road_id} {m.segment.name!r} {'+s' if m.forward else '-s'}: lanes {list(m.lanes)} "
              f"(left to right), oncoming {list(m.oncoming)}, right side {'+'.join(m.right_side) or '-'}, "
              f"[{','.join(sorted(t.value for t in m.segment.layouts))}]")
    print(f"{len(matches)} matching road directions")
    return 0 if matches else 1
