"""Adapter example: an Autoware-style control command -> the txt2sce closed loop's command.

Autoware's controller publishes `autoware_control_msgs/msg/Control` on `/control/command/control_cmd`:

    Control.longitudinal.velocity          target speed (m/s)
    Control.longitudinal.acceleration      target acceleration (m/s²)
    Control.lateral.steering_tire_angle    front tyre angle (rad, left positive)

The txt2sce player takes `geometry_msgs/TwistStamped` on `/control/command`: `twist.linear.x` = the speed to reach by
the next step (m/s), `twist.angular.z` = yaw rate (rad/s), `header.stamp` = the time of the frame answered. The
mapping below uses the kinematic bicycle model about the rear axle (the reference point of our odometry):
yaw rate = v·tan(δ)/wheelbase; and the next-step speed v + a·dt, bounded by the target velocity so that an
acceleration request never overshoots it.

`control_to_command` is plain Python and is what a bridge node calls; `AutowareBridge` is that node. The Autoware
message package is not on PyPI, so the node imports it lazily and this file runs without it
(`python examples/autoware_adapter.py` prints a worked example).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

from txt2sce_ros.contract import ControlCommand


@dataclass(frozen=True, slots=True)
class AutowareControl:
    """The fields of autoware_control_msgs/Control the closed loop needs."""

    velocity: float              # m/s
    acceleration: float          # m/s²
    steering_tire_angle: float   # rad


def control_to_command(ctrl: AutowareControl, *, speed_now: float, t: float, dt: float,
                       wheelbase: float = 2.7) -> ControlCommand:
    """The player command answering the frame at time `t`, given the ego's current speed (m/s)."""
    v_next = speed_now + ctrl.acceleration * dt
    # Do not pass the target velocity within the step (Autoware's acceleration is a means to reach it).
    if ctrl.acceleration >= 0.0:
        v_next = min(v_next, max(ctrl.velocity, speed_now))
    else:
        v_next = max(v_next, min(ctrl.velocity, speed_now))
    v_next = max(v_next, 0.0)
    yaw_rate = v_next * math.tan(ctrl.steering_tire_angle) / wheelbase
    return ControlCommand(t=t, speed=v_next, yaw_rate=yaw_rate)


def command_to_control(cmd: ControlCommand, *, speed_now: float, dt: float,
                       wheelbase: float = 2.7) -> AutowareControl:
    """The inverse, for replaying one of our runs into an Autoware-style consumer."""
    accel = (cmd.speed - speed_now) / dt
    steer = math.atan2(cmd.yaw_rate * wheelbase, cmd.speed) if cmd.speed > 1e-3 else 0.0
    return AutowareControl(velocity=cmd.speed, acceleration=accel, steering_tire_angle=steer)


def make_bridge_node(wheelbase: float = 2.7):  # pragma: no cover - needs Autoware's messages
    """A ROS 2 node relaying Autoware's control command to /control/command, stamped with the last ego odometry's
    time (lock-step: the player waits for that stamp)."""
    import rclpy.node
    from autoware_control_msgs.msg import Control  # type: ignore[import-not-found]
    from geometry_msgs.msg import TwistStamped
    from nav_msgs.msg import Odometry

    from txt2sce_ros.contract import TOPIC_COMMAND, TOPIC_EGO_ODOM
    from txt2sce_ros.ros_io import command_to_twist, from_stamp

    class AutowareBridge(rclpy.node.Node):
        def __init__(self) -> None:
            super().__init__("autoware_bridge")
            self.speed, self.t, self.dt = 0.0, 0.0, 0.05
            self.pub = self.create_publisher(TwistStamped, TOPIC_COMMAND, 10)
            self.create_subscription(Odometry, TOPIC_EGO_ODOM, self._odom, 10)
            self.create_subscription(Control, "/control/command/control_cmd", self._control, 10)

        def _odom(self, msg: Odometry) -> None:
            t = from_stamp(msg.header.stamp)
            if t > self.t:
                self.dt = t - self.t
            self.t, self.speed = t, msg.twist.twist.linear.x

        def _control(self, msg) -> None:
            ctrl = AutowareControl(msg.longitudinal.velocity, msg.longitudinal.acceleration,
                                   msg.lateral.steering_tire_angle)
            cmd = control_to_command(ctrl, speed_now=self.speed, t=self.t, dt=self.dt, wheelbase=wheelbase)
            self.pub.publish(command_to_twist(cmd))

    return AutowareBridge()


def main() -> int:
    ctrl = AutowareControl(velocity=8.0, acceleration=1.0, steering_tire_angle=0.05)
    cmd = control_to_command(ctrl, speed_now=5.0, t=12.35, dt=0.05)
    print(f"Autoware Control {ctrl}\n  at v = 5.0 m/s, t = 12.35 s, dt = 0.05 s -> {cmd}")
    back = command_to_control(cmd, speed_now=5.0, dt=0.05)
    print(f"  and back -> {back}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
