"""``dwa-tracks`` and ``vfh-tracks``: DWA and VFH planning against the predicted tracks of moving
obstacles (control/classic/local_map.py ``TrackedMap``, ``moving_free_length``)."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.base import Observation
from fuzzynav.control.classic.local_map import TrackedMap, arcs, moving_free_length
from fuzzynav.robot.sensors import named_ring
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import scenario_from_dict


def crossing(y0: float, vy: float) -> dict:
    """A robot driving along y = 10 to x = 18; a disc of radius 0.4 crossing its way at x = 10."""
    return {"world": {"width": 20, "height": 20}, "robot": {"x": 2, "y": 10, "theta": 0}, "goal": {"x": 18, "y": 10},
            "obstacles": [{"circle": {"center": [10, y0], "radius": 0.4},
                           "motion": {"type": "line", "velocity": [0, vy]}}], "max_time": 30}


@pytest.mark.parametrize("y0, vy", [(5.0, 1.0), (15.0, -1.0)])
def test_dwa_tracks_gets_past_a_crossing_disc_that_plain_dwa_drives_into(y0, vy):
    scenario = scenario_from_dict(crossing(y0, vy))
    plain = run_episode(scenario, make_controller("dwa"), seed=0)
    assert plain.outcome == "collision"
    tracked = run_episode(scenario, make_controller("dwa-tracks"), seed=0)
    assert tracked.outcome == "reached", tracked.outcome


def test_vfh_tracks_reaches_the_goal_past_a_crossing_disc():
    trace = run_episode(scenario_from_dict(crossing(5.0, 1.0)), make_controller("vfh-tracks"), seed=0)
    assert trace.outcome == "reached"


def test_an_arc_is_cut_where_the_moving_disc_will_be_when_the_robot_gets_there():
    """A disc 2 m ahead, 2.5 m to the right, walking left at 1 m/s: at 1 m/s the robot meets it on the
    straight arc about 2 m on; at 2 m/s it is past before the disc gets there."""
    def predict(times):
        centres = np.array([2.0, -2.5]) + np.array([0.0, 1.0]) * np.asarray(times)[..., None]
        return centres[None], np.array([0.3])

    free = moving_free_length(np.zeros(1), np.array([1.0, 2.0]), predict, 0.4, 3.0, 3.0, margin=0.0)
    assert 1.0 < free[0, 0] < 2.25  # at 1 m/s: cut before the point of closest approach
    assert free[0, 1] == 3.0  # at 2 m/s: clear
    # where it is cut the disc is within reach of the body at that time (0.4 + 0.3 m)
    where = arcs(np.zeros(1), np.array([free[0, 0] + 0.05]))[0, 0]
    assert np.hypot(*(where - predict(free[0, 0] + 0.05)[0][0])) < 0.7


def _observation(t, pose, ranges):
    ring = named_ring("lidar")
    return Observation(t=t, dt=0.1, pose=np.asarray(pose, dtype=float), speed=0.0, steering=0.0,
                       target=np.array([18.0, 10.0]), ranges=ranges, sensor_angles=ring.angles,
                       max_range=ring.max_range, obstacle_distance=1.0, obstacle_bearing=0.0)


def _scan(pose, centre, radius=0.4):
    """Lidar ranges from ``pose`` to a disc at ``centre`` (max range elsewhere)."""
    ring = named_ring("lidar")
    heading = pose[2] + ring.angles
    d = np.stack([np.cos(heading), np.sin(heading)], axis=1)
    rel = np.asarray(centre) - np.asarray(pose[:2])
    m = d @ rel
    disc = m * m - (rel @ rel - radius * radius)
    hit = (disc >= 0) & (m > 0)
    return np.where(hit, np.minimum(m - np.sqrt(np.maximum(disc, 0)), ring.max_range), ring.max_range)


def test_the_tracked_map_keeps_no_trail_of_a_moving_disc_and_predicts_it():
    tracked, pose = TrackedMap(memory=10), np.array([0.0, 0.0, 0.0])
    for k in range(20):  # a disc walking left across the view at 1.2 m/s, 2.5 m ahead, for 2 s
        centre = np.array([2.5, -1.5 + 0.12 * k])
        points = tracked.points(_observation(0.1 * k, pose, _scan(pose, centre)))
    # once it is tracked (half a second) and the memory (1 s) has turned over, nothing is remembered
    # along where it walked: its echoes now are those of the track's predicted disc
    assert len(points) == 0
    where, radii = tracked.predicted(_observation(1.9, pose, _scan(pose, centre)), np.array([0.0, 1.0]))
    assert len(radii) == 1
    # its velocity in the robot frame, fitted to centres estimated from the near side (within 0.2 m/s)
    np.testing.assert_allclose(where[0, 1] - where[0, 0], [0.0, 1.2], atol=0.2)
