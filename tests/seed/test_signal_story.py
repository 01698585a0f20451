"""Signal phases as timed TrafficSignalStateActions (`seed.signal_story`): written and read back, played by the
scenario player at the times the form says."""

from __future__ import annotations

from lxml import etree

from txt2sce_ros.seed.model import SignalPhase, SignalPlan
from txt2sce_ros.seed.signal_story import EarlyStart, colour_of, is_signal_story, lamp_state, read_plan, write_plan

PLAN = SignalPlan("signal_ctrl_9", (SignalPhase("phase_red", 6.0, (("1", "red"), ("2", "green"))),
                                    SignalPhase("phase_green", 4.0, (("1", "green"), ("2", "red")))))


def _starts(story: etree._Element) -> list[tuple[str, float]]:
    return [(e.get("name"), float(next(e.iter("SimulationTimeCondition")).get("value"))) for e in story.iter("Event")]


def test_timed_plan_cycles_until_the_time_limit_and_reads_back() -> None:
    inits, story = write_plan(PLAN, time_limit=21.0)
    assert [next(g.iter("TrafficSignalStateAction")).attrib for g in inits] == [
        {"name": "1", "state": "on;off;off"}, {"name": "2", "state": "off;off;on"}]     # lamps, top to bottom
    # a controller's cycle: red 6 s, green 4 s, red again at 10 s ... while a phase starts before the limit
    assert _starts(story) == [("signal_ctrl_9_phase_green_1", 6.0), ("signal_ctrl_9_phase_red_2", 10.0),
                              ("signal_ctrl_9_phase_green_3", 16.0), ("signal_ctrl_9_phase_red_4", 20.0)]
    assert is_signal_story(story)
    back = read_plan(inits, story)
    assert not back.triggered and back.plan == PLAN


def test_one_phase_plan_still_has_a_story_event() -> None:
    plan = SignalPlan("c", (SignalPhase("phase_green", 40.0, (("1", "green"),)),))
    inits, story = write_plan(plan, time_limit=30.0)
    assert _starts(story) == [("c_phase_green_1", 40.0)]        # past the limit: never fires, but valid XML
    assert read_plan(inits, story).plan == plan


def test_triggered_plan_waits_in_its_last_phase_and_delays_each_phase_from_the_trigger() -> None:
    cond = etree.Element("Condition", name="go", delay="0", conditionEdge="none")
    etree.SubElement(etree.SubElement(cond, "ByValueCondition"), "SimulationTimeCondition", value="3",
                     rule="greaterThan")
    inits, story = write_plan(PLAN, time_limit=60.0, trigger=cond)
    assert [colour_of(next(g.iter("TrafficSignalStateAction")).get("state")) for g in inits] == ["green", "red"]
    delays = [float(e.find("StartTrigger//Condition").get("delay")) for e in story.iter("Event")]
    assert delays == [0.0, 6.0]
    back = read_plan(inits, story)
    assert back.triggered and [p.name for p in back.plan.phases] == ["phase_red", "phase_green"]
    assert back.tested == PLAN.phases[0].states and back.waiting == PLAN.phases[1].states


def test_lamp_strings_round_trip_and_other_texts_pass() -> None:
    for colour in ("red", "yellow", "green"):
        assert colour_of(lamp_state(colour)) == colour
    assert lamp_state("flashing;off;off") == "flashing;off;off"


def _play_lights(tmp_path, inits, story, t_end: float = 5.0) -> dict[float, str]:
    """Light 1010's colour after each step of the player running `inits` + `story` on a straight road with one
    light (the ego stands by it: the story alone switches the lights)."""
    from scenario_player import Simulation, SimulationConfig, load_scenario
    from txt2sce_ros.mapdb.bundled import bundled_map_paths

    xodr = next(p for p in bundled_map_paths() if p.name == "junction4_signal.xodr")
    ga = "".join(etree.tostring(g, encoding="unicode") for g in inits)
    xosc = f"""<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="0" date="2024-01-01T00:00:00"
      description="t" author="t"/><ParameterDeclarations/><CatalogLocations/>
      <RoadNetwork><LogicFile filepath="{xodr}"/></RoadNetwork><Entities><ScenarioObject name="ego"><Vehicle name="car" vehicleCategory="car">
      <BoundingBox><Center x="1.4" y="0" z="0.8"/><Dimensions width="2" length="4.5" height="1.5"/></BoundingBox>
      <Performance maxSpeed="50" maxAcceleration="5" maxDeceleration="9"/><Axles>
      <FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="2.8" positionZ="0.3"/>
      <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0" positionZ="0.3"/></Axles>
      <Properties/></Vehicle></ScenarioObject></Entities>
      <Storyboard><Init><Actions>{ga}<Private entityRef="ego"><PrivateAction><TeleportAction><Position>
      <LanePosition roadId="1" laneId="-2" s="50" offset="0"/></Position></TeleportAction></PrivateAction>
      </Private></Actions></Init>{etree.tostring(story, encoding="unicode")}
      <StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
      <SimulationTimeCondition value="{t_end:g}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
      </StopTrigger></Storyboard></OpenSCENARIO>"""
    path = tmp_path / "lights.xosc"
    path.write_text(xosc, encoding="utf-8")
    sim = Simulation(load_scenario(path), SimulationConfig(ego_mode="storyboard", time_limit=t_end))
    sim.reset()
    shown = {}
    while not sim.done:
        t = sim.world.t
        sim.advance(None)
        shown[round(t, 2)] = colour_of(sim.world.signals.state_text("1010"))
    return shown


