"""The deterministic 2D world: entities, lane tracking, kinematics, measurements, collisions, signals."""
