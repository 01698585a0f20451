"""ScenarioPlan -> OpenSCENARIO 1.0 XML bytes (docs/seed_format.md), every attribute value checked against the
entity database as it is written.

Deterministic: no clock, no dict-order surprises, numbers rounded to 3 decimals (mm, ms), so the same plan gives
the same bytes.
"""

from __future__ import annotations

import math

from lxml import etree

from ..sketch import LANED_POSITIONS
from ..xosc.entitydb import EntityDB, entity_db
from .model import (
    EntityPlan, EnvironmentPlan, EventPlan, LaneChangeAct, LaneOffsetAct, LanePose, Pose, RouteAct, ScenarioPlan,
    SpeedAct, TrajectoryAct, Trigger,
)
from .signal_story import write_plan

#: The FileHeader date: fixed so that seeds are byte-identical across runs (the manifest says when it was built).
HEADER_DATE = "2024-01-01T00:00:00"
AUTHOR = "txt2sce"
#: Masses (kg) the XSD requires for pedestrians and objects; nothing in the pipeline reads them.
PEDESTRIAN_MASS = 75.0
OBJECT_MASS = 50.0
#: Events in one maneuver may overlap (a route assigned while a speed change runs): `parallel`, not `overwrite`.
EVENT_PRIORITY = "parallel"


def _num(v: float) -> str:
    r = round(float(v), 3)
    if r == 0:
        r = 0.0  # no "-0.0"
    return repr(r)


class _Xml:
    """Element factory that checks each attribute with the entity database (type resolved from the tag, or given
    when the tag is ambiguous)."""

    def __init__(self, db: EntityDB) -> None:
        self.db = db

    def el(self, parent: etree._Element | None, tag: str, attrs: dict | None = None, *, xsd_type: str | None = None
           ) -> etree._Element:
        node = etree.Element(tag) if parent is None else etree.SubElement(parent, tag)
        typ = xsd_type or tag
        for k, v in (attrs or {}).items():
            text = _num(v) if isinstance(v, float) else ("true" if v is True else "false" if v is False else str(v))
            node.set(k, self.db.check_value(typ, k, text))
        return node


def _position(x: _Xml, parent: etree._Element, pose: Pose, tag: str = "Position") -> None:
    pos = x.el(parent, tag, xsd_type="Position")
    if isinstance(pose, LanePose):
        x.el(pos, "LanePosition", {"roadId": pose.road_id, "laneId": str(pose.lane_id), "offset": float(pose.offset),
                                   "s": float(pose.s)})
    else:
        x.el(pos, "WorldPosition", {"x": float(pose.x), "y": float(pose.y), "z": 0.0,
                                    "h": float(_wrap(pose.h)), "p": 0.0, "r": 0.0})


def _wrap(h: float) -> float:
    return (h + math.pi) % (2 * math.pi) - math.pi


def _properties(x: _Xml, parent: etree._Element, props: list[tuple[str, str]]) -> None:
    ps = x.el(parent, "Properties")
    for k, v in props:
        x.el(ps, "Property", {"name": k, "value": v})


def _bounding_box(x: _Xml, parent: etree._Element, e: EntityPlan) -> None:
    w, l, h = e.dimensions
    bb = x.el(parent, "BoundingBox")
    # Vehicles: OpenSCENARIO's reference point is the rear axle; the box centre sits ~31% of the length ahead of it
    # (1.4 m for a 4.5 m sedan, as contract.EntityState assumes). Pedestrians and objects are centred.
    cx = round(0.311 * l, 2) if e.kind == "vehicle" else 0.0
    x.el(bb, "Center", {"x": float(cx), "y": 0.0, "z": float(h / 2)})
    x.el(bb, "Dimensions", {"width": float(w), "length": float(l), "height": float(h)})


