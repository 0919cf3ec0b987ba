"""Moving obstacles in scenario files: the ``motion`` of any obstacle (line, circle, sinusoid,
waypoints), its checks naming the file and field, and the closed-form offsets (a line reflects
at the world's border, waypoints loop or stop)."""

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.world.moving import fold, offsets
from fuzzynav.world.scenario import scenario_from_dict

ISSUE_EXAMPLE = [
    {"circle": {"center": [5, 5], "radius": 0.3}, "motion": {"type": "line", "velocity": [0.6, 0.0]}},
    {"polygon": {"points": [[8, 8], [9, 8], [9, 9]]},
     "motion": {"type": "waypoints", "points": [[8, 8], [12, 8]], "speed": 0.8, "loop": True}},
    {"ellipse": {"center": [14, 14], "radii": [1.0, 0.5]}, "motion": {"type": "circle", "center": [14, 12], "speed": 0.5}},
    {"wall": {"start": [2, 16], "end": [4, 16]},
     "motion": {"type": "sinusoid", "velocity": [0.3, 0.0], "amplitude": 1.0, "period": 4.0}},
    {"circle": {"center": [15, 5], "radius": 1.0}},
]


def scenario(obstacles, width=20.0):
    return scenario_from_dict({"world": {"width": width, "height": 20.0}, "robot": {"x": 1, "y": 1},
                               "goal": {"x": 18, "y": 18}, "obstacles": obstacles}, source="dyn.yaml")


def test_the_schema_of_the_issue_parses_and_round_trips():
    s = scenario(ISSUE_EXAMPLE)
    assert s.world.moving == (0, 1, 2, 3)
    assert [s.world.motions[i].type for i in s.world.moving] == ["line", "waypoints", "circle", "sinusoid"]
    assert s.world.motions[4] is None
    again = scenario_from_dict(s.to_dict(), source="again")
    assert again.to_dict() == s.to_dict()
    assert s.to_dict()["obstacles"][1]["motion"] == ISSUE_EXAMPLE[1]["motion"]
    t = np.linspace(0, 30, 61)
    np.testing.assert_array_equal(offsets(again.world, t), offsets(s.world, t))


def test_a_static_scenario_has_no_moving_obstacles():
    s = scenario(ISSUE_EXAMPLE[4:])
    assert s.world.motions == () and s.world.moving == () and s.world.movers.shape == (0, 4)
    assert "motion" not in s.to_dict()["obstacles"][0]


@pytest.mark.parametrize("motion, field, problem", [
    ({"type": "linear", "velocity": [1, 0]}, "obstacles[0].motion.type", "did you mean 'line'"),
    ({"velocity": [1, 0]}, "obstacles[0].motion.type", "missing"),
    ({"type": "line"}, "obstacles[0].motion.velocity", "missing"),
    ({"type": "line", "velocity": [1, 0, 2]}, "obstacles[0].motion.velocity", ""),
    ({"type": "line", "velocity": [1, 0], "speed": 2}, "obstacles[0].motion.speed", "unknown"),
    ({"type": "waypoints", "points": [[1, 1], [2, 2]], "speed": 0}, "obstacles[0].motion.speed", "> 0"),
    ({"type": "waypoints", "points": [[1, 1]], "speed": 1}, "obstacles[0].motion.points", "at least 2"),
    ({"type": "waypoints", "points": [[1, 1], [1, 1]], "speed": 1}, "obstacles[0].motion.points", "same"),
    ({"type": "waypoints", "points": [[1, 1], [2, 2]], "speed": 1, "loop": "yes"}, "obstacles[0].motion.loop",
     "true or false"),
    ({"type": "circle", "center": [5, 5], "speed": 1}, "obstacles[0].motion.center", "zero radius"),
    ({"type": "sinusoid", "velocity": [0, 0], "amplitude": 3, "period": 4}, "obstacles[0].motion.velocity",
     "must not be zero"),
    ([1, 2], "obstacles[0].motion.type", "missing"),
])
def test_bad_motions_name_the_file_and_field(motion, field, problem):
    with pytest.raises(InputError) as caught:
        scenario([{"circle": {"center": [5, 5], "radius": 0.3}, "motion": motion}])
    assert caught.value.source == "dyn.yaml" and caught.value.field == field
    assert problem in str(caught.value)


def test_an_entry_with_motion_but_two_shapes_is_refused():
    with pytest.raises(InputError, match="exactly one of"):
        scenario([{"circle": {"center": [5, 5], "radius": 0.3}, "ellipse": {"center": [9, 9], "radii": [1, 1]},
                   "motion": {"type": "line", "velocity": [1, 0]}}])


def test_a_line_reflects_at_the_border():
    """A disc of radius 0.5 at x = 18 moving at +1 m/s in a 20 m wide world touches the right
    border at t = 1.5 s and comes back: x = 18.5 at t = 2.5 s, the left border (x = 0.5) at
    t = 20.5 s, and x = 18 again at t = 38 s."""
    s = scenario([{"circle": {"center": [18, 10], "radius": 0.5}, "motion": {"type": "line", "velocity": [1.0, 0]}}])
    x = 18 + offsets(s.world, [0.0, 1.0, 1.5, 2.5, 20.5, 21.5, 38.0])[:, 0, 0]
    np.testing.assert_allclose(x, [18, 19, 19.5, 18.5, 0.5, 1.5, 18], atol=1e-12)


def test_fold_is_a_triangle_wave():
    u = np.array([-3.0, -1.0, 0.0, 2.0, 4.0, 5.0, 9.0])
    np.testing.assert_allclose(fold(u, -1.0, 2.0), [1.0, -1.0, 0.0, 2.0, 0.0, -1.0, 1.0])


def test_waypoints_loop_or_stop():
    patrol = {"type": "waypoints", "points": [[4, 4], [8, 4], [8, 7]], "speed": 1.0}
    looped, stopped = (scenario([{"circle": {"center": [4, 4], "radius": 0.3}, "motion": {**patrol, "loop": loop}}])
                       for loop in (True, False))
    t = [0.0, 2.0, 4.0, 5.5, 7.0, 9.5, 12.0, 14.0]  # the loop is 4 + 3 + 5 = 12 m long
    np.testing.assert_allclose(offsets(looped.world, t)[:, 0],
                               [[0, 0], [2, 0], [4, 0], [4, 1.5], [4, 3], [2, 1.5], [0, 0], [2, 0]], atol=1e-12)
    np.testing.assert_allclose(offsets(stopped.world, t)[:, 0],
                               [[0, 0], [2, 0], [4, 0], [4, 1.5], [4, 3], [4, 3], [4, 3], [4, 3]], atol=1e-12)


def test_circle_and_sinusoid_move_the_shape_as_the_target_moves():
    s = scenario(ISSUE_EXAMPLE)
    t = np.linspace(0, 10, 11)
    moved = offsets(s.world, t)
    centre = np.array([14, 14]) + moved[:, 2]
    np.testing.assert_allclose(np.hypot(*(centre - [14, 12]).T), 2.0)  # a circle of radius |p0 - center|
    np.testing.assert_allclose(moved[:, 3, 0], 0.3 * t, atol=1e-12)
    np.testing.assert_allclose(moved[:, 3, 1], 1.0 * np.sin(2 * np.pi * t / 4.0), atol=1e-12)
