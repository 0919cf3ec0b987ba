"""The default navigator forgets where moving obstacles were (kernels/clearing.py): the points a
scan sees through, or nearer than the nearest obstacle, leave its memory in a scenario with
moving obstacles, and only there."""

import math

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.through_gaps import fuzzy_5b_gap_robust
from fuzzynav.kernels import clearing, sightings
from fuzzynav.kernels.layers import PARAM
from fuzzynav.kernels.records import Pose, Reading
from fuzzynav.robot.sensors import named_ring
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import scenario_from_dict


def _memory(points):
    slots = 64
    memory, cells = np.zeros((slots, 2)), np.zeros(128)
    count = 0
    for px, py in points:
        count = sightings.add(memory, cells, count, px, py)
    return memory, cells, count


def test_a_scan_forgets_the_points_it_sees_through_and_keeps_those_on_or_past_its_echoes():
    ring = named_ring("lidar")
    ranges = np.full(len(ring.angles), ring.max_range)
    ahead = int(np.argmin(np.abs(ring.angles)))
    wall = slice(ahead - 10, ahead + 11)
    ranges[wall] = 2.0 / np.cos(ring.angles[wall])  # a wall 2 m ahead, nothing elsewhere within reach
    seen = Reading(ranges, ring.angles, ring.max_range, 2.0, 0.0)
    passed = (1.0, 0.0)  # on the beam ahead, short of its echo: the beam went through
    on_echo, past_echo = (2.0, 0.0), (3.0, 0.0)
    aside = (0.0, 1.0)  # 90° left, 1 m: nearer than the nearest obstacle (2 m)
    behind = (-3.0, 0.0)  # in the blind sector, farther than the nearest obstacle
    memory, cells, count = _memory([passed, on_echo, past_echo, aside, behind])
    kept = clearing.clear(memory, cells, count, Pose(0.0, 0.0, 0.0), seen)
    assert kept == 3
    assert [tuple(point) for point in memory[:kept]] == [on_echo, past_echo, behind]
    # the hash set follows: a forgotten point's cell takes a point again, a kept one's does not
    assert sightings.add(memory, cells, kept, *passed) == kept + 1
    assert sightings.add(memory, cells, kept + 1, *behind) == kept + 1


def test_without_a_nearest_obstacle_only_the_beams_clear():
    ring = named_ring("lidar")
    seen = Reading(np.full(len(ring.angles), ring.max_range), ring.angles, ring.max_range, math.inf, 0.0)
    memory, cells, count = _memory([(-2.0, 0.0)])  # behind, no beam there
    assert clearing.clear(memory, cells, count, Pose(0.0, 0.0, 0.0), seen) == 1


def patrol(speed: float) -> dict:
    """The robot drives along y = 10 to x = 18; a disc walks to and fro across its way at x = 10."""
    return {"world": {"width": 20, "height": 20}, "robot": {"x": 2, "y": 10, "theta": 0}, "goal": {"x": 18, "y": 10},
            "obstacles": [{"circle": {"center": [10, 7], "radius": 0.4},
                           "motion": {"type": "waypoints", "points": [[10, 7], [10, 13]], "speed": speed,
                                      "loop": True}}], "max_time": 40}


def test_only_a_scenario_with_moving_obstacles_turns_the_clearing_on():
    navigator = make_controller("fuzzy-5b")
    assert navigator.for_traffic(True).params[PARAM.forget] == 1.0
    assert navigator.for_traffic(False).params[PARAM.forget] == 0.0
    assert fuzzy_5b_gap_robust(forget_moving=False).for_traffic(True).params[PARAM.forget] == 0.0
    run_episode(scenario_from_dict(patrol(1.0)), navigator, seed=0, max_time=0.5)
    assert navigator.params[PARAM.forget] == 1.0  # the simulator told it
    static = patrol(1.0)
    del static["obstacles"][0]["motion"]
    run_episode(scenario_from_dict(static), navigator, seed=0, max_time=0.5)
    assert navigator.params[PARAM.forget] == 0.0


def test_a_patrol_across_the_way_no_longer_leaves_a_wall_of_ghosts_to_drive_round():
    """Remembering the disc everywhere it was seen, the route guidance plans round a wall of its
    past places across the way (about 17 s to the goal); forgetting them, the robot gets through
    once the disc has passed (under 10 s). Both as version 6 drove: no yield layer, and the step after a
    back-up the navigator's (version 10 plans on at once, which takes the remembering robot round sooner)."""
    scenario = scenario_from_dict(patrol(1.0))
    version_6 = {"yield_in_traffic": False, "guidance": {"guide_car_chain": 0.0}, "pace": {"pace_horizon": 1.5}}
    remembering = run_episode(scenario, fuzzy_5b_gap_robust(forget_moving=False, **version_6), seed=0)
    forgetting = run_episode(scenario, fuzzy_5b_gap_robust(**version_6), seed=0)
    assert remembering.outcome == forgetting.outcome == "reached"
    assert remembering.time > 15.0
    assert forgetting.time < 10.0


def test_the_tracked_yield_variant_runs_round_the_default_and_the_plain_one_round_version_2():
    """``fuzzy-5b-yield-tracks`` (version 2) wraps the default ``fuzzy-5b``, paced and forgetting;
    ``fuzzy-5b-yield`` keeps ``fuzzy-5b`` at the thesis' speeds, remembering every point."""
    tracked, plain = make_controller("fuzzy-5b-yield-tracks"), make_controller("fuzzy-5b-yield")
    assert tracked.for_traffic(True).inner.params[PARAM.forget] == 1.0
    assert tracked.inner.params[PARAM.pace] == 1.0
    assert plain.for_traffic(True).inner.params[PARAM.forget] == 0.0
    assert plain.inner.params[PARAM.pace] == 0.0


def test_a_held_out_dynamic_world_that_version_4_failed_is_now_passed():
    """``dynamic`` seed 11, world 2: remembering every mover where it was seen, the car route
    drove its own arcs between their past places until a mover ran into the robot; forgetting
    them, ``fuzzy-5b`` reaches the goal."""
    from fuzzynav.world.generate import generate_world

    scenario = generate_world("dynamic", 11, 2)
    version_4 = {"forget_moving": False, "yield_in_traffic": False, "pace": {"pace_horizon": 1.5}}
    before = run_episode(scenario, fuzzy_5b_gap_robust(**version_4), seed=0)
    assert before.outcome == "collision"
    assert {"CAR-FWD", "CAR-BACK"} & set(before.behaviour[-10:])
    no_yield = fuzzy_5b_gap_robust(yield_in_traffic=False)  # the clearing alone, without version 7's yield layer
    assert run_episode(scenario, no_yield, seed=0).outcome == "reached"