def _entity(x: _Xml, ents: etree._Element, e: EntityPlan, d_perf: tuple[float, float, float]) -> None:
    so = x.el(ents, "ScenarioObject", {"name": e.name})
    props = [("txt2sce:category", e.category)]
    # The report's relative position, so analysis labels a party by what the report said rather than by its Init
    # pose (a pedestrian crossing from R1 starts beside the road, which a pose-based guess cannot tell apart).
    if e.position:
        props.append(("txt2sce:position", e.position))
        if e.lane and e.position in LANED_POSITIONS:
            props.append(("txt2sce:lane", e.lane))
    if e.kind == "vehicle":
        v = x.el(so, "Vehicle", {"name": f"{e.name}_vehicle", "vehicleCategory": e.xosc_category})
        _bounding_box(x, v, e)
        x.el(v, "Performance", {"maxSpeed": float(d_perf[2]), "maxAcceleration": float(d_perf[0]),
                                "maxDeceleration": float(d_perf[1])})
        axles = x.el(v, "Axles")
        w, l, _ = e.dimensions
        wheel = 0.6 if l > 3 else 0.5
        x.el(axles, "FrontAxle", {"maxSteering": 0.5, "wheelDiameter": wheel, "trackWidth": float(round(w * 0.85, 2)),
                                  "positionX": float(round(l * 0.6, 2)), "positionZ": wheel / 2}, xsd_type="Axle")
        x.el(axles, "RearAxle", {"maxSteering": 0.0, "wheelDiameter": wheel, "trackWidth": float(round(w * 0.85, 2)),
                                 "positionX": 0.0, "positionZ": wheel / 2}, xsd_type="Axle")
        _properties(x, v, props)
    elif e.kind == "pedestrian":
        p = x.el(so, "Pedestrian", {"name": f"{e.name}_pedestrian", "model": e.category, "mass": PEDESTRIAN_MASS,
                                    "pedestrianCategory": e.xosc_category})
        _bounding_box(x, p, e)
        _properties(x, p, props)
    else:
        m = x.el(so, "MiscObject", {"name": f"{e.name}_object", "mass": OBJECT_MASS,
                                    "miscObjectCategory": e.xosc_category})
        _bounding_box(x, m, e)
        _properties(x, m, props)
    if e.external:
        oc = x.el(so, "ObjectController")
        c = x.el(oc, "Controller", {"name": "ads_under_test"})
        # esminiController: esmini knows the controller type by this property (a name it does not know is an
        # [error]); its ExternalController means "driven from outside", as ours is, and, never activated, leaves
        # the storyboard driving the ego there exactly as before. Our player reads only txt2sce:controller.
        _properties(x, c, [("esminiController", "ExternalController"), ("txt2sce:controller", "external")])


def _environment(x: _Xml, parent: etree._Element, env: EnvironmentPlan) -> None:
    ga = x.el(parent, "GlobalAction")
    ea = x.el(ga, "EnvironmentAction")
    en = x.el(ea, "Environment", {"name": "environment"})
    x.el(en, "TimeOfDay", {"animation": False, "dateTime": env.date_time})
    w = x.el(en, "Weather", {"cloudState": env.cloud_state})
    x.el(w, "Sun", {"intensity": float(env.sun_intensity), "azimuth": float(env.sun_azimuth),
                    "elevation": float(env.sun_elevation)})
    x.el(w, "Fog", {"visualRange": float(env.visual_range)})
    x.el(w, "Precipitation", {"precipitationType": env.precipitation,
                              "intensity": float(env.precipitation_intensity)})
    x.el(en, "RoadCondition", {"frictionScaleFactor": float(env.friction)})


def _speed(x: _Xml, parent: etree._Element, a: SpeedAct) -> None:
    la = x.el(parent, "LongitudinalAction")
    sa = x.el(la, "SpeedAction")
    x.el(sa, "SpeedActionDynamics", {"dynamicsShape": a.shape, "value": float(a.value),
                                     "dynamicsDimension": a.dimension})
    t = x.el(sa, "SpeedActionTarget")
    x.el(t, "AbsoluteTargetSpeed", {"value": float(a.target)})


def _route(x: _Xml, parent: etree._Element, a: RouteAct) -> None:
    ra = x.el(parent, "RoutingAction")
    ar = x.el(ra, "AssignRouteAction")
    r = x.el(ar, "Route", {"name": a.name, "closed": False})
    for wp in a.waypoints:
        w = x.el(r, "Waypoint", {"routeStrategy": a.strategy})
        _position(x, w, wp)


