"""Write the stand-in planner's check scenarios (OpenSCENARIO 1.0, seed naming of docs/seed_format.md) on the
bundled maps: `python examples/scenarios/build.py` regenerates every `.xosc` beside this file.

- `benign_*`: no conflicting party; the nominal planner must reach the goal with no oracle violation
  (`txt2sce planner-check` runs them).
- `fault_*`: one scenario per fault mode, built to expose it (see standin_planner/faults.py); the test suite runs
  each with the fault on and off (tests/standin_planner/test_fault_scenarios.py).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
MAPS = "../../txt2sce_ros/data/maps"

VEHICLE_CATEGORY = {"car": "car", "van": "van", "truck": "truck", "bus": "bus", "motorcycle": "motorbike",
                    "bicycle": "bicycle", "scooter": "bicycle", "parked_vehicle": "car"}
DIMS = {"car": (4.5, 1.8, 1.5, 1.4), "parked_vehicle": (4.5, 1.8, 1.5, 1.4), "bicycle": (1.8, 0.6, 1.7, 0.0),
        "truck": (8.0, 2.5, 3.0, 2.5)}


@dataclass(frozen=True)
class Lane:
    road: str
    lane: int
    s: float
    offset: float = 0.0

    def xml(self) -> str:
        return (f'<LanePosition roadId="{self.road}" laneId="{self.lane}" s="{self.s}" '
                f'offset="{self.offset}"/>')


@dataclass(frozen=True)
class Event:
    """One NPC event: start time (s) and either a speed change or a lane change."""

    name: str
    t: float
    speed: float | None = None
    rate: float = 2.0                 # m/s² for speed changes
    lane_change_to: int | None = None
    lane_change_time: float = 2.0


@dataclass(frozen=True)
class Npc:
    name: str
    category: str
    start: Lane
    speed: float = 0.0
    events: tuple[Event, ...] = ()


@dataclass(frozen=True)
class Scenario:
    name: str
    map: str
    ego: Lane
    goal: Lane
    ego_speed: float = 0.0
    friction: float = 1.0
    npcs: tuple[Npc, ...] = ()
    signals: tuple[tuple[str, float, tuple[tuple[str, str], ...]], ...] = ()   # (phase, duration, ((id, state)…))
    time_limit: float = 90.0
    note: str = ""
    weather: str = "dry"


def _vehicle(name: str, category: str, external: bool = False) -> str:
    length, width, height, cx = DIMS.get(category, DIMS["car"])
    ctrl = ""
    if external:
        ctrl = """
      <ObjectController>
        <Controller name="ads_under_test">
          <Properties>
            <Property name="esminiController" value="ExternalController"/>
            <Property name="txt2sce:controller" value="external"/>
          </Properties>
        </Controller>
      </ObjectController>"""
    return f"""    <ScenarioObject name="{name}">
      <Vehicle name="{name}" vehicleCategory="{VEHICLE_CATEGORY.get(category, 'car')}">
        <BoundingBox>
          <Center x="{cx}" y="0.0" z="{height / 2}"/>
          <Dimensions width="{width}" length="{length}" height="{height}"/>
        </BoundingBox>
        <Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/>
        <Axles>
          <FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="{width}" positionX="2.8" positionZ="0.3"/>
          <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="{width}" positionX="0" positionZ="0.3"/>
        </Axles>
        <Properties>
          <Property name="txt2sce:category" value="{category}"/>
        </Properties>
      </Vehicle>{ctrl}
    </ScenarioObject>
