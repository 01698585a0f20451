"""The bundled OpenDRIVE maps, generated from code so every coordinate follows from a few design numbers.

One map per sketch layout (`../shared/spec/sketch.md`): a long straight two-way road with bike and parking lanes,
a one-way street, a curve (clothoid-arc-clothoid both ways), a signalised 4-way junction with left-turn lanes, a
stop-controlled T junction, an all-way-stop 4-way junction of a one-way and a two-way street, a single-lane
roundabout and a parking aisle. Right-hand traffic throughout; lanes with
negative ids drive along +s. `txt2sce mapdb build-maps` rewrites them; the output is byte-for-byte deterministic.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Callable

from ..paths import BUNDLED_MAPS
from .odr_builder import (BROKEN_WHITE, NO_MARK, SOLID_WHITE, SOLID_YELLOW_DOUBLE, Arc, ConnectionSpec,
                          ControllerSpec, Hermite, JunctionSpec, LaneSpec, Line, MapSpec, Pose, RoadLink, RoadMark,
                          RoadSpec, SignalSpec, Spiral, connector, lane_border_t, to_xml)

DRIVING_W = 3.5
BIKE_W = 1.8
PARKING_W = 2.5
STALL_W = 5.0  # perpendicular parking stalls in a lot
SIDEWALK_W = 2.0
RING_W = 4.5

# Signal codes. The lights carry the OpenDRIVE standard's own catalogue (country "OpenDRIVE"): esmini resolves a
# TrafficSignalStateAction's name to a light by that country's codes (a country-DE light is "no matching traffic
# signal" there, an [error]), so only these lights take the signal phases in both players. Signs stay German.
LIGHT_COUNTRY = "OpenDRIVE"
TRAFFIC_LIGHT = "1000001"  # three-light signal (red, yellow, green lamps)
ARROW_LIGHT = "1000011"    # arrow signal, three lamps; subtype 10 = left
STOP_SIGN = "206"
YIELD_SIGN = "205"


def _side(sign: int, kinds: list[tuple[str, float, RoadMark]], *, linked: bool = False) -> tuple[LaneSpec, ...]:
    """Lanes of one side, inner to outer, from (type, width, outer mark) triples."""
    return tuple(LaneSpec(sign * (k + 1), typ, width, mark,
                          predecessor=sign * (k + 1) if linked else None,
                          successor=sign * (k + 1) if linked else None)
                 for k, (typ, width, mark) in enumerate(kinds))


def _unit(phi: float) -> tuple[float, float]:
    return math.cos(phi), math.sin(phi)


# --------------------------------------------------------------------------------------------- single roads


def straight_map() -> MapSpec:
    """(a) 500 m straight two-way road: 3 driving lanes, a bike lane, a parking lane and a sidewalk each way."""
    side = [("driving", DRIVING_W, BROKEN_WHITE), ("driving", DRIVING_W, BROKEN_WHITE),
            ("driving", DRIVING_W, SOLID_WHITE), ("biking", BIKE_W, SOLID_WHITE), ("parking", PARKING_W, NO_MARK),
            ("sidewalk", SIDEWALK_W, NO_MARK)]
    road = RoadSpec("1", "main_street", Pose(0.0, 0.0, 0.0), (Line(500.0),), left=_side(1, side),
                    right=_side(-1, side), center_mark=SOLID_YELLOW_DOUBLE)
    return MapSpec("txt2sce_straight", (road,), description="straight two-way road, 3+3 lanes, bike and parking lanes")


def one_way_map() -> MapSpec:
    """(b) 400 m one-way street: 2 driving lanes along +s, parking on the right, sidewalks on both sides."""
    right = _side(-1, [("driving", DRIVING_W, BROKEN_WHITE), ("driving", DRIVING_W, SOLID_WHITE),
                       ("parking", PARKING_W, NO_MARK), ("sidewalk", SIDEWALK_W, NO_MARK)])
    left = _side(1, [("sidewalk", SIDEWALK_W, NO_MARK)])
    road = RoadSpec("1", "one_way_street", Pose(0.0, 0.0, 0.0), (Line(400.0),), left=left, right=right,
                    center_mark=SOLID_WHITE)
    return MapSpec("txt2sce_one_way", (road,), description="one-way street, 2 lanes, parking on the right")


def curve_map() -> MapSpec:
    """(c) Two-way road, 2 lanes each way: a left curve R=100 m then a right curve R=150 m, clothoid transitions."""
    k1, k2 = 1.0 / 100.0, -1.0 / 150.0
    geometry = (Line(100.0), Spiral(40.0, 0.0, k1), Arc(100.0, k1), Spiral(40.0, k1, 0.0), Line(60.0),
                Spiral(30.0, 0.0, k2), Arc(120.0, k2), Spiral(30.0, k2, 0.0), Line(100.0))
    side = [("driving", DRIVING_W, BROKEN_WHITE), ("driving", DRIVING_W, SOLID_WHITE),
            ("sidewalk", SIDEWALK_W, NO_MARK)]
    road = RoadSpec("1", "curved_road", Pose(0.0, 0.0, 0.0), geometry, left=_side(1, side), right=_side(-1, side),
                    center_mark=SOLID_YELLOW_DOUBLE, speed_kmh=60.0)
    return MapSpec("txt2sce_curve", (road,), description="two-way curves R100 left and R150 right with clothoids")


def parking_map() -> MapSpec:
    """(g) A parking-lot aisle: one lane each way between rows of perpendicular stalls, 10 km/h."""
    side = [("driving", 3.0, NO_MARK), ("parking", STALL_W, NO_MARK), ("sidewalk", SIDEWALK_W, NO_MARK)]
    road = RoadSpec("1", "parking_aisle", Pose(0.0, 0.0, 0.0), (Line(120.0),), left=_side(1, side),
                    right=_side(-1, side), center_mark=RoadMark("broken", "white", "both"), road_type="lowSpeed",
                    speed_kmh=10.0)
    return MapSpec("txt2sce_parking_lot", (road,), description="parking aisle with perpendicular stalls both sides")


# --------------------------------------------------------------------------------------------- junction helpers


def _approach(rid: str, name: str, phi: float, dist: float, length: float, left: tuple[LaneSpec, ...],
              right: tuple[LaneSpec, ...], junction: str, *, signals: tuple[SignalSpec, ...] = (),
              center: RoadMark = SOLID_YELLOW_DOUBLE) -> RoadSpec:
    """A straight leg whose end (s = length) touches the junction `dist` m from the origin in direction `phi`.

    Its right lanes (negative ids) drive towards the junction, its left lanes away from it.
    """
    ux, uy = _unit(phi)
    start = Pose((dist + length) * ux, (dist + length) * uy, phi + math.pi)
    return RoadSpec(rid, name, start, (Line(length),), left=left, right=right, center_mark=center,
                    successor=RoadLink("junction", junction), signals=signals)


def _connecting(rid: str, junction: str, a: RoadSpec, lane_in: int, b: RoadSpec, lane_out: int,
                width: float = DRIVING_W) -> RoadSpec:
    """A one-lane connecting road from lane `lane_in` at the end of `a` into lane `lane_out` at the end of `b`.

    Its reference line runs along the lane's left border, so it starts on the incoming lane's inner border and
    ends on the outgoing lane's inner border; lane -1 of the connector is then exactly the lane.
    """
    start = a.end_pose().offset(lane_border_t(a.right, lane_in, outer=False))
    b_end = b.end_pose().offset(lane_border_t(b.left, lane_out, outer=False))
    end = Pose(b_end.x, b_end.y, b_end.h + math.pi)
    lane = LaneSpec(-1, "driving", width, NO_MARK, predecessor=lane_in, successor=lane_out)
    return RoadSpec(rid, f"{a.name}:{lane_in}->{b.name}:{lane_out}", start, tuple(connector(start, end)),
                    right=(lane,), junction=junction, predecessor=RoadLink("road", a.id, "end"),
                    successor=RoadLink("road", b.id, "end"))


def _connect_all(junction: str, first_id: int, plan: list[tuple[RoadSpec, int, RoadSpec, int]],
                 ) -> tuple[list[RoadSpec], list[ConnectionSpec]]:
    roads, conns = [], []
    for k, (a, lin, b, lout) in enumerate(plan):
        rid = str(first_id + k)
        roads.append(_connecting(rid, junction, a, lin, b, lout))
        conns.append(ConnectionSpec(str(k), a.id, rid, "start", ((lin, -1),)))
    return roads, conns


# --------------------------------------------------------------------------------------------- junction maps


def junction4_map() -> MapSpec:
    """(d) Signalised 4-way junction: per approach a left-turn lane and 2 through lanes, a median opposite.

    Legs are 200 m long and end 20 m from the centre. Lane -1 turns left (or U-turns into the outer lane), -2 goes
    straight, -3 straight or right. Each approach has a traffic light for lanes -2..-3 and a left-arrow light for
    lane -1 at its stop line; four controllers group them into the usual phases (E-W through, E-W left, ...).
    """
    jid, dist, length = "100", 20.0, 200.0
    inc = _side(-1, [("driving", DRIVING_W, BROKEN_WHITE), ("driving", DRIVING_W, BROKEN_WHITE),
                     ("driving", DRIVING_W, SOLID_WHITE), ("sidewalk", SIDEWALK_W, NO_MARK)])
    out = _side(1, [("median", DRIVING_W, SOLID_YELLOW_DOUBLE), ("driving", DRIVING_W, BROKEN_WHITE),
                    ("driving", DRIVING_W, SOLID_WHITE), ("sidewalk", SIDEWALK_W, NO_MARK)])
    inc = (LaneSpec(-1, "driving", DRIVING_W, SOLID_WHITE),) + inc[1:]  # no change into the left-turn lane
    legs: dict[str, RoadSpec] = {}
    controllers: dict[str, list[str]] = {"ew_through": [], "ew_left": [], "ns_through": [], "ns_left": []}
    for k, (name, phi) in enumerate((("east_leg", 0.0), ("north_leg", math.pi / 2), ("west_leg", math.pi),
                                     ("south_leg", 3 * math.pi / 2))):
        rid = str(k + 1)
        axis = "ew" if name[0] in "ew" else "ns"
        sid_main, sid_left = f"{1000 + 10 * (k + 1)}", f"{1000 + 10 * (k + 1) + 1}"
        signals = (
            SignalSpec(sid_main, f"{name}_light", length - 1.0, -(3 * DRIVING_W + SIDEWALK_W / 2), True, "+",
                       TRAFFIC_LIGHT, country=LIGHT_COUNTRY, valid_lanes=(-3, -2), height=3.0, z_offset=2.5),
            SignalSpec(sid_left, f"{name}_left_arrow", length - 1.0, DRIVING_W / 2, True, "+", ARROW_LIGHT, "10",
                       country=LIGHT_COUNTRY, valid_lanes=(-1, -1), height=3.0, z_offset=2.5),
        )
        controllers[f"{axis}_through"].append(sid_main)
        controllers[f"{axis}_left"].append(sid_left)
        legs[name] = _approach(rid, name, phi, dist, length, out, inc, jid, signals=signals)
    order = ["east_leg", "north_leg", "west_leg", "south_leg"]  # counter-clockwise
    plan = []
    for k, name in enumerate(order):
        a = legs[name]
        # `order` runs counter-clockwise by direction from the centre; a car arriving from leg k faces the
        # centre, so the leg before it in that order is on its left (from the east, heading west: south).
        left_leg, opposite, right_leg = (legs[order[(k - 1) % 4]], legs[order[(k + 2) % 4]],
                                         legs[order[(k + 1) % 4]])
        plan += [(a, -1, left_leg, 2), (a, -2, opposite, 2), (a, -3, opposite, 3), (a, -3, right_leg, 3),
                 (a, -1, a, 3)]
    conn_roads, conns = _connect_all(jid, 101, plan)
    ctrl_specs = tuple(ControllerSpec(str(k + 1), f"{jid}_{name}", tuple(ids), sequence=k)
                       for k, (name, ids) in enumerate(controllers.items()))
    junction = JunctionSpec(jid, "signalised_crossing", tuple(conns), controllers=tuple(c.id for c in ctrl_specs))
    return MapSpec("txt2sce_junction4_signal", tuple(legs.values()) + tuple(conn_roads), (junction,), ctrl_specs,
                   description="signalised 4-way junction with left-turn lanes and U-turns")


def junction3_map() -> MapSpec:
    """(e) Stop-controlled T junction: a major road (2 lanes each way, west-east) and a minor road from the south
    (1 lane each way) with a stop sign at its stop line; the major road has priority."""
    jid, length = "200", 200.0
    major_side = [("driving", DRIVING_W, BROKEN_WHITE), ("driving", DRIVING_W, SOLID_WHITE),
                  ("sidewalk", SIDEWALK_W, NO_MARK)]
    minor_side = [("driving", DRIVING_W, SOLID_WHITE), ("sidewalk", SIDEWALK_W, NO_MARK)]
    # Major legs end 10 m from the centre (clear of the 5.5 m minor half width), the minor leg 12 m (major: 9 m).
    east = _approach("1", "major_east", 0.0, 10.0, length, _side(1, major_side), _side(-1, major_side), jid)
    west = _approach("2", "major_west", math.pi, 10.0, length, _side(1, major_side), _side(-1, major_side), jid)
    stop = SignalSpec("2001", "minor_south_stop", length - 1.0, -(DRIVING_W + SIDEWALK_W / 2), False, "+", STOP_SIGN,
                      valid_lanes=(-1, -1), height=0.9, z_offset=1.5)
    south = _approach("3", "minor_south", 3 * math.pi / 2, 12.0, length, _side(1, minor_side),
                      _side(-1, minor_side), jid, signals=(stop,))
    plan = [(west, -1, east, 1), (west, -2, east, 2), (west, -2, south, 1),
            (east, -1, west, 1), (east, -2, west, 2), (east, -1, south, 1),
            (south, -1, west, 1), (south, -1, east, 2)]
    conn_roads, conns = _connect_all(jid, 201, plan)
    junction = JunctionSpec(jid, "stop_t_junction", tuple(conns), priorities=(("1", "3"), ("2", "3")))
    return MapSpec("txt2sce_junction3_stop", (east, west, south) + tuple(conn_roads), (junction,),
                   description="T junction, stop sign on the minor road")


def junction4_stop_map() -> MapSpec:
    """(h) All-way-stop 4-way junction of a one-way street (2 lanes, westbound) and a two-way street (1 lane each
    way, north-south): stop signs on the three approaches. Covers the dev set's 4-way stops and one-way approaches.
    """
    jid, length = "400", 200.0
    lanes2 = [("driving", DRIVING_W, BROKEN_WHITE), ("driving", DRIVING_W, SOLID_WHITE),
              ("sidewalk", SIDEWALK_W, NO_MARK)]
    walk = [("sidewalk", SIDEWALK_W, NO_MARK)]
    two_way = [("driving", DRIVING_W, SOLID_WHITE), ("sidewalk", SIDEWALK_W, NO_MARK)]

    def stop(sid: str, name: str, lanes: tuple[int, int], t: float) -> SignalSpec:
        return SignalSpec(sid, name, length - 1.0, t, False, "+", STOP_SIGN, valid_lanes=lanes, height=0.9,
                          z_offset=1.5)

    # One-way legs end 8 m from the centre (north-south half width 5.5 m); the two-way legs 11 m (the one-way
    # street spans y = -2 .. 9 m).
    east = _approach("1", "one_way_east", 0.0, 8.0, length, _side(1, walk), _side(-1, lanes2), jid,
                     signals=(stop("4001", "east_stop", (-2, -1), -(2 * DRIVING_W + SIDEWALK_W / 2)),),
                     center=SOLID_WHITE)
    west = _approach("2", "one_way_west", math.pi, 8.0, length, _side(1, lanes2), _side(-1, walk), jid,
                     center=SOLID_WHITE)
    north = _approach("3", "two_way_north", math.pi / 2, 11.0, length, _side(1, two_way), _side(-1, two_way), jid,
                      signals=(stop("4003", "north_stop", (-1, -1), -(DRIVING_W + SIDEWALK_W / 2)),))
    south = _approach("4", "two_way_south", 3 * math.pi / 2, 11.0, length, _side(1, two_way), _side(-1, two_way),
                      jid, signals=(stop("4004", "south_stop", (-1, -1), -(DRIVING_W + SIDEWALK_W / 2)),))
    plan = [(east, -1, west, 1), (east, -2, west, 2), (east, -1, south, 1), (east, -2, north, 1),
            (south, -1, north, 1), (south, -1, west, 1),
            (north, -1, south, 1), (north, -1, west, 2)]
    conn_roads, conns = _connect_all(jid, 401, plan)
    junction = JunctionSpec(jid, "all_way_stop", tuple(conns))
    return MapSpec("txt2sce_junction4_stop", (east, west, north, south) + tuple(conn_roads), (junction,),
                   description="all-way stop: one-way 2-lane street crossing a two-way street")


def roundabout_map() -> MapSpec:
    """(f) Single-lane roundabout (ring radius 25 m to the lane's inner edge, counter-clockwise) with 4 two-way legs.

    The ring is 4 arc roads between 4 junctions, one per leg; each junction holds the ring's through connector, the
    entry (leg -> ring, a right turn) and the exit (ring -> leg). Legs carry yield signs.
    """
    # The ring keeps to under 30° inside each junction so that staying on it reads as "straight".
    radius, half_gap, dist, length = 25.0, math.radians(14.0), 40.0, 150.0
    side = [("driving", DRIVING_W, SOLID_WHITE), ("sidewalk", SIDEWALK_W, NO_MARK)]
    angles = [k * math.pi / 2 for k in range(4)]
    jids = [str(301 + k) for k in range(4)]
    legs, ring = [], []
    for k, phi in enumerate(angles):
        yield_sign = SignalSpec(f"{3000 + k + 1}", f"leg{k + 1}_yield", length - 1.0, -(DRIVING_W + SIDEWALK_W / 2),
                                False, "+", YIELD_SIGN, valid_lanes=(-1, -1), height=0.9, z_offset=1.5)
        legs.append(_approach(str(k + 1), f"leg_{k + 1}", phi, dist, length, _side(1, side), _side(-1, side),
                              jids[k], signals=(yield_sign,)))
        a0 = phi + half_gap
        start = Pose(radius * math.cos(a0), radius * math.sin(a0), a0 + math.pi / 2)
        arc_len = radius * (math.pi / 2 - 2 * half_gap)
        ring.append(RoadSpec(str(11 + k), f"ring_{k + 1}", start, (Arc(arc_len, 1.0 / radius),),
                             right=(LaneSpec(-1, "driving", RING_W, NO_MARK),), center_mark=SOLID_WHITE,
                             predecessor=RoadLink("junction", jids[k]),
                             successor=RoadLink("junction", jids[(k + 1) % 4]), speed_kmh=30.0))
    junctions, conn_roads = [], []
    for k in range(4):
        jid, leg, ring_in, ring_out = jids[k], legs[k], ring[(k - 1) % 4], ring[k]
        base = 310 + 10 * k
        through_start = ring_in.end_pose()
        through = RoadSpec(str(base + 1), f"ring_through_{k + 1}", through_start,
                           (Arc(radius * 2 * half_gap, 1.0 / radius),),
                           right=(LaneSpec(-1, "driving", RING_W, NO_MARK, predecessor=-1, successor=-1),),
                           junction=jid, predecessor=RoadLink("road", ring_in.id, "end"),
                           successor=RoadLink("road", ring_out.id, "start"), speed_kmh=30.0)
        entry_start = leg.end_pose()
        entry = RoadSpec(str(base + 2), f"entry_{k + 1}", entry_start,
                         (Hermite(entry_start.local(ring_out.start)),),
                         right=(LaneSpec(-1, "driving", DRIVING_W, NO_MARK, predecessor=-1, successor=-1,
                                         width_end=RING_W),),
                         junction=jid, predecessor=RoadLink("road", leg.id, "end"),
                         successor=RoadLink("road", ring_out.id, "start"), speed_kmh=30.0)
        exit_end = leg.end_pose()
        exit_end = Pose(exit_end.x, exit_end.y, exit_end.h + math.pi)
        exit_ = RoadSpec(str(base + 3), f"exit_{k + 1}", through_start, (Hermite(through_start.local(exit_end)),),
                         right=(LaneSpec(-1, "driving", RING_W, NO_MARK, predecessor=-1, successor=1,
                                         width_end=DRIVING_W),),
                         junction=jid, predecessor=RoadLink("road", ring_in.id, "end"),
                         successor=RoadLink("road", leg.id, "end"), speed_kmh=30.0)
        conn_roads += [through, entry, exit_]
        junctions.append(JunctionSpec(jid, f"roundabout_leg_{k + 1}", (
            ConnectionSpec("0", ring_in.id, through.id, "start", ((-1, -1),)),
            ConnectionSpec("1", leg.id, entry.id, "start", ((-1, -1),)),
            ConnectionSpec("2", ring_in.id, exit_.id, "start", ((-1, -1),)),
        ), priorities=((ring_in.id, leg.id),)))
    return MapSpec("txt2sce_roundabout", tuple(legs) + tuple(ring) + tuple(conn_roads), tuple(junctions),
                   description="single-lane roundabout, 4 legs, yield on entry")


#: file name -> generator. The file names are what seeds and tests refer to.
BUNDLED: dict[str, Callable[[], MapSpec]] = {
    "straight_3x3.xodr": straight_map,
    "one_way.xodr": one_way_map,
    "curve.xodr": curve_map,
    "junction4_signal.xodr": junction4_map,
    "junction3_stop.xodr": junction3_map,
    "junction4_stop.xodr": junction4_stop_map,
    "roundabout.xodr": roundabout_map,
    "parking_lot.xodr": parking_map,
}


def render(name: str) -> bytes:
    """The OpenDRIVE bytes of bundled map `name` (a key of `BUNDLED`)."""
    return to_xml(BUNDLED[name]())


def build_bundled_maps(out_dir: str | Path | None = None) -> list[Path]:
    """Write every bundled map into `out_dir` (default: the package's `data/maps`); returns the paths written."""
    target = Path(out_dir) if out_dir else BUNDLED_MAPS
    target.mkdir(parents=True, exist_ok=True)
    written = []
    for name in BUNDLED:
        path = target / name
        path.write_bytes(render(name))
        written.append(path)
    return written


def bundled_map_paths() -> list[Path]:
    """The committed bundled maps, in `BUNDLED` order."""
    return [BUNDLED_MAPS / name for name in BUNDLED]