def _private_action(x: _Xml, parent: etree._Element, act: object, entity: str) -> None:
    pa = x.el(parent, "PrivateAction")
    if isinstance(act, SpeedAct):
        _speed(x, pa, act)
    elif isinstance(act, LaneChangeAct):
        lat = x.el(pa, "LateralAction")
        lc = x.el(lat, "LaneChangeAction")
        x.el(lc, "LaneChangeActionDynamics", {"dynamicsShape": "sinusoidal", "value": float(act.duration),
                                              "dynamicsDimension": "time"}, xsd_type="TransitionDynamics")
        tgt = x.el(lc, "LaneChangeTarget")
        x.el(tgt, "RelativeTargetLane", {"entityRef": act.reference or entity, "value": str(int(act.relative))})
    elif isinstance(act, LaneOffsetAct):
        lat = x.el(pa, "LateralAction")
        lo = x.el(lat, "LaneOffsetAction", {"continuous": False})
        x.el(lo, "LaneOffsetActionDynamics", {"dynamicsShape": "sinusoidal",
                                              "maxLateralAcc": float(act.max_lateral_acc)})
        tgt = x.el(lo, "LaneOffsetTarget")
        x.el(tgt, "AbsoluteTargetLaneOffset", {"value": float(act.offset)})
    elif isinstance(act, RouteAct):
        _route(x, pa, act)
    elif isinstance(act, TrajectoryAct):
        ra = x.el(pa, "RoutingAction")
        ft = x.el(ra, "FollowTrajectoryAction")
        tr = x.el(ft, "Trajectory", {"name": act.name, "closed": False})
        shape = x.el(tr, "Shape")
        pl = x.el(shape, "Polyline")
        for v in act.vertices:
            vx = x.el(pl, "Vertex", {"time": 0.0})
            _position(x, vx, v)
        tref = x.el(ft, "TimeReference")
        x.el(tref, "None")
        x.el(ft, "TrajectoryFollowingMode", {"followingMode": "position"})
    else:  # pragma: no cover - the plan types are closed
        raise TypeError(f"unknown action record {act!r}")


def _condition(x: _Xml, group: etree._Element, name: str, trig: Trigger) -> None:
    c = x.el(group, "Condition", {"name": name, "delay": 0.0 if trig.kind != "event_end" else float(trig.value),
                                  "conditionEdge": "none"})
    if trig.kind == "time":
        bv = x.el(c, "ByValueCondition")
        x.el(bv, "SimulationTimeCondition", {"value": float(trig.value), "rule": "greaterThan"})
    elif trig.kind == "event_end":
        bv = x.el(c, "ByValueCondition")
        x.el(bv, "StoryboardElementStateCondition", {"storyboardElementType": "event",
                                                     "storyboardElementRef": trig.ref, "state": "completeState"})
    elif trig.kind in ("distance", "ttc"):
        be = x.el(c, "ByEntityCondition")
        te = x.el(be, "TriggeringEntities", {"triggeringEntitiesRule": "any"})
        x.el(te, "EntityRef", {"entityRef": trig.entity})
        ec = x.el(be, "EntityCondition")
        if trig.kind == "distance":
            x.el(ec, "RelativeDistanceCondition", {"entityRef": trig.ref, "freespace": False,
                                                   "relativeDistanceType": "cartesianDistance",
                                                   "value": float(trig.value), "rule": "lessThan"})
        else:
            ttc = x.el(ec, "TimeToCollisionCondition", {"value": float(trig.value), "freespace": False,
                                                        "alongRoute": False, "rule": "lessThan"})
            tt = x.el(ttc, "TimeToCollisionConditionTarget")
            x.el(tt, "EntityRef", {"entityRef": trig.ref})
    else:  # pragma: no cover
        raise ValueError(f"unknown trigger kind {trig.kind}")


def _trigger(x: _Xml, parent: etree._Element, tag: str, name: str, trig: Trigger) -> None:
    t = x.el(parent, tag, xsd_type="Trigger")
    g = x.el(t, "ConditionGroup")
    _condition(x, g, name, trig)


def _event(x: _Xml, man: etree._Element, ev: EventPlan, entity: str) -> None:
    e = x.el(man, "Event", {"name": ev.name, "priority": EVENT_PRIORITY, "maximumExecutionCount": "1"})
    for i, act in enumerate(ev.actions):
        a = x.el(e, "Action", {"name": f"{ev.name}_action" if i == 0 else f"{ev.name}_action{i + 1}"})
        _private_action(x, a, act, entity)
    _trigger(x, e, "StartTrigger", f"{ev.name}_start", ev.trigger)
    if ev.within is not None:
        _within(x, e.find("StartTrigger/ConditionGroup"), f"{ev.name}_where", entity, ev.within)


def _within(x: _Xml, group: etree._Element, name: str, entity: str, where: tuple[float, float, float]) -> None:
    """A second condition of the group (both must hold): `entity` within where[2] m of (where[0], where[1])."""
    c = x.el(group, "Condition", {"name": name, "delay": 0.0, "conditionEdge": "none"})
    be = x.el(c, "ByEntityCondition")
    x.el(x.el(be, "TriggeringEntities", {"triggeringEntitiesRule": "any"}), "EntityRef", {"entityRef": entity})
    dc = x.el(x.el(be, "EntityCondition"), "DistanceCondition", {"value": float(where[2]), "freespace": False,
                                                                  "alongRoute": False, "rule": "lessThan"})
    x.el(x.el(dc, "Position"), "WorldPosition", {"x": float(where[0]), "y": float(where[1]), "z": 0.0, "h": 0.0,
                                                 "p": 0.0, "r": 0.0})


