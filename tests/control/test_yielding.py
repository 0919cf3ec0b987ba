"""fuzzy-5b-yield: the time to collision read from two lidar scans, and the layer getting through
dynamic worlds where fuzzy-5b is run into."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.yield_layer import yield_system
from fuzzynav.kernels import scan_tracks, threats
from fuzzynav.kernels.records import Scans, ThreatSettings
from fuzzynav.sim.simulator import run_episode
from fuzzynav.world.generate import generate_world


def scan(centre, radius, origin, angles):
    """Points where rays from ``origin`` meet a disc (inf-free rows only) and which rays hit."""
    d = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    rel = np.asarray(centre) - origin
    along = d @ rel
    disc = along ** 2 - (rel @ rel - radius ** 2)
    hit = disc >= 0
    t = along - np.sqrt(np.where(hit, disc, 0))
    return origin + t[:, None] * d, hit & (t > 0)


def _ttc(now, seen, robot_now, before, valid, robot_before, angles):
    """The compiled two-scan cue (no tracks) of one robot at ``robot_now`` heading along x."""
    ranges = np.where(seen, np.hypot(*(now - robot_now).T), 8.0)
    pose = np.array([[*robot_now, 0.0]])
    settings = ThreatSettings(t=0.1, dt=0.1, max_range=8.0, mover_speed=0.3, horizon=3.0, track_range=6.0,
                              tracked_beyond=np.pi / 3, radius=0.3, tracks=False)
    previous = Scans(before[None].copy(), valid[None].copy(), robot_before[None].copy())
    ttc, bearing, _ = threats.threats(pose, np.array([0.8]), ranges[None], angles, np.ones(1, dtype=bool), previous,
                                      scan_tracks.empty(1), settings)
    return ttc[0], bearing[0]


def test_a_standing_surface_is_no_threat_and_an_approaching_one_is():
    angles = np.deg2rad(np.arange(-30.0, 31.0, 1.0))
    robot_before, robot_now = np.array([0.0, 0.0]), np.array([0.08, 0.0])  # driving at 0.8 m/s
    before, valid = scan([2.5, 0.0], 0.4, robot_before, angles)
    now, seen = scan([2.5, 0.0], 0.4, robot_now, angles)
    assert _ttc(now, seen, robot_now, before, valid, robot_before, angles)[0] == np.inf
    now, seen = scan([2.4, 0.0], 0.4, robot_now, angles)  # the disc came 0.1 m closer: 1 m/s towards the robot
    ttc, bearing = _ttc(now, seen, robot_now, before, valid, robot_before, angles)
    # gap 2.4 − 0.4 − 0.08 m closed at 1.8 m/s, straight ahead
    assert ttc == pytest.approx((2.4 - 0.4 - 0.08) / 1.8, abs=1e-6) and bearing == 0.0


def test_the_rule_base_waits_for_long_times_and_acts_on_short_ones():
    out = yield_system().evaluate(np.array([[8.0, 0.0], [1.0, np.pi / 2], [1.0, 0.0]]))
    assert out[0, 0] == 0.0  # far in time: the navigator drives alone
    assert out[1, 0] == 1.0 and out[1, 1] > 1.0  # abeam and close: speed out of the way
    assert 0.0 < out[2, 0] < 1.0 and out[2, 1] < 1.0  # head-on: slow down and swerve, the navigator keeps a say


@pytest.mark.slow
@pytest.mark.parametrize("index", [1, 3])
def test_it_gets_through_where_fuzzy_5b_is_run_into(index):
    scenario = generate_world("dynamic", 1, index)
    plain = run_episode(scenario, make_controller("fuzzy-5b", paced=False, yield_in_traffic=False),
                        seed=0)  # the thesis' speeds, no yield layer
    assert plain.outcome == "collision" and plain.collision_by == "obstacle"
    trace = run_episode(scenario, make_controller("fuzzy-5b-yield"), seed=0)
    assert trace.outcome == "reached"
    assert "YIELD" in set(trace.behaviour)


@pytest.mark.slow
def test_tracked_obstacles_keep_it_clear_of_what_comes_from_behind():
    """In this world fuzzy-5b-yield (the two-scan cue alone) is run into from behind, out of the
    lidar's view; fuzzy-5b-yield-tracks, predicting the tracked obstacle there, gets through."""
    scenario = generate_world("dynamic", 7, 69)
    before = run_episode(scenario, make_controller("fuzzy-5b-yield"), seed=0)
    assert before.outcome == "collision" and before.collision_by == "obstacle"
    assert run_episode(scenario, make_controller("fuzzy-5b-yield-tracks"), seed=0).outcome == "reached"