"""


def _speed(value: float, rate: float | None = None) -> str:
    dyn = ('<SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/>' if rate is None else
           f'<SpeedActionDynamics dynamicsShape="linear" value="{rate}" dynamicsDimension="rate"/>')
    return f"""<PrivateAction>
            <LongitudinalAction>
              <SpeedAction>
                {dyn}
                <SpeedActionTarget>
                  <AbsoluteTargetSpeed value="{value}"/>
                </SpeedActionTarget>
              </SpeedAction>
            </LongitudinalAction>
          </PrivateAction>"""


def _teleport(pos: Lane) -> str:
    return f"""<PrivateAction>
            <TeleportAction>
              <Position>
                {pos.xml()}
              </Position>
            </TeleportAction>
          </PrivateAction>"""


def _event_action(ev: Event) -> str:
    if ev.lane_change_to is not None:
        return f"""<PrivateAction>
                  <LateralAction>
                    <LaneChangeAction>
                      <LaneChangeActionDynamics dynamicsShape="sinusoidal" value="{ev.lane_change_time}" dynamicsDimension="time"/>
                      <LaneChangeTarget>
                        <AbsoluteTargetLane value="{ev.lane_change_to}"/>
                      </LaneChangeTarget>
                    </LaneChangeAction>
                  </LateralAction>
                </PrivateAction>"""
    assert ev.speed is not None
    return _speed(ev.speed, ev.rate)


def _story(npc: Npc) -> str:
    if not npc.events:
        return ""
    events = []
    for k, ev in enumerate(npc.events, start=1):
        ename = f"{npc.name}_e{k}_{ev.name}"
        events.append(f"""            <Event name="{ename}" priority="parallel">
              <Action name="{ename}_action">
                {_event_action(ev)}
              </Action>
              <StartTrigger>
                <ConditionGroup>
                  <Condition name="{ename}_start" delay="0" conditionEdge="rising">
                    <ByValueCondition>
                      <SimulationTimeCondition value="{ev.t}" rule="greaterThan"/>
                    </ByValueCondition>
                  </Condition>
                </ConditionGroup>
              </StartTrigger>
            </Event>""")
    body = "\n".join(events)
    return f"""    <Story name="{npc.name}_story">
      <Act name="{npc.name}_act">
        <ManeuverGroup name="{npc.name}_mg" maximumExecutionCount="1">
          <Actors selectTriggeringEntities="false">
            <EntityRef entityRef="{npc.name}"/>
          </Actors>
          <Maneuver name="{npc.name}_maneuver">
{body}
          </Maneuver>
        </ManeuverGroup>
        <StartTrigger>
          <ConditionGroup>
            <Condition name="{npc.name}_act_start" delay="0" conditionEdge="none">
              <ByValueCondition>
                <SimulationTimeCondition value="0" rule="greaterThan"/>
              </ByValueCondition>
            </Condition>
          </ConditionGroup>
        </StartTrigger>
      </Act>
    </Story>
"""


def _signals(sc: Scenario) -> str:
    if not sc.signals:
        return ""
    phases = []
    for name, duration, states in sc.signals:
        rows = "\n".join(f'          <TrafficSignalState trafficSignalId="{sid}" state="{st}"/>' for sid, st in states)
        phases.append(f'        <Phase name="{name}" duration="{duration}">\n{rows}\n        </Phase>')
    body = "\n".join(phases)
    return f"""    <TrafficSignals>
      <TrafficSignalController name="signal_ctrl_100">
{body}
      </TrafficSignalController>
    </TrafficSignals>
"""


def render(sc: Scenario) -> str:
    entities = _vehicle("ego", "car", external=True) + "".join(_vehicle(n.name, n.category) for n in sc.npcs)
    npc_init = "".join(f"""        <Private entityRef="{n.name}">
          {_teleport(n.start)}
          {_speed(n.speed)}
        </Private>