def test_the_player_switches_at_the_first_step_after_each_start(tmp_path) -> None:
    # A straight road with one light: the form played by our player (esmini-check compares the same times with
    # esmini's in tests/scenario_player/test_esmini_portability.py).
    inits, story = write_plan(SignalPlan("s", (SignalPhase("a", 1.0, (("1010", "red"),)),
                                              SignalPhase("b", 2.0, (("1010", "green"),)))), time_limit=5.0)
    shown = _play_lights(tmp_path, inits, story)
    assert shown[1.0] == "red" and shown[1.05] == "green"          # started by `t > 1` at the step from 1.05
    assert shown[3.0] == "green" and shown[3.05] == "red"          # the cycle back to phase a at 3 s


def _time_cond(name: str, t: float) -> etree._Element:
    cond = etree.Element("Condition", name=name, delay="0", conditionEdge="none")
    etree.SubElement(etree.SubElement(cond, "ByValueCondition"), "SimulationTimeCondition", value=f"{t:g}",
                     rule="greaterThan")
    return cond


YELLOW = SignalPlan("s", (SignalPhase("y", 3.0, (("1010", "yellow"),)), SignalPhase("r", 2.0, (("1010", "red"),)),
                          SignalPhase("g", 0.0, (("1010", "green"),))))


def test_an_early_start_brings_phase_one_forward_once_phase_zero_has_shown_its_minimum(tmp_path) -> None:
    # yellow from t > 1 for 3 s (red at 4), but red as soon as t > 2.5 once the yellow has shown 1 s
    early = EarlyStart(1.0, _time_cond("soon", 2.5))
    inits, story = write_plan(YELLOW, time_limit=8.0, trigger=_time_cond("go", 1.0), early=early)
    red = [e for e in story.iter("Event") if e.get("name") == "s_r"][0]
    groups = red.findall("StartTrigger/ConditionGroup")
    assert [[(c.get("name"), c.get("delay")) for c in g] for g in groups] == [
        [("go_r", "3")], [("go_r_shown", "1"), ("go_r_early", "0")]]
    # read back, the plan is the one written without the early start (its first group gives the durations)
    assert read_plan(inits, story) == read_plan(*write_plan(YELLOW, time_limit=8.0, trigger=_time_cond("go", 1.0)))
    shown = _play_lights(tmp_path, inits, story, t_end=8.0)
    assert shown[1.0] == "green" and shown[1.05] == "yellow"
    assert shown[2.5] == "yellow" and shown[2.55] == "red"         # early: 1.5 s of yellow
    assert shown[6.0] == "red" and shown[6.05] == "green"         # the later phases keep their offsets
    # a condition that holds before the minimum waits for it: red 1 s after the yellow began, not at t > 1.2
    inits, story = write_plan(YELLOW, time_limit=8.0, trigger=_time_cond("go", 1.0),
                              early=EarlyStart(1.0, _time_cond("soon", 1.2)))
    shown = _play_lights(tmp_path, inits, story, t_end=8.0)
    assert shown[2.0] == "yellow" and shown[2.05] == "red"
    # one that never holds leaves the red at its time
    inits, story = write_plan(YELLOW, time_limit=8.0, trigger=_time_cond("go", 1.0),
                              early=EarlyStart(1.0, _time_cond("never", 99.0)))
    shown = _play_lights(tmp_path, inits, story, t_end=8.0)
    assert shown[4.0] == "yellow" and shown[4.05] == "red"
