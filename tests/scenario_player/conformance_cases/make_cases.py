"""Writes the conformance cases of this directory (xosc/*.xosc). Run from the repository root:

    python tests/scenario_player/conformance_cases/make_cases.py

The reference trajectories (reference/*.csv) are then recorded with the shared esmini (see README.md)."""

from __future__ import annotations

from pathlib import Path

HERE = Path(__file__).resolve().parent

HEAD = """<?xml version="1.0" encoding="UTF-8"?>
<!-- {comment} -->
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="0" date="2026-11-25T00:00:00" description="{name}" author="txt2sce"/>
  <ParameterDeclarations/>
  <CatalogLocations/>
  <RoadNetwork>
    <LogicFile filepath="../xodr/curve_r100.xodr"/>
  </RoadNetwork>
  <Entities>
{entities}
  </Entities>
  <Storyboard>
    <Init>
      <Actions>
{init}
      </Actions>
    </Init>
{stories}
    <StopTrigger>
      <ConditionGroup>
        <Condition name="stop" delay="0" conditionEdge="rising">
          <ByValueCondition><SimulationTimeCondition value="{end}" rule="greaterThan"/></ByValueCondition>
        </Condition>
      </ConditionGroup>
    </StopTrigger>
  </Storyboard>
</OpenSCENARIO>
"""


def car(name: str) -> str:
    return f"""    <ScenarioObject name="{name}">
      <Vehicle name="{name}" vehicleCategory="car">
        <BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="1.8" length="4.5" height="1.5"/></BoundingBox>
        <Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/>
        <Axles>
          <FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.5" positionX="2.7" positionZ="0.3"/>
          <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.5" positionX="0" positionZ="0.3"/>
        </Axles>
        <Properties/>
      </Vehicle>
    </ScenarioObject>"""


def walker(name: str) -> str:
    return f"""    <ScenarioObject name="{name}">
      <Pedestrian name="{name}" model="adult" mass="75" pedestrianCategory="pedestrian">
        <BoundingBox><Center x="0" y="0" z="0.9"/><Dimensions width="0.5" length="0.5" height="1.8"/></BoundingBox>
        <Properties/>
      </Pedestrian>
    </ScenarioObject>"""


def place(name: str, lane: int, s: float, speed: float, offset: float = 0.0) -> str:
    return f"""        <Private entityRef="{name}">
          <PrivateAction><TeleportAction><Position>
            <LanePosition roadId="0" laneId="{lane}" s="{s}" offset="{offset}"/>
          </Position></TeleportAction></PrivateAction>
          <PrivateAction><LongitudinalAction><SpeedAction>
            <SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/>
            <SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget>
          </SpeedAction></LongitudinalAction></PrivateAction>
        </Private>"""


def at_time(t: float) -> str:
    return f"""<ByValueCondition><SimulationTimeCondition value="{t}" rule="greaterThan"/></ByValueCondition>"""


def after_event(event: str) -> str:
    return f"""<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event"
                 storyboardElementRef="{event}" state="endTransition"/></ByValueCondition>"""


def event(name: str, action: str, condition: str) -> str:
    return f"""          <Event name="{name}" priority="parallel" maximumExecutionCount="1">
            <Action name="{name}_action"><PrivateAction>{action}</PrivateAction></Action>
            <StartTrigger><ConditionGroup>
              <Condition name="{name}_start" delay="0" conditionEdge="none">{condition}</Condition>
            </ConditionGroup></StartTrigger>
          </Event>"""


def story(actor: str, events: list[str]) -> str:
    body = "\n".join(events)
    return f"""    <Story name="{actor}_story">
      <Act name="{actor}_act">
        <ManeuverGroup name="{actor}_mg" maximumExecutionCount="1">
          <Actors selectTriggeringEntities="false"><EntityRef entityRef="{actor}"/></Actors>
          <Maneuver name="{actor}_maneuver">
{body}
          </Maneuver>
        </ManeuverGroup>
        <StartTrigger><ConditionGroup>
          <Condition name="{actor}_act_start" delay="0" conditionEdge="none">{at_time(0)}</Condition>
        </ConditionGroup></StartTrigger>
      </Act>
    </Story>"""


def lane_change(shape: str, rate: float, lane: int) -> str:
    return f"""<LateralAction><LaneChangeAction>
              <LaneChangeActionDynamics dynamicsShape="{shape}" value="{rate}" dynamicsDimension="rate"/>
              <LaneChangeTarget><AbsoluteTargetLane value="{lane}"/></LaneChangeTarget>
            </LaneChangeAction></LateralAction>"""


def speed(value: float, seconds: float) -> str:
    return f"""<LongitudinalAction><SpeedAction>
              <SpeedActionDynamics dynamicsShape="linear" value="{seconds}" dynamicsDimension="time"/>
              <SpeedActionTarget><AbsoluteTargetSpeed value="{value}"/></SpeedActionTarget>
            </SpeedAction></LongitudinalAction>"""