""" for n in sc.npcs)
    precipitation = "rain" if sc.weather == "rain" else "dry"
    intensity = "0.8" if sc.weather == "rain" else "0.0"
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<!-- {sc.note} -->
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="0" date="2026-11-21T00:00:00" description="txt2sce planner check {sc.name}" author="txt2sce"/>
  <ParameterDeclarations/>
  <CatalogLocations/>
  <RoadNetwork>
    <LogicFile filepath="{MAPS}/{sc.map}"/>
{_signals(sc)}  </RoadNetwork>
  <Entities>
{entities}  </Entities>
  <Storyboard>
    <Init>
      <Actions>
        <GlobalAction>
          <EnvironmentAction>
            <Environment name="environment">
              <TimeOfDay animation="false" dateTime="2026-06-01T12:00:00"/>
              <Weather cloudState="{'overcast' if sc.weather == 'rain' else 'free'}">
                <Sun intensity="1.0" azimuth="0.0" elevation="1.2"/>
                <Fog visualRange="100000"/>
                <Precipitation precipitationType="{precipitation}" intensity="{intensity}"/>
              </Weather>
              <RoadCondition frictionScaleFactor="{sc.friction}"/>
            </Environment>
          </EnvironmentAction>
        </GlobalAction>
        <Private entityRef="ego">
          {_teleport(sc.ego)}
          {_speed(sc.ego_speed)}
          <PrivateAction>
            <RoutingAction>
              <AssignRouteAction>
                <Route name="ego_route" closed="false">
                  <Waypoint routeStrategy="shortest">
                    <Position>
                      {sc.ego.xml()}
                    </Position>
                  </Waypoint>
                  <Waypoint routeStrategy="shortest">
                    <Position>
                      {sc.goal.xml()}
                    </Position>
                  </Waypoint>
                </Route>
              </AssignRouteAction>
            </RoutingAction>
          </PrivateAction>
        </Private>
{npc_init}      </Actions>
    </Init>
{''.join(_story(n) for n in sc.npcs)}    <StopTrigger>
      <ConditionGroup>
        <Condition name="time_limit" delay="0" conditionEdge="rising">
          <ByValueCondition>
            <SimulationTimeCondition value="{sc.time_limit}" rule="greaterThan"/>
          </ByValueCondition>
        </Condition>
      </ConditionGroup>
      <ConditionGroup>
        <Condition name="ego_goal_reached" delay="0" conditionEdge="rising">
          <ByEntityCondition>
            <TriggeringEntities triggeringEntitiesRule="any">
              <EntityRef entityRef="ego"/>
            </TriggeringEntities>
            <EntityCondition>
              <ReachPositionCondition tolerance="3.0">
                <Position>
                  {sc.goal.xml()}
                </Position>
              </ReachPositionCondition>
            </EntityCondition>
          </ByEntityCondition>
        </Condition>
      </ConditionGroup>
    </StopTrigger>
  </Storyboard>
</OpenSCENARIO>
"""


J4 = "junction4_signal.xodr"
# East-west green for through traffic and left arrows alike (the oracle reads a stop line 5 m either side when it
# cannot tell lanes, so neighbouring heads of one approach show the same colour in these scenarios).
WEST_GREEN = (("1010", "green"), ("1030", "green"), ("1011", "green"), ("1031", "green"), ("1020", "red"),
              ("1040", "red"), ("1021", "red"), ("1041", "red"))

