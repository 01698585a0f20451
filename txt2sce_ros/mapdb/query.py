"""Road-matching queries over the map database (paper §III-C: eliminate segments that do not fit the report).

Mixed into `MapDatabase`; every query returns typed records in a deterministic order (road ids numerically), so a
caller drawing one candidate with a seeded `numpy.random.Generator` gets the same scenario every time.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Iterable, TypeVar

from ..errors import InputError
from .records import (ROAD_NEEDS, Approach, ConnectionEdge, Control, JunctionInfo, Layout, RoadMatch, Segment,
                      Turn)

if TYPE_CHECKING:  # pragma: no cover
    import networkx as nx

#: What an approach may be asked to offer (`MapDatabase.approaches(needs=...)`).
APPROACH_NEEDS = frozenset({"dedicated_left", "left_with_left_neighbour", "right_with_right_neighbour",
                            "two_way"})


def _id_key(rid: str) -> tuple[int, str]:
    return (len(rid), rid)


def _check(needs: Iterable[str], allowed: frozenset[str], what: str) -> frozenset[str]:
    got = frozenset(needs)
    unknown = got - allowed
    if unknown:
        raise InputError(f"unknown {what} need(s) {sorted(unknown)}; known: {sorted(allowed)}",
                         element="mapdb query")
    return got


_E = TypeVar("_E", Layout, Control)


def _member(kind: type[_E], value: str | _E | None, what: str) -> _E | None:
    """The enum member a query argument names (None passes through); InputError listing the known values."""
    try:
        return None if value is None else kind(value)
    except ValueError:
        raise InputError(f"unknown {what} {value!r}; known: {[m.value for m in kind]}",
                         element="mapdb query") from None


def _layout(value: str | Layout | None) -> Layout | None:
    return _member(Layout, value, "layout")


def _control(value: str | Control | None) -> Control | None:
    return _member(Control, value, "control")


class MapQueries:
    """Queries; the data attributes are set by `MapDatabase.__init__`."""

    source: str
    graph: "nx.MultiDiGraph"
    segments: dict[str, Segment]
    edges: tuple[ConnectionEdge, ...]
    junction_infos: dict[str, JunctionInfo]
    approach_map: dict[str, tuple[Approach, ...]]

    # ----------------------------------------------------------------------------------------- roads

    def segment(self, road_id: str | int) -> Segment:
        """The record of one road (connecting roads included)."""
        try:
            return self.segments[str(road_id)]
        except KeyError:
            raise InputError(f"no road {road_id!r} in the map database", source=self.source, element="road") from None

    def roads(self, layout: str | Layout | None = None, *, min_lanes: int | None = None,
              one_way: bool | None = None, needs: Iterable[str] = ()) -> list[RoadMatch]:
        """Roads outside junctions, one match per driving direction, that fit a sketch's road.

        - `layout`: 'straight', 'curve', 'parking', 'roundabout' (the ring) — a tag of the segment.
        - `min_lanes`: at least this many driving lanes in the direction of travel (in the road's main section).
        - `one_way`: True only one-way roads, False only two-way roads, None either.
        - `needs`: features of the direction of travel, any of 'left_neighbour', 'right_neighbour' (a second lane
          to change into), 'oncoming' (opposite-direction lanes), 'bike_lane', 'parking_lane', 'sidewalk',
          'shoulder' (beyond the rightmost driving lane, before the next driving lane), 'lane_change_left',
          'lane_change_right' (some lane's marks permit the change).

        Example: `db.roads("straight", min_lanes=3, one_way=False, needs={"oncoming", "bike_lane"})`.
        """
        want_layout = _layout(layout)
        want = _check(needs, ROAD_NEEDS, "road")
        out = []
        for rid in sorted(self.segments, key=_id_key):
            seg = self.segments[rid]
            if seg.is_connecting or (want_layout and want_layout not in seg.layouts):
                continue
            if one_way is not None and seg.one_way != one_way:
                continue
            main = seg.main_section
            for forward in (True, False):
                lanes = main.driving(forward)
                if not lanes or (min_lanes is not None and len(lanes) < min_lanes):
                    continue
                match = RoadMatch(seg, forward, main.index, tuple(ln.id for ln in lanes),
                                  tuple(ln.id for ln in main.driving(not forward)),
                                  tuple(ln.type for ln in main.beside(forward, "right")),
                                  tuple(ln.type for ln in main.beside(forward, "left")))
                if self._road_needs_met(match, lanes, want):
                    out.append(match)
        return out

    @staticmethod
    def _road_needs_met(match: RoadMatch, lanes: tuple, needs: frozenset[str]) -> bool:
        checks = {
            "left_neighbour": lambda: len(lanes) >= 2,
            "right_neighbour": lambda: len(lanes) >= 2,
            "oncoming": lambda: bool(match.oncoming),
            "bike_lane": lambda: "biking" in match.right_side,
            "parking_lane": lambda: "parking" in match.right_side,
            "sidewalk": lambda: "sidewalk" in match.right_side,
            "shoulder": lambda: "shoulder" in match.right_side,
            "lane_change_left": lambda: any(ln.change_left for ln in lanes),
            "lane_change_right": lambda: any(ln.change_right for ln in lanes),
        }
        return all(checks[n]() for n in needs)

    # ----------------------------------------------------------------------------------------- junctions

    def junctions(self, layout: str | Layout | None = None, *, control: str | Control | None = None,
                  min_lanes: int | None = None, one_way: bool | None = None, turns: Iterable[str | Turn] = (),
                  needs: Iterable[str] = ()) -> list[JunctionInfo]:
        """Junctions with at least one approach that fits: see `approaches` for `control`, `min_lanes`,
        `one_way`, `turns` and `needs`. `layout`: 'junction4', 'junction3', 'roundabout' or 'junction' (other leg counts).

        Example: `db.junctions("junction4", control="signal", turns={"left"}, needs={"dedicated_left"})`.
        """
        want_layout = _layout(layout)
        out = []
        for jid in sorted(self.junction_infos, key=_id_key):
            info = self.junction_infos[jid]
            if want_layout and info.layout is not want_layout:
                continue
            if self.approaches(jid, control=control, min_lanes=min_lanes, one_way=one_way, turns=turns,
                               needs=needs):
                out.append(info)
        return out

    def approaches(self, junction_id: str | int, *, control: str | Control | None = None,
                   min_lanes: int | None = None, one_way: bool | None = None, turns: Iterable[str | Turn] = (),
                   needs: Iterable[str] = ()) -> tuple[Approach, ...]:
        """Incoming roads of a junction: per road its driving lanes (left to right), and per lane the connections
        (with turn types) that start from it, the approach's control and its signals.

        Filters: `control` ('signal', 'stop_sign', 'none'); `min_lanes` driving lanes into the junction;
        `one_way` True for one-way approach roads (no lanes leave the junction on them), False for two-way; `turns`
        the approach must offer (any of 'straight', 'left', 'right', 'uturn'); `needs` any of 'dedicated_left'
        (a lane that only turns left), 'left_with_left_neighbour' (a left turn from a lane that has a
        same-direction lane on its left, i.e. a lane change may precede the turn — paper's "afd"),
        'right_with_right_neighbour', 'two_way' (the road also has lanes leaving the junction).
        """
        jid = str(junction_id)
        if jid not in self.junction_infos:
            raise InputError(f"no junction {jid!r} in the map database", source=self.source, element="junction")
        want_control = _control(control)
        want_turns = frozenset(Turn(t) for t in turns)
        want = _check(needs, APPROACH_NEEDS, "approach")
        out = []
        for app in self.approach_map.get(jid, ()):
            if want_control and app.control is not want_control:
                continue
            if min_lanes is not None and len(app.lanes) < min_lanes:
                continue
            if one_way is not None and (app.exit_lanes == 0) != one_way:
                continue
            if not want_turns <= app.turns:
                continue
            checks = {
                "dedicated_left": lambda: any(ln.dedicated_left for ln in app.lanes),
                "left_with_left_neighbour": lambda: any(Turn.LEFT in ln.turns and ln.has_left_neighbour
                                                        for ln in app.lanes),
                "right_with_right_neighbour": lambda: any(Turn.RIGHT in ln.turns and ln.has_right_neighbour
                                                          for ln in app.lanes),
                "two_way": lambda: app.exit_lanes > 0,
            }
            if all(checks[n]() for n in want):
                out.append(app)
        return tuple(out)

    def approach(self, junction_id: str | int, road_id: str | int) -> Approach:
        """The approach of `road_id` into `junction_id`."""
        for app in self.approach_map.get(str(junction_id), ()):
            if app.road_id == str(road_id):
                return app
        raise InputError(f"road {road_id!r} is no approach of junction {junction_id!r}", source=self.source,
                         element="junction")

    def relative_roads(self, junction_id: str | int, road_id: str | int) -> dict[str, str | None]:
        """The junction's other legs as the sketch's R1–R4 see them from `road_id`: 'left' (the crossing road on
        the left, R1; a left turn leaves on it), 'opposite' (R2; straight on), 'right' (R3); None where the
        junction has no such leg. One-way legs count: a leg is a road, whichever way it may be driven."""
        info = self.junction_infos.get(str(junction_id))
        if info is None:
            raise InputError(f"no junction {junction_id!r} in the map database", source=self.source,
                             element="junction")
        heads = dict(info.leg_headings)
        if str(road_id) not in heads:
            raise InputError(f"road {road_id!r} is no leg of junction {junction_id!r}", source=self.source,
                             element="junction")
        mine = heads[str(road_id)]
        # Traffic arriving from the leg on my left drives to my right: its heading is mine minus 90 degrees.
        wanted = {"left": -math.pi / 2, "opposite": math.pi, "right": math.pi / 2}
        best: dict[str, tuple[float, str | None]] = {k: (math.radians(50), None) for k in wanted}
        for rid, heading in info.leg_headings:
            if rid == str(road_id):
                continue
            d = heading - mine
            for name, target in wanted.items():
                err = abs(math.atan2(math.sin(d - target), math.cos(d - target)))
                if err < best[name][0]:
                    best[name] = (err, rid)
        return {k: v[1] for k, v in best.items()}

    def relative_approaches(self, junction_id: str | int, road_id: str | int) -> dict[str, Approach | None]:
        """Like `relative_roads`, as approaches (None for a leg no lane drives into the junction on)."""
        by_road = {a.road_id: a for a in self.approach_map.get(str(junction_id), ())}
        return {k: by_road.get(r) if r else None for k, r in self.relative_roads(junction_id, road_id).items()}

    def edges_from(self, road_id: str | int, *, junction_id: str | None = None) -> list[ConnectionEdge]:
        """Connections leaving a road (optionally only through one junction)."""
        rid = str(road_id)
        return [e for e in self.edges if e.from_road == rid and (junction_id is None or e.junction_id == junction_id)]

    # ----------------------------------------------------------------------------------------- report

    def summary(self) -> str:
        """A human-readable overview: segments with lanes and tags, junctions with approaches and turns."""
        lines = [f"map {self.source}", f"  sha256 {getattr(self, 'sha256', '')[:16]}",
                 f"  {sum(not s.is_connecting for s in self.segments.values())} segments, "
                 f"{sum(s.is_connecting for s in self.segments.values())} connecting roads, "
                 f"{len(self.junction_infos)} junctions, {len(self.edges)} lane connections"]
        lines.append("segments:")
        for rid in sorted(self.segments, key=_id_key):
            seg = self.segments[rid]
            if seg.is_connecting:
                continue
            main = seg.main_section
            tags = ",".join(sorted(t.value for t in seg.layouts))
            right = "+".join(ln.type for ln in main.beside(True, "right")) or "-"
            left = "+".join(ln.type for ln in main.beside(False, "right")) or "-"
            lines.append(f"  road {rid:>4} {seg.name[:24]:<24} {seg.length:8.1f} m  [{tags}]  lanes +s:"
                         f"{seg.lanes_forward} -s:{seg.lanes_backward}{'  one-way' if seg.one_way else ''}"
                         f"  right of +s: {right}  right of -s: {left}")
        if self.junction_infos:
            lines.append("junctions:")
        for jid in sorted(self.junction_infos, key=_id_key):
            info = self.junction_infos[jid]
            lines.append(f"  junction {jid} {info.name[:24]!r}: {info.layout.value}, {info.legs} legs, "
                         f"control {info.control.value}, {len(info.connecting_roads)} connecting roads")
            for app in self.approach_map.get(jid, ()):
                lanes = " ".join(f"{ln.lane_id}:{'/'.join(sorted(t.value for t in ln.turns)) or '-'}"
                                 for ln in app.lanes)
                lines.append(f"    from road {app.road_id:>4} ({app.control.value}): {lanes}")
        return "\n".join(lines)