def _story(x: _Xml, sb: etree._Element, e: EntityPlan) -> None:
    story_name = f"{e.name}_story"
    st = x.el(sb, "Story", {"name": story_name})
    act = x.el(st, "Act", {"name": f"{e.name}_act"})
    mg = x.el(act, "ManeuverGroup", {"name": f"{e.name}_mg", "maximumExecutionCount": "1"})
    actors = x.el(mg, "Actors", {"selectTriggeringEntities": False})
    x.el(actors, "EntityRef", {"entityRef": e.name})
    man = x.el(mg, "Maneuver", {"name": f"{e.name}_maneuver"})
    for ev in e.events:
        _event(x, man, ev, e.name)
    _trigger(x, act, "StartTrigger", f"{e.name}_act_start", Trigger("time", 0.0))


def write_xosc(plan: ScenarioPlan, *, db: EntityDB | None = None,
               performance: tuple[float, float, float] = (10.0, 10.0, 70.0)) -> bytes:
    """Serialise a plan as OpenSCENARIO 1.0 (UTF-8 bytes with XML declaration). `performance` is (max acceleration,
    max deceleration, max speed) for every vehicle (Table III). Raises InputError (from the entity database) when a
    value is outside its domain."""
    x = _Xml(db or entity_db("1.0"))
    root = x.el(None, "OpenSCENARIO", xsd_type="OpenScenario")
    x.el(root, "FileHeader", {"revMajor": "1", "revMinor": "0", "date": HEADER_DATE,
                              "description": f"txt2sce seed {plan.report_id}", "author": AUTHOR})
    x.el(root, "ParameterDeclarations")
    x.el(root, "CatalogLocations")
    rn = x.el(root, "RoadNetwork")
    x.el(rn, "LogicFile", {"filepath": plan.map_ref}, xsd_type="File")
    ents = x.el(root, "Entities")
    for e in plan.entities:
        _entity(x, ents, e, performance)
    sb = x.el(root, "Storyboard")
    init = x.el(sb, "Init")
    acts = x.el(init, "Actions", xsd_type="InitActions")
    _environment(x, acts, plan.environment)
    # Signal phases as timed TrafficSignalStateActions (signal_story): the form esmini executes as well as ours.
    signal_stories = []
    for sig in plan.signals:
        inits, story = write_plan(sig, time_limit=plan.time_limit)
        acts.extend(inits)
        signal_stories.append(story)
    for e in plan.entities:
        pr = x.el(acts, "Private", {"entityRef": e.name})
        pa = x.el(pr, "PrivateAction")
        tp = x.el(pa, "TeleportAction")
        _position(x, tp, e.start)
        if e.kind != "misc":
            _private_action(x, pr, SpeedAct(e.speed, "step", "time", 0.0), e.name)
        if e.route is not None:
            _private_action(x, pr, e.route, e.name)
    stories = [e for e in plan.entities if e.events]
    if not stories:
        # OpenSCENARIO needs at least one Story: a scene where nobody moves holds the AV's standstill explicitly
        ego = plan.entity("ego")
        hold = EventPlan("ego_e0_hold", "", (SpeedAct(ego.speed, "step", "time", 0.0),), Trigger("time", 0.0), 0.0)
        stories = [EntityPlan(ego.name, ego.kind, ego.category, ego.xosc_category, ego.dimensions, ego.start,
                              ego.speed, (hold,), ego.route, ego.external)]
    for e in stories:
        _story(x, sb, e)
    sb.extend(signal_stories)
    stop = x.el(sb, "StopTrigger", xsd_type="Trigger")
    g1 = x.el(stop, "ConditionGroup")
    _condition(x, g1, "time_limit", Trigger("time", plan.time_limit))
    g2 = x.el(stop, "ConditionGroup")
    c = x.el(g2, "Condition", {"name": "ego_goal_reached", "delay": 0.0, "conditionEdge": "none"})
    be = x.el(c, "ByEntityCondition")
    te = x.el(be, "TriggeringEntities", {"triggeringEntitiesRule": "any"})
    x.el(te, "EntityRef", {"entityRef": "ego"})
    ec = x.el(be, "EntityCondition")
    rp = x.el(ec, "ReachPositionCondition", {"tolerance": float(plan.goal_tolerance)})
    _position(x, rp, plan.goal)
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)
