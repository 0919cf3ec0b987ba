"""Path generators of chapter V (sim/paths.py): shapes, corners, scenarios."""

import math

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.sim import paths


def test_thesis_paths_have_the_spec_corners():
    np.testing.assert_array_equal(paths.v_path(), [[2, 14], [10, 5], [18, 14]])
    np.testing.assert_array_equal(paths.n_path(), [[3, 3], [3, 17], [17, 3], [17, 17]])
    np.testing.assert_array_equal(paths.trapezoid_path(), [[3, 3], [7, 17], [13, 17], [17, 3]])
    np.testing.assert_allclose(np.degrees(paths.turn_angles(paths.n_path())), [-135, 135])
    np.testing.assert_allclose(np.abs(np.degrees(paths.turn_angles(paths.trapezoid_path()))), 74.05, atol=0.01)


def test_star_lines_leave_the_centre_every_60_degrees():
    lines = paths.star_lines(length=8.0)
    assert len(lines) == 6
    for k, line in enumerate(lines):
        np.testing.assert_allclose(line[0], [10, 10])
        assert paths.length(line) == pytest.approx(8.0)
        assert paths.headings(line)[0] == pytest.approx(math.atan2(math.sin(k * math.pi / 3), math.cos(k * math.pi / 3)))


def test_path_scenario_starts_on_the_path_heading_along_it():
    scenario = paths.path_scenario(paths.v_path(), tolerance=0.8, speed=1.5)
    np.testing.assert_allclose(scenario.start, [2, 14, math.atan2(-9, 8)])
    assert scenario.task == "path" and scenario.path.tolerance == 0.8 and scenario.path.speed == 1.5
    assert scenario.max_time == pytest.approx(3 * paths.length(paths.v_path()) / 1.5 + 10)


@pytest.mark.parametrize("points", [[[1, 1]], [[1, 1], [1, 1]], [[0, 0], [np.nan, 1]]])
def test_bad_paths_raise_input_error(points):
    with pytest.raises(InputError):
        paths.segment(*points) if len(points) == 2 else paths.path_scenario(points)


def test_a_u_turn_turns_by_pi_as_the_package_wraps_angles():
    assert paths.turn_angles([[0.0, 0.0], [0.0, 1.0], [0.0, 0.0]]).tolist() == [math.pi]  # (−π, π]: +π, not −π
