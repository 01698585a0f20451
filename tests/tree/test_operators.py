"""The nine Table III operators on the fixture seeds: ranges, enumerations, context checks, schema validity."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from txt2sce_ros.errors import InputError
from txt2sce_ros.seed.signal_story import read_plan
from txt2sce_ros.tree import BlockKind, assemble, disassemble
from txt2sce_ros.tree.build import tree_config
from txt2sce_ros.tree.environment import signal_timing
from txt2sce_ros.seed.context import build_context, lane_pos
from txt2sce_ros.tree.mutate import block_variants
from txt2sce_ros.tree.trajectory import feasible_s
from txt2sce_ros.tree.values import Recorder
from txt2sce_ros.tree.xml import parse_bytes, parse_fragment
from txt2sce_ros.xosc.validate import validate_xosc

from .conftest import CUT_IN, JUNCTION


def _setup(path: Path, cfg):
    data = path.read_bytes()
    ctx = build_context(parse_bytes(data, str(path)), source=str(path), seed_path=path)
    d = disassemble(data, source=str(path), new_obstacle_slots=1)
    return d, ctx


def _variants(path, cfg, key, seed=0):
    d, ctx = _setup(path, cfg)
    block = next(b for b in d.blocks if b.key == key)
    return d, block, block_variants(block, ctx, cfg, seed=seed, seed_key=11), ctx


def _valid_with(d, block, variant) -> list[str]:
    frags = d.originals()
    for slot, frag in zip(block.slots, variant.fragments):
        frags[slot] = frag
    return validate_xosc(assemble(d.template, frags))


def test_wm_enumerates_weather_types_with_ranged_parameters(cfg):
    d, block, vs, _ = _variants(JUNCTION, cfg, "environment")
    assert [v.features[1] for v in vs] == ["sunny", "cloudy", "rainy", "foggy", "snowy"]
    spec = cfg["environment"]["weather"]
    for v in vs:
        env = parse_fragment(v.fragments[0])
        kind = v.features[1]
        fric = float(env.find("RoadCondition").get("frictionScaleFactor"))
        vis = float(env.find("Weather/Fog").get("visualRange"))
        prec = env.find("Weather/Precipitation")
        assert spec[kind]["friction"][0] <= fric <= spec[kind]["friction"][1]
        assert spec[kind]["visibility"][0] <= vis <= spec[kind]["visibility"][1]
        assert prec.get("precipitationType") == spec[kind]["precipitationType"]
        assert 0 <= float(env.find("Weather/Sun").get("azimuth")) <= 2 * np.pi
        assert _valid_with(d, block, v) == []
    rainy = parse_fragment(next(v for v in vs if v.features[1] == "rainy").fragments[0])
    assert 0.5 <= float(rainy.find("Weather/Precipitation").get("intensity")) <= 1.0
    assert 0.2 <= float(rainy.find("RoadCondition").get("frictionScaleFactor")) <= 0.5


def test_tsm_and_dtm_stay_in_table_iii_ranges(cfg):
    for seed in range(6):
        d, block, vs, _ = _variants(JUNCTION, cfg, "npc1_e2_turn_left", seed=seed)
        assert len(vs) == 2
        for v in vs:
            ev = parse_fragment(v.fragments[0])
            speed = float(next(ev.iter("AbsoluteTargetSpeed")).get("value"))
            style = v.features[2]
            assert style in ("acc", "dec")
            lo, hi = (4.0, 6.0) if style == "acc" else (2.0, 4.0)
            assert lo - 1e-3 <= speed <= hi + 1e-3
            dyn = next(ev.iter("SpeedActionDynamics"))
            assert dyn.get("dynamicsShape") in ("linear", "cubic", "sinusoidal", "step")
            assert 1.0 <= float(dyn.get("value")) <= 10.0
            assert v.operator == "TSM+DTM"
            assert _valid_with(d, block, v) == []


def test_tsm_direction_follows_the_action_name(cfg):
    ev = parse_fragment(disassemble(JUNCTION.read_bytes()).blocks[4].fragments[0])
    from txt2sce_ros.tree.dynamics import tsm

    rng = np.random.default_rng(0)
    rec = Recorder()
    assert tsm(ev, "decelerate", rng, cfg["dynamics"]["tsm"], rec) == "dec"
    assert 3.0 <= float(next(ev.iter("AbsoluteTargetSpeed")).get("value")) <= 6.0
    assert tsm(ev, "accelerate", rng, cfg["dynamics"]["tsm"], rec) == "acc"
    assert len(rec.changes) == 2 and rec.changes[0].old == "6.0"


def test_ncm_enumerates_categories_and_model_follows(cfg):
    d, block, vs, _ = _variants(JUNCTION, cfg, "npc1")
    assert [v.features[1] for v in vs] == ["car", "van", "truck", "bus", "motorcycle", "bicycle", "pedestrian"]
    cats = cfg["physical"]["categories"]
    for v in vs:
        obj = parse_fragment(v.fragments[0])
        cat = v.features[1]
        ent = obj[0]
        assert ent.tag == cats[cat]["element"]
        dims = ent.find("BoundingBox/Dimensions")
        for attr, lo, hi in zip(("width", "length", "height"), cats[cat]["lo"], cats[cat]["hi"]):
            assert lo <= float(dims.get(attr)) <= hi  # DM bounded per category
        if ent.tag == "Vehicle":
            assert ent.get("vehicleCategory") == cats[cat]["osc"]
            perf = ent.find("Performance")
            assert 0.5 * cats[cat]["perf"][0] <= float(perf.get("maxSpeed")) <= 1.5 * cats[cat]["perf"][0]
        else:
            assert ent.get("model") == "pedestrian" and ent.find("Performance") is None
            # a pedestrian does not start at the car's 6 m/s
            priv = parse_fragment(v.fragments[1])
            assert float(next(priv.iter("AbsoluteTargetSpeed")).get("value")) <= cats[cat]["speed"]
        assert _valid_with(d, block, v) == []


def test_tls_enumerates_states_and_conflicting_signals_follow(cfg):
    d, block, vs, _ = _variants(JUNCTION, cfg, "signal_ctrl_4")
    # yellow first (config environment.signal_states): the state a one-node budget keeps
    assert [v.features for v in vs] == [("signal", "yellow", "yellow/red/red"), ("signal", "red", "red/green/green"),
                                        ("signal", "green", "green/red/red")]
    timing = signal_timing()
    expected = {  # (phase, duration, state of the primary signal 1, state of the conflicting signals 2 and 3)
        "green": [("tls_green", timing.hold, "green", "red")],
        "yellow": [("tls_yellow", timing.yellow, "yellow", "red"),
                   ("tls_red", timing.red - timing.yellow, "red", "green"),
                   ("tls_red_clear", timing.yellow, "red", "yellow"), ("tls_green", timing.hold, "green", "red")],
        "red": [("tls_red", timing.red - timing.yellow, "red", "green"),
                ("tls_red_clear", timing.yellow, "red", "yellow"), ("tls_green", timing.hold, "green", "red")],
    }
    for v in vs:
        parts = [parse_fragment(f) for f in v.fragments]
        plan = read_plan(parts[:-1], parts[-1]).plan
        want = expected[v.features[1]]
        assert [tuple(dict(p.states)[sid] for sid in ("1", "2", "3")) for p in plan.phases] == [
            (a, b, b) for _, _, a, b in want]
        # Read back from the timed state actions: every phase's start, so all durations but the last (which
        # outlasts the run) and all names but the first (shown by the Init actions)
        assert [p.duration for p in plan.phases[:-1]] == [dur for _, dur, _, _ in want[:-1]]
        assert [p.name for p in plan.phases[1:]] == [n for n, _, _, _ in want[1:]]
        assert not any(e.tag == "TrafficSignalController" for part in parts for e in part.iter())
        assert _valid_with(d, block, v) == []
    # Even green rewrites the seed's cycle (green 20 s, then yellow, then red): green now holds for the run.
    assert [c.new for c in vs[2].changes] == [f"tls_green:{timing.hold:g} (green)"]


def test_tls_states_hold_their_meaning_in_the_player(cfg):
    # Played by the scenario player — a mutated yellow turns red after `yellow` s, a red turns green after `red` s.
    # The fixture's ego faces none of the map's signals, so its yellow shows from t = 0 (no dilemma-zone trigger;
    # that one is tested in test_dilemma_yellow.py).
    # The ego gets no command (it stands); the NPC's scripted path hits it, so contact must not end the run.
    from scenario_player import Simulation, SimulationConfig, load_scenario

    d, block, vs, _ = _variants(JUNCTION, cfg, "signal_ctrl_4")
    timing = signal_timing()
    xodr = (JUNCTION.parent / etree.fromstring(JUNCTION.read_bytes()).find(".//LogicFile").get("filepath")).resolve()
    seen = {}
    for v in vs:
        frags = d.originals()
        for slot, frag in zip(block.slots, v.fragments):
            frags[slot] = frag
        sim = Simulation(load_scenario(assemble(d.template, frags), source=str(JUNCTION),
                                       map_path=str(xodr)), SimulationConfig(ego_mode="planner", time_limit=30.0,
                                                                        stop_on_ego_collision=False))
        frame, states = sim.reset(), {}
        while frame.t < timing.yellow + timing.red + 0.5 and not sim.done:
            states[round(frame.t, 2)] = {l.id: l.state.value for l in frame.lights}["1"]
            frame = sim.step()
        seen[v.features[1]] = states
        assert max(states) >= timing.yellow + timing.red, (v.features, max(states), sim.end_reason)
    # A phase starting at T is started by `SimulationTime > T`: its actions run in the first step after T and
    # show from the frame after that (T + 0.1 s at 20 Hz), exactly as esmini runs them (esmini-check compares).
    y, r, late = timing.yellow, timing.red, 0.1
    assert {seen["green"][t] for t in seen["green"]} == {"green"}
    assert seen["yellow"][0.0] == seen["yellow"][round(y + late - 0.05, 2)] == "yellow"
    # (the run ends at y + r = 16 s, when the standing ego counts as at its goal: red until then)
    assert {seen["yellow"][t] for t in seen["yellow"] if t >= y + late} == {"red"}
    assert seen["red"][0.0] == seen["red"][round(r + late - 0.05, 2)] == "red" and seen["red"][r + late] == "green"


def test_wpm_lane_change_offset_keeps_entity_in_its_lane(cfg):
    d, block, vs, ctx = _variants(CUT_IN, cfg, "npc1_e2_lane_change_right")
    lane_w = ctx.map.lane_width("0", -2, 80.0)
    for seed in range(5):
        _, _, vs, _ = _variants(CUT_IN, cfg, "npc1_e2_lane_change_right", seed=seed)
        for v in vs:
            assert "WPM" in v.operator and "DTM" in v.operator and "TSM" not in v.operator
            lc = next(parse_fragment(v.fragments[0]).iter("LaneChangeAction"))
            off = float(lc.get("targetLaneOffset"))
            assert abs(off) <= (lane_w - 1.8) / 2 + 1e-6
            dyn = lc.find("LaneChangeActionDynamics")
            assert 1.0 <= float(dyn.get("value")) <= 10.0  # dimension 'time'
            assert _valid_with(d, block, v) == []


def test_initial_location_is_context_aware(cfg):
    """The NPC turning left from road 0 lane 1 (driving toward s=0) must start upstream of its route's first
    waypoint (s=10) and its trigger (s=15) by the margin, on the same drivable lane."""
    d, ctx = _setup(JUNCTION, cfg)
    start = ctx.starts["npc1"]
    margin = cfg["trajectory"]["init_location"]["margin"]
    assert feasible_s(ctx, "npc1", start, 45.0 + 8.0, margin)
    assert not feasible_s(ctx, "npc1", start, 19.0, margin)     # too close to the trigger at s=15
    assert not feasible_s(ctx, "npc1", start, 200.0, margin)    # past the road's end (93.7 m)
    ego = ctx.starts["ego"]                                      # road 2 lane -1 at s=250, obs1 at s=280
    assert feasible_s(ctx, "ego", ego, 245.0, margin)
    assert not feasible_s(ctx, "ego", ego, 276.0, margin)        # 4 m behind the obstacle in its lane
    assert not feasible_s(ctx, "ego", ego, 290.0, margin)        # past it
    for seed in range(8):
        _, block, vs, _ = _variants(JUNCTION, cfg, "npc1", seed=seed)
        for v in vs:
            s = float(parse_fragment(v.fragments[1]).find(".//TeleportAction//LanePosition").get("s"))
            assert feasible_s(ctx, "npc1", start, s, margin) or s == 45.0
    _, block, vs, _ = _variants(JUNCTION, cfg, "ego")
    assert [v.operator for v in vs].count("TSM-start") == 1
    for v in vs:
        priv = parse_fragment(v.fragments[0])
        tele = lane_pos(priv.find(".//TeleportAction//LanePosition"))
        first_wp = lane_pos(priv.find(".//Route/Waypoint/Position/LanePosition"))
        speed = float(priv.find(".//LongitudinalAction//AbsoluteTargetSpeed").get("value"))
        if v.operator == "TSM-start":    # the standing start: same place, speed 0
            assert tele.s == 250.0 and speed == 0.0 and v.features[-1] == "standing"
        else:
            assert tele == first_wp and tele.s != 250.0  # the route starts where the ego now starts
            assert speed > 0.0 and v.features[-1] == "moving"


def test_oim_places_obstacles_on_the_av_path(cfg):
    d, ctx = _setup(JUNCTION, cfg)
    ego = ctx.starts["ego"]
    seen_roads = set()
    for seed in range(10):
        _, block, vs, _ = _variants(JUNCTION, cfg, "obs2", seed=seed)
        assert len(vs) == 2 and all(v.operator == "OIM" for v in vs)
        for v in vs:
            obj, priv = (parse_fragment(f) for f in v.fragments)
            dims = obj.find("MiscObject/BoundingBox/Dimensions")
            for attr, lo, hi in zip(("width", "length", "height"), cfg["environment"]["obstacle"]["dims_lo"],
                                    cfg["environment"]["obstacle"]["dims_hi"]):
                assert lo <= float(dims.get(attr)) <= hi
            pos = lane_pos(priv.find(".//LanePosition"))
            seen_roads.add(pos.road)
            assert pos.road in {w.road for w in ctx.ego_route} | {ego.road}
            assert ctx.map.lane_type(pos.road, pos.lane, pos.s) == "driving"
            assert abs(pos.offset) <= (ctx.map.lane_width(pos.road, pos.lane, pos.s) - float(dims.get("width"))) / 2 + 1e-3
            if pos.road == ego.road:
                assert 15.0 - 1e-6 <= pos.s - ego.s <= 60.0 + 1e-6  # ahead of the AV (lane -1 drives +s)
            assert _valid_with(d, block, v) == []
    assert seen_roads == {"2", "0"}  # the path continues past the junction onto the goal road


def test_values_are_checked_against_the_entity_database():
    rec = Recorder()
    el = etree.Element("Weather", cloudState="free")
    with pytest.raises(InputError, match="cloudState"):
        rec.set(el, "cloudState", "drizzle")
    with pytest.raises(InputError, match="intensity"):
        rec.set(etree.Element("Precipitation"), "intensity", 1.7)  # documented range [0, 1]
    assert rec.set(el, "cloudState", "rainy") == "rainy" and rec.changes[-1].old == "free"
    whole = etree.fromstring('<Vehicle name="x" vehicleCategory="car"><Performance maxSpeed="-3" '
                             'maxAcceleration="1" maxDeceleration="1"/></Vehicle>')
    with pytest.raises(InputError, match="maxSpeed"):
        rec.check_tree(whole)  # elements written whole are checked attribute by attribute


def test_obstacle_block_dm_and_relocation(cfg):
    d, block, vs, ctx = _variants(JUNCTION, cfg, "obs1")
    assert block.kind is BlockKind.OBSTACLE and len(vs) == 2
    for v in vs:
        assert v.operator == "DM+OIM"
        assert _valid_with(d, block, v) == []


def test_one_weather_classifier_reads_every_wm_variant_back(cfg):
    # The tree's features and the analysis's `weather:` elements share tree.environment.weather_type: every
    # weather the WM operator writes is read back as its own type, and the analysis labels it the same way.
    from lxml import etree

    from txt2sce_ros.analysis.features import WEATHER_LABELS, weather_label
    from txt2sce_ros.tree.environment import weather_type

    for seed in range(4):
        _, _, vs, _ = _variants(JUNCTION, cfg, "environment", seed=seed)
        for v in vs:
            env = parse_fragment(v.fragments[0])
            assert weather_type(env) == v.features[1]
            wrapped = etree.fromstring("<Init><EnvironmentAction/></Init>")
            wrapped[0].append(env)
            assert weather_label(wrapped) == WEATHER_LABELS[v.features[1]]
    # fog is visibility under 1 km on a dry road; a rain type with zero intensity is dry
    dry_fog = etree.fromstring('<Environment><Weather cloudState="free"><Fog visualRange="600"/>'
                               '<Precipitation precipitationType="rain" intensity="0"/></Weather></Environment>')
    assert weather_type(dry_fog) == "foggy"
