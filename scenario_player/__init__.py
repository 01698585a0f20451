"""scenario_player: an OpenSCENARIO 1.0–1.3 interpreter over a deterministic 2D kinematic world (no rclpy here).

    from scenario_player import load_scenario, Simulation, SimulationConfig
    sim = Simulation(load_scenario("file.xosc"), SimulationConfig(ego_mode="storyboard"))
    frame = sim.reset()
    while not sim.done:
        frame = sim.step(None)

See docs/closed_loop_api.md; the ROS 2 node is `scenario_player.node`.
"""

import txt2sce_ros  # noqa: F401  (first: it installs the compiled build's import hook, txt2sce_ros.accel)
from .simulation import Simulation, SimulationConfig
from .syntax.scenario import Scenario, load_scenario

__all__ = ["Scenario", "Simulation", "SimulationConfig", "load_scenario"]