def lane_offset(value: float, max_acc: float) -> str:
    return f"""<LateralAction><LaneOffsetAction continuous="false">
              <LaneOffsetActionDynamics dynamicsShape="sinusoidal" maxLateralAcc="{max_acc}"/>
              <LaneOffsetTarget><AbsoluteTargetLaneOffset value="{value}"/></LaneOffsetTarget>
            </LaneOffsetAction></LateralAction>"""


def trajectory(name: str, points: list[tuple[float, float, float]]) -> str:
    verts = "\n".join(f"""                <Vertex><Position><LanePosition roadId="0" laneId="{lane}" s="{s}" offset="{off}"/>
                </Position></Vertex>""" for lane, s, off in points)
    return f"""<RoutingAction><FollowTrajectoryAction>
              <Trajectory name="{name}" closed="false"><Shape><Polyline>
{verts}
              </Polyline></Shape></Trajectory>
              <TimeReference><None/></TimeReference>
              <TrajectoryFollowingMode followingMode="position"/>
            </FollowTrajectoryAction></RoutingAction>"""


def write(name: str, comment: str, ents: list[str], init: list[str], stories: list[str], end: float) -> None:
    text = HEAD.format(name=name, comment=comment, entities="\n".join(ents), init="\n".join(init),
                       stories="\n".join(stories), end=end)
    (HERE / "xosc" / f"{name}.xosc").write_text(text, encoding="utf-8")


def main() -> None:
    # Rate-based lane changes: the rate is the peak lateral speed of each shape; the speed change that follows each
    # lane change shows when the change ended.
    shapes = [("Sine", "sinusoidal", 0.8), ("Cubic", "cubic", 1.0), ("Linear", "linear", 1.2)]
    write("lane_change_rate", "LaneChangeAction with dynamicsDimension rate (sinusoidal, cubic, linear), then a "
          "speed change triggered by each lane change's end",
          [car(n) for n, _, _ in shapes],
          [place(n, -1, 20.0 + 40.0 * i, 15.0) for i, (n, _, _) in enumerate(shapes)],
          [story(n, [event(f"{n}_change", lane_change(shape, rate, 1), at_time(2.0)),
                     event(f"{n}_speed", speed(25.0, 3.0), after_event(f"{n}_change"))])
           for n, shape, rate in shapes], 14.0)
    # Lateral offsets through a curve (radius 100 m at the reference line): both lanes, both signs, and an offset
    # that is shaped while the curve is driven.
    write("offset_curve", "Driving with a lateral lane offset through a curve: the entity advances at the "
          "radius of its offset path",
          [car("Outer"), car("Inner"), car("Against"), car("Shifting")],
          [place("Outer", -1, 440.0, 20.0, -1.0), place("Inner", -1, 400.0, 20.0, 1.2),
           place("Against", 1, 700.0, 18.0, 1.0), place("Shifting", -1, 470.0, 15.0)],
          [story("Shifting", [event("Shifting_offset", lane_offset(-1.3, 0.4), at_time(2.0)),
                              event("Shifting_back", lane_offset(0.8, 0.4), after_event("Shifting_offset"))])],
          14.0)
    # After a FollowTrajectoryAction ends the entity goes on along the road, in the direction of the road that its
    # heading points along: into the curve, against a lane's driving direction, and off the driving lanes.
    write("trajectory_end", "After FollowTrajectoryAction the entity continues along the road (lane direction "
          "chosen by its heading), not straight on",
          [car("IntoCurve"), car("Across"), walker("WalkerUp"), walker("WalkerDown")],
          [place("IntoCurve", -1, 420.0, 15.0), place("Across", -1, 100.0, 12.0),
           place("WalkerUp", -1, 300.0, 1.5, -3.0), place("WalkerDown", -1, 340.0, 1.5, -3.0)],
          [story("IntoCurve", [event("IntoCurve_traj", trajectory("into_curve", [(-1, 420.0, 0.0), (-1, 450.0, 0.8),
                                                                                  (-1, 480.0, 0.6)]), at_time(0.0))]),
           story("Across", [event("Across_traj", trajectory("across", [(-1, 110.0, 0.0), (-1, 125.0, 0.0),
                                                                      (1, 150.0, 0.0), (1, 160.0, 0.3)]),
                                  at_time(0.5))]),
           story("WalkerUp", [event("WalkerUp_traj", trajectory("walk_up", [(-1, 300.0, -3.0), (-1, 300.6, 0.0),
                                                                           (1, 301.2, 4.0)]), at_time(0.0))]),
           story("WalkerDown", [event("WalkerDown_traj", trajectory("walk_down", [(-1, 340.0, -3.0),
                                                                                 (-1, 339.4, 0.0),
                                                                                 (1, 338.8, 4.0)]),
                                      at_time(0.0))])],
          16.0)


if __name__ == "__main__":
    main()
