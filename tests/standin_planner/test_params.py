import pytest

from standin_planner.faults import Faults
from standin_planner.params import PlannerParams
from txt2sce_ros.errors import InputError


def test_repository_config_loads_and_matches_the_smoothness_band():
    p = PlannerParams.from_config()
    # The comfort limits must sit inside the oracle's bands (0.9 m/s³, 10 °/s) or benign runs would fail.
    assert 0.0 < p.comfort.max_jerk < 0.9
    assert 0.0 < p.lateral.max_yaw_rate < 0.1745
    assert p.longitudinal.desired_speed > 0.0


def test_partial_dict_keeps_defaults_and_converts_numbers():
    p = PlannerParams.from_dict({"longitudinal": {"desired_speed": "12.5"}})
    assert p.longitudinal.desired_speed == 12.5
    assert p.longitudinal.max_accel == PlannerParams().longitudinal.max_accel


def test_unknown_key_names_file_and_key(tmp_path):
    path = tmp_path / "planner.yaml"
    path.write_text("longitudinal:\n  desired_sped: 3\n")
    with pytest.raises(InputError) as err:
        PlannerParams.from_config(path)
    assert "desired_sped" in str(err.value) and str(path) in str(err.value)


def test_unknown_section_and_bad_number_are_input_errors():
    with pytest.raises(InputError, match="lateral_control"):
        PlannerParams.from_dict({"lateral_control": {}})
    with pytest.raises(InputError, match="max_jerk"):
        PlannerParams.from_dict({"comfort": {"max_jerk": "fast"}})


def test_fault_names_round_trip_and_reject_unknown():
    f = Faults.from_names(["stale-tracking", "ignore_cyclists"])
    assert f.active() == ("ignore_cyclists", "stale_tracking")
    assert Faults().nominal and not f.nominal
    with pytest.raises(InputError, match="brake_never"):
        Faults.from_names(["brake_never"])
