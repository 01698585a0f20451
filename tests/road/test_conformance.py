"""Road model vs esmini: every reference row on a road maps to esmini's (x, y) within 5 cm."""

from __future__ import annotations

import pytest

from txt2sce_ros.road.conformance import check_reference


@pytest.fixture(scope="module")
def results(esmini_dir):
    return check_reference(esmini_dir / "xodr", esmini_dir / "reference")


def test_all_reference_files_checked(results) -> None:
    assert len(results) == 18
    assert sum(r.rows for r in results) > 15_000


@pytest.mark.parametrize("mapping", ["road", "lane"])
def test_each_file_at_least_99_percent_within_5cm(results, mapping: str) -> None:
    low = {r.name: getattr(r, f"{mapping}_share") for r in results if getattr(r, f"{mapping}_share") < 0.99}
    assert not low, low


def test_lane_offset_sign_and_lane_offset_maps_are_exercised(results) -> None:
    # soderleden (laneOffset, paramPoly3) and curves_elevation (clothoids) are the hard cases.
    by_name = {r.name: r for r in results}
    assert by_name["highway_merge"].map_name == "soderleden.xodr" and by_name["highway_merge"].lane_share == 1.0
    assert by_name["trajectory-test"].map_name == "curves_elevation.xodr"
    assert by_name["trajectory-test"].road_max_err < 0.05