SCENARIOS: tuple[Scenario, ...] = (
    # --- benign: no conflicting party ---------------------------------------------------------------------------
    Scenario("benign_straight", "straight_3x3.xodr", Lane("1", -2, 20.0), Lane("1", -2, 300.0),
             note="Straight three-lane road, from standstill to a goal 280 m ahead."),
    Scenario("benign_lane_change", "straight_3x3.xodr", Lane("1", -1, 20.0), Lane("1", -3, 300.0), ego_speed=8.0,
             note="The goal lies two lanes to the right: the route changes lanes twice."),
    Scenario("benign_curve", "curve.xodr", Lane("1", -1, 20.0), Lane("1", -1, 450.0), ego_speed=5.0,
             note="Curved road: the curve speed limit keeps the yaw rate inside the smoothness band."),
    Scenario("benign_junction_left", J4, Lane("3", -1, 80.0), Lane("2", 2, 120.0),
             signals=(("ew_green", 120.0, WEST_GREEN),),
             note="Left turn through the signalised 4-way junction on a green arrow."),
    Scenario("benign_junction_straight", J4, Lane("3", -2, 60.0), Lane("1", 2, 120.0),
             signals=(("ew_green", 120.0, WEST_GREEN),),
             note="Straight through the signalised 4-way junction on green."),
    Scenario("benign_junction_right", J4, Lane("3", -3, 80.0), Lane("4", 3, 120.0),
             signals=(("ew_green", 120.0, WEST_GREEN),),
             note="Right turn at the signalised 4-way junction."),
    Scenario("benign_red_then_green", J4, Lane("3", -2, 100.0), Lane("1", 2, 120.0),
             signals=(("ew_red", 12.0, tuple((sid, "red") for sid, _ in WEST_GREEN)),
                      ("ew_green", 120.0, WEST_GREEN)),
             note="Red on approach: stop at the line, go on green."),
    Scenario("benign_stop_t_junction", "junction3_stop.xodr", Lane("3", -1, 100.0), Lane("1", 1, 120.0),
             note="T junction: turn from the minor road."),
    Scenario("benign_roundabout", "roundabout.xodr", Lane("1", -1, 30.0), Lane("3", 1, 100.0),
             note="Through a single-lane roundabout, leaving at the second exit."),
    Scenario("benign_parked_car", "straight_3x3.xodr", Lane("1", -1, 20.0), Lane("1", -1, 250.0), ego_speed=8.0,
             npcs=(Npc("obs1", "parked_vehicle", Lane("1", -1, 120.0)),),
             note="A parked car blocks the ego's lane; the lane to the right is free: pass it there."),
    Scenario("benign_wet_straight", "straight_3x3.xodr", Lane("1", -1, 20.0), Lane("1", -1, 250.0), friction=0.4,
             weather="rain", note="Wet road (friction 0.4): start and stop without slipping."),
    # --- one scenario per fault mode ------------------------------------------------------------------------------
    Scenario("fault_ignore_cyclists", "straight_3x3.xodr", Lane("1", -1, 20.0), Lane("1", -1, 220.0),
             ego_speed=8.0, npcs=(Npc("npc1", "bicycle", Lane("1", -1, 70.0), speed=3.0),),
             note="A cyclist rides ahead in the ego's lane at 3 m/s: follow it, or (ignore_cyclists) hit it."),
    Scenario("fault_late_braking_low_friction", "straight_3x3.xodr", Lane("1", -1, 20.0), Lane("1", -1, 250.0),
             ego_speed=10.0, friction=0.3, weather="rain",
             npcs=(Npc("npc1", "car", Lane("1", -1, 140.0),
                       events=(Event("start", 30.0, speed=8.0, rate=1.5),)),),
             note="Wet road (friction 0.3), a car stands in the lane 120 m ahead (it drives off at 30 s): stop "
                  "in time, or (late braking ignoring friction) slide into it."),
    Scenario("fault_no_start_when_close", "straight_3x3.xodr", Lane("1", -1, 30.0), Lane("1", -1, 200.0),
             npcs=(Npc("npc1", "car", Lane("1", -1, 23.5)),),
             note="A car stands 2 m behind the ego at the start; the lane ahead is clear."),
    Scenario("fault_stale_tracking", "straight_3x3.xodr", Lane("1", -1, 20.0), Lane("1", -1, 300.0),
             ego_speed=10.0,
             npcs=(Npc("npc1", "car", Lane("1", -2, 55.0), speed=6.0,
                       events=(Event("lane_change_left", 5.0, lane_change_to=-1, lane_change_time=1.5),
                               Event("decelerate", 6.0, speed=1.0, rate=4.0),
                               Event("accelerate", 14.0, speed=10.0, rate=2.0))),),
             note="A slower car cuts in ahead and brakes: a tracker a second late reacts too late."),
    Scenario("fault_aggressive_start", "straight_3x3.xodr", Lane("1", -1, 20.0), Lane("1", -1, 150.0),
             friction=0.35, weather="rain",
             note="Standstill start on a wet road (friction 0.35): full throttle with steering spins the wheels."),
    Scenario("fault_red_light_misread", J4, Lane("3", -2, 60.0), Lane("1", 2, 120.0), ego_speed=10.0,
             signals=(("ew_green", 9.0, WEST_GREEN),
                      ("ew_yellow", 4.0, tuple((sid, "yellow" if st == "green" else st) for sid, st in WEST_GREEN)),
                      ("ew_red", 12.0, tuple((sid, "red") for sid, _ in WEST_GREEN)),
                      ("ew_green_again", 120.0, WEST_GREEN)),
             note="The light turns yellow while the ego can still stop comfortably, red 4 s later."),
)


def main() -> int:
    for sc in SCENARIOS:
        (HERE / f"{sc.name}.xosc").write_text(render(sc), encoding="utf-8")
    print(f"wrote {len(SCENARIOS)} scenarios to {HERE}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
