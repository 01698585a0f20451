import importlib.util
import math
import sys

import pytest

from txt2sce_ros.paths import REPO_ROOT

_spec = importlib.util.spec_from_file_location("autoware_adapter", REPO_ROOT / "examples" / "autoware_adapter.py")
adapter = importlib.util.module_from_spec(_spec)
sys.modules["autoware_adapter"] = adapter        # dataclasses look their module up there
_spec.loader.exec_module(adapter)


def test_acceleration_and_steering_map_to_next_speed_and_bicycle_yaw_rate():
    ctrl = adapter.AutowareControl(velocity=8.0, acceleration=1.0, steering_tire_angle=0.05)
    cmd = adapter.control_to_command(ctrl, speed_now=5.0, t=3.2, dt=0.05, wheelbase=2.7)
    assert cmd.t == 3.2 and cmd.speed == pytest.approx(5.05)
    assert cmd.yaw_rate == pytest.approx(5.05 * math.tan(0.05) / 2.7)


def test_target_velocity_is_not_overshot_and_speed_never_negative():
    up = adapter.control_to_command(adapter.AutowareControl(5.02, 2.0, 0.0), speed_now=5.0, t=0.0, dt=0.05)
    assert up.speed == pytest.approx(5.02)
    down = adapter.control_to_command(adapter.AutowareControl(0.0, -6.0, 0.0), speed_now=0.1, t=0.0, dt=0.05)
    assert down.speed == 0.0


def test_round_trip():
    ctrl = adapter.AutowareControl(velocity=2.0, acceleration=-1.5, steering_tire_angle=-0.1)
    cmd = adapter.control_to_command(ctrl, speed_now=6.0, t=1.0, dt=0.05)
    back = adapter.command_to_control(cmd, speed_now=6.0, dt=0.05)
    assert back.acceleration == pytest.approx(-1.5) and back.steering_tire_angle == pytest.approx(-0.1)
