"""Gap-aware avoidance (kernels.gaps): the opt-in navigators fuzzy-5b-gap / fuzzy-2b-gap (and
fuzzy-5b-gap inside the layers, the default fuzzy-5b, also named fuzzy-5b-gap-robust), with the
lidar scan, find and take the one passage wide enough for the body in a row of thin posts; the
published versions keep their seven rays and no gap finding."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.kernels import gaps
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import scenario_from_dict

POST, GAP_X, GAP, ROW_Y = 0.075, 11.5, 1.2, 10.0


def post_field() -> dict:
    """A row of 15 cm posts 0.3 m apart across a 20 m world, open only at a 1.2 m gap (post
    surface to post surface) 1.5 m to the right of the start-goal line, a few posts before it."""
    half = GAP / 2 + POST
    row = [x for x in np.arange(0.3, 19.8, 0.3) if abs(x - GAP_X) > half + 0.15] + [GAP_X - half, GAP_X + half]
    scattered = [(9.2, 6.5), (10.6, 7.4), (8.0, 8.2), (12.8, 7.0)]
    circles = [(x, ROW_Y) for x in row] + scattered
    return {"name": "post-field", "world": {"width": 20.0, "height": 20.0},
            "robot": {"x": 10.0, "y": 3.0, "theta": float(np.pi / 2)}, "goal": {"x": 10.0, "y": 17.0},
            "obstacles": [{"circle": {"center": [float(x), float(y)], "radius": POST}} for x, y in circles],
            "max_time": 100.0}


@pytest.mark.parametrize("name", ["fuzzy-5b-gap", "fuzzy-2b-gap", "fuzzy-5b-gap-robust"])
def test_robot_passes_through_the_gap_in_a_field_of_posts(name):
    trace = run_episode(scenario_from_dict(post_field()), make_controller(name), seed=0)
    assert trace.outcome == "reached"
    crossing = np.flatnonzero(np.diff(np.sign(trace.pose[:, 1] - ROW_Y)) != 0)
    assert len(crossing) == 1
    assert abs(trace.pose[crossing[0], 0] - GAP_X) < GAP / 2  # through the gap
    assert "GAP" in "|".join(trace.behaviour.tolist())


def test_published_navigator_does_not_find_the_gap():
    trace = run_episode(scenario_from_dict(post_field()), make_controller("fuzzy-5b-thesis"), seed=0)
    assert trace.outcome != "reached"
    assert not any("GAP" in label for label in trace.behaviour.tolist())


def test_gap_heading_is_the_goal_bearing_when_free_else_the_nearest_free_direction():
    angles = np.deg2rad(np.arange(-90.0, 90.5, 1.0))
    free = np.full(angles.size, 4.0)
    found, heading, width = gaps.gap_heading(free, angles, 0.2, 0.4, 2.0, np.pi / 2, 0.69)
    assert found and heading == pytest.approx(angles[np.argmin(abs(angles - 0.2))]) and width == pytest.approx(np.pi)
    ahead = free.copy()
    ahead[np.abs(angles) <= np.deg2rad(3.0)] = 1.0  # a post 1 m ahead: blocks ±asin(0.4) around it
    found, heading, _ = gaps.gap_heading(ahead, angles, 0.0, 0.4, 2.0, np.pi / 2, 0.69)
    assert found and np.deg2rad(3.0) + np.arcsin(0.4) < abs(heading) < np.deg2rad(3.0) + np.arcsin(0.4) + 0.1
    wall = np.full(angles.size, 0.5)
    assert not gaps.gap_heading(wall, angles, 0.0, 0.4, 2.0, np.pi / 2, 0.69)[0]


def blocked_by_definition(ranges, angles, clearance, look):
    """Every direction tested against every hit (the definition :func:`gaps.blocked_directions` scans runs of)."""
    with np.errstate(invalid="ignore"):  # a negative clearance below −r: no spread (NaN), nothing blocked
        spread = np.arcsin(np.minimum(1.0, clearance / np.maximum(ranges, 1e-9)))
    gap = np.abs(np.pi - (np.pi - (angles[:, None] - angles[None, :])) % (2 * np.pi))
    return ((gap <= spread[None, :]) & (ranges[None, :] < look)).any(axis=1)


@pytest.mark.parametrize("field_deg", [180.0, 270.0, 359.0])
def test_blocked_directions_are_those_of_the_definition_on_random_scans(field_deg):
    rng = np.random.default_rng(int(field_deg))
    angles = np.deg2rad(np.linspace(-field_deg / 2, field_deg / 2, 271))
    mixed = 0
    for k in range(200):
        ranges = np.where(rng.random(271) < 0.01 + k / 2000, rng.uniform(0.05, 4.0, 271), 4.0)
        clearance = rng.uniform(0.2, 0.6)
        expected = blocked_by_definition(ranges, angles, clearance, 2.0)
        assert np.array_equal(gaps.blocked_directions(ranges, angles, clearance, 2.0), expected)
        mixed += expected.any() and not expected.all()
    assert mixed > 50  # most scans test both answers


@pytest.mark.parametrize("case", ["full circle", "repeated", "one beam", "two beams", "tiny steps", "negative"])
def test_blocked_directions_on_odd_scans_are_those_of_the_definition(case):
    """Scans round the whole circle, with repeated directions, of one or two beams, with steps
    below the rounding of the angles' differences, and a negative clearance (blocks nothing)."""
    rng = np.random.default_rng(len(case))
    for _ in range(100):
        angles = {"full circle": np.linspace(-np.pi, np.pi, 361),
                  "repeated": np.repeat(np.linspace(-2.0, 2.0, 61), 3),
                  "one beam": np.array([rng.uniform(-3.0, 3.0)]),
                  "two beams": np.sort(rng.uniform(-3.0, 3.0, 2)),
                  "tiny steps": np.arange(21) * 3e-17,
                  "negative": np.linspace(-2.0, 2.0, 41)}[case]
        ranges = np.where(rng.random(angles.size) < 0.3, rng.uniform(0.05, 3.0, angles.size), 9.0)
        clearance = -0.1 if case == "negative" else (4e-16 if case == "tiny steps" else rng.uniform(0.2, 2.5))
        assert np.array_equal(gaps.blocked_directions(ranges, angles, clearance, 2.0),
                              blocked_by_definition(ranges, angles, clearance, 2.0)), case


def test_blocked_directions_on_uneven_scans_are_those_of_the_definition():
    """Directions unevenly spaced (the runs blocked without a test are sized by the widest step)."""
    rng = np.random.default_rng(8)
    for k in range(200):
        angles = np.sort(rng.uniform(-2.4, 2.4, 181))
        ranges = np.where(rng.random(181) < 0.02 + k / 1000, rng.uniform(0.05, 4.0, 181), 4.0)
        clearance = rng.uniform(0.2, 0.6)
        assert np.array_equal(gaps.blocked_directions(ranges, angles, clearance, 2.0),
                              blocked_by_definition(ranges, angles, clearance, 2.0))
