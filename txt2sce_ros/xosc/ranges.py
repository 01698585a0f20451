"""Numeric ranges of OpenSCENARIO attributes.

The 1.0 XSD types every number as `Double`/`UnsignedInt`… with no facets: the ranges live in the standard's prose
(the 1.0 model documentation). These are the ones the seed writer and the mutators touch, written down once so
both check against the same table. Keys are (complex type, attribute); bounds are inclusive, None = open.
"""

from __future__ import annotations

import math

INF = None

#: (type, attribute) -> (min, max), from the ASAM OpenSCENARIO 1.0 model documentation.
DOCUMENTED_RANGES: dict[tuple[str, str], tuple[float | None, float | None]] = {
    ("Precipitation", "intensity"): (0.0, 1.0),
    ("Fog", "visualRange"): (0.0, INF),
    ("Sun", "intensity"): (0.0, INF),
    ("Sun", "azimuth"): (0.0, 2 * math.pi),
    ("Sun", "elevation"): (-math.pi, math.pi),
    ("RoadCondition", "frictionScaleFactor"): (0.0, INF),
    ("Performance", "maxSpeed"): (0.0, INF),
    ("Performance", "maxAcceleration"): (0.0, INF),
    ("Performance", "maxDeceleration"): (0.0, INF),
    ("Dimensions", "width"): (0.0, INF),
    ("Dimensions", "length"): (0.0, INF),
    ("Dimensions", "height"): (0.0, INF),
    ("Vehicle", "mass"): (0.0, INF),
    ("Pedestrian", "mass"): (0.0, INF),
    ("MiscObject", "mass"): (0.0, INF),
    ("Axle", "maxSteering"): (0.0, math.pi),
    ("Axle", "wheelDiameter"): (0.0, INF),
    ("Axle", "trackWidth"): (0.0, INF),
    ("Axle", "positionZ"): (0.0, INF),
    ("TransitionDynamics", "value"): (0.0, INF),
    ("Condition", "delay"): (0.0, INF),
    ("Phase", "duration"): (0.0, INF),
    ("TimeToCollisionCondition", "value"): (0.0, INF),
    ("TimeHeadwayCondition", "value"): (0.0, INF),
    ("DistanceCondition", "value"): (0.0, INF),
    ("RelativeDistanceCondition", "value"): (0.0, INF),
    ("ReachPositionCondition", "tolerance"): (0.0, INF),
    ("SimulationTimeCondition", "value"): (0.0, INF),
    ("TraveledDistanceCondition", "value"): (0.0, INF),
    ("StandStillCondition", "duration"): (0.0, INF),
    ("Waypoint", "routeStrategy"): (None, None),
    ("LaneOffsetActionDynamics", "maxLateralAcc"): (0.0, INF),
    ("AbsoluteSpeed", "value"): (None, None),  # negative = reverse (sketch action k)
    ("TimeReference", "scale"): (0.0, INF),
    ("Polyline", "time"): (0.0, INF),
    ("Vertex", "time"): (0.0, INF),
}

#: Ranges implied by the XSD's numeric base types.
BASE_TYPE_RANGES: dict[str, tuple[float | None, float | None]] = {
    "UnsignedInt": (0.0, 4294967295.0),
    "UnsignedShort": (0.0, 65535.0),
    "Int": (-2147483648.0, 2147483647.0),
    "Double": (None, None),
}
