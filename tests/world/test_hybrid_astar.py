"""Hybrid A* (world/hybrid_astar.py): paths a car can drive, clear of the inflated obstacles."""

import math
from pathlib import Path

import numpy as np

from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world.barn import barn_scenario, read_posts
from fuzzynav.world.hybrid_astar import Car, Search, hybrid_astar
from fuzzynav.world.planning import default_cell, shortest_path
from fuzzynav.world.scenario import scenario_from_dict

CAR = Car(DEFAULT_PARAMS.radius + 0.05, DEFAULT_PARAMS.wheelbase, DEFAULT_PARAMS.max_steering)
BARN = Path(__file__).resolve().parents[1] / "data" / "barn"


def bay(width: float, room: float = 2.5):
    """A corridor 6 m long between two walls ``width`` m apart (axes), open into a room of depth
    ``room``; the robot in the middle faces the room, the goal is behind it."""
    walls = [{"wall": {"start": [0, 2.0 + side * width / 2], "end": [6.0, 2.0 + side * width / 2], "thickness": 0.1}}
             for side in (-1, 1)]
    return scenario_from_dict({"world": {"width": 6.0 + room, "height": 4}, "robot": {"x": 3, "y": 2, "theta": 0},
                               "goal": {"x": 0.8, "y": 2, "tolerance": 0.3}, "max_time": 60, "obstacles": walls})


def assert_drivable(plan, car: Car, start):
    """Consecutive poses lie on arcs of curvature at most 1 / turning radius, heading along the motion."""
    poses = plan.poses
    assert np.allclose(poses[0], start)
    steps = np.diff(poses[:, :2], axis=0)
    lengths = np.hypot(*steps.T)
    turns = np.abs(np.array([math.remainder(a, math.tau) for a in np.diff(poses[:, 2])]))
    assert (turns <= car.max_curvature * lengths * 1.001 + 1e-9).all()
    chord = np.arctan2(steps[:, 1], steps[:, 0])  # the chord of an arc points half-way through its turn
    mid = poses[:-1, 2] + 0.5 * np.array([math.remainder(a, math.tau) for a in np.diff(poses[:, 2])])
    assert np.abs([math.remainder(a, math.tau) for a in chord - mid]).max() < 1e-6


def test_turning_round_in_the_open_follows_the_turning_circle():
    """Goal 2 m behind the start in an empty world: the plan loops round on arcs the car can drive."""
    scenario = scenario_from_dict({"world": {"width": 10, "height": 10}, "robot": {"x": 5, "y": 5, "theta": 0},
                                   "goal": {"x": 3, "y": 5}})
    plan = hybrid_astar(scenario.world, scenario.start, scenario.goal.position, CAR)
    assert_drivable(plan, CAR, scenario.start)
    assert math.dist(plan.poses[-1, :2], scenario.goal.position) <= Search().reach
    assert plan.poses[:, 0].max() > 5.3  # went forward before turning: no turn on the spot
    assert np.abs(plan.curvature).max() <= CAR.max_curvature + 1e-9


def test_barn_world_path_is_drivable_and_clear_of_the_inflated_posts():
    scenario = scenario_from_dict(barn_scenario(read_posts(BARN / "world_0.world"), "world_0", 1.0))
    plan = hybrid_astar(scenario.world, scenario.start, scenario.goal.position, CAR)
    assert_drivable(plan, CAR, scenario.start)
    # every sample on the arcs (poses every 5 cm) keeps the inflated disc clear, up to the grid's half diagonal
    slack = default_cell(scenario.world) / math.sqrt(2)
    assert scenario.world.clearance(plan.poses[:, :2]).min() >= CAR.radius - slack > DEFAULT_PARAMS.radius


def test_a_corridor_too_narrow_to_turn_in_makes_it_turn_in_the_room():
    """1.4 m between the walls' axes: a U-turn needs 2 (l / tan α_max + r) = 1.6 m, so the car
    drives into the room (x > 6), turns there and comes back; the grid A* path goes straight back."""
    scenario = bay(1.4)
    plan = hybrid_astar(scenario.world, scenario.start, scenario.goal.position, CAR)
    assert_drivable(plan, CAR, scenario.start)
    assert plan.poses[:, 0].max() > 6.0
    grid = shortest_path(scenario.world, scenario.start, scenario.goal.position, CAR.radius)
    assert grid[:, 0].max() <= scenario.start[0] + 1e-9


def test_no_path_where_the_car_cannot_turn_round_or_within_a_tiny_budget():
    closed = bay(1.4, room=0.0)  # the corridor ends at the world's edge: no room to turn round
    assert shortest_path(closed.world, closed.start, closed.goal.position, CAR.radius) is not None
    assert hybrid_astar(closed.world, closed.start, closed.goal.position, CAR) is None
    scenario = bay(1.4)
    assert hybrid_astar(scenario.world, scenario.start, scenario.goal.position, CAR, Search(budget=50)) is None
