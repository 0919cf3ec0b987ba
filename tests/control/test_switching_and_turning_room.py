"""Hysteresis of the behaviour switches (Figs IV.9, IV.16) and the turning room of the tricycle (§IV.4)."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.turning_room import TURN_RADIUS
from fuzzynav.kernels import guard
from fuzzynav.kernels.records import Pose, Reading
from fuzzynav.sim import run_episode
from fuzzynav.viz.trajectories import merged_changes
from fuzzynav.world.generate import generate_worlds
from fuzzynav.world.scenario import load_scenario, scenario_from_dict

RANK = (0, 1)


def test_switch_adds_caution_at_once_and_removes_it_after_the_dwell():
    state = np.array([-1, 0])
    assert guard.switch(state, 0, True, RANK, 3) == 0
    assert guard.switch(state, 1, True, RANK, 3) == 1  # more caution, urgent: immediately
    assert [guard.switch(state, 0, True, RANK, 3) for _ in range(4)] == [1, 1, 1, 0]  # less: after 3 steps held
    assert [guard.switch(state, 1, False, RANK, 3) for _ in range(5)] == [0, 0, 0, 1, 1]  # not urgent: the dwell


def _memory_of(points):
    """A one-step hit memory holding the robot-frame ``points`` of a robot at the origin facing +x."""
    memory = np.zeros((1, len(points), 3))
    memory[0, :, :2], memory[0, :, 2] = points, 1.0
    return memory


def test_turning_room_of_a_wall_ahead():
    y = np.linspace(-3, 3, 61)
    for distance in (0.8, 1.5, 3.0):
        memory = _memory_of(np.column_stack([np.full_like(y, distance), y]))
        left, right, ahead = guard.turning_room(memory, 0.0, 0.0, 0.0, 0.3, TURN_RADIUS)
        # a half turn reaches R ahead of the robot, its body 0.3 m further (eq IV.1)
        assert left == pytest.approx(distance - TURN_RADIUS - 0.3, abs=0.02) == right
        assert ahead == pytest.approx(distance - 0.3)


def test_hit_memory_keeps_world_points_seen_from_the_new_pose():
    memory = np.zeros((2, 3, 3))  # 2 steps, 2 rays + the cone echo
    angles = np.array([0.0, 0.5])
    guard.remember(memory, 0, Pose(1.0, 2.0, np.pi / 2), Reading(np.array([1.0, 4.0]), angles, 4.0, np.inf, 0.0), 0.26)
    np.testing.assert_allclose(memory[0, :, 2], [1.0, 0.0, 0.0])  # the max-range reading is no hit, no echo
    np.testing.assert_allclose(memory[0, 0, :2], [1.0, 3.0], atol=1e-12)
    guard.remember(memory, 1, Pose(1.0, 2.5, np.pi / 2), Reading(np.array([4.0, 4.0]), angles, 4.0, 2.0, 0.1), 0.26)
    np.testing.assert_allclose(memory[1, 2, 2], 1.0)  # the nearest point within the cone: an echo
    x, y = guard.local(memory, 0, 0, 1.0, 2.5, np.cos(np.pi / 2), np.sin(np.pi / 2))
    assert (x, y) == pytest.approx((0.5, 0.0), abs=1e-12)  # remembered, now 0.5 m ahead


@pytest.mark.parametrize("name, controller", [("fig-IV-15a", "fuzzy-2b-layered"), ("fig-IV-15b", "fuzzy-2b-layered"),
                                              ("fig-IV-23", "fuzzy-5b-layered")])
def test_few_switches_and_no_steering_chatter(name, controller):
    scenario = load_scenario(name)
    trace = run_episode(scenario, make_controller(controller))
    assert trace.reached
    changes = trace.behaviour_changes()
    labels = trace.behaviour
    flip_backs = [(a, b) for a, b in zip(changes, changes[1:]) if b - a < 3 and labels[b] == labels[a - 1]]
    assert len(changes) <= 20 and len(flip_backs) <= 1  # step-to-step A -> B -> A: at most one urgent re-entry
    flips = np.sum(np.abs(np.diff(trace.steering)) > np.pi / 10)
    assert flips <= 12  # steering jumps of more than 18° are rare events, not a buzz
    assert len(merged_changes(trace)) <= 12  # a handful of lettered points, as Fig IV.15's A…H


def test_start_facing_a_wall_turns_at_full_lock_without_collision():
    scenario = scenario_from_dict({
        "robot": {"x": 10.0, "y": 10.0, "theta": 0.0}, "goal": {"x": 4.0, "y": 10.0},
        "obstacles": [{"wall": {"start": [11.8, 6.0], "end": [11.8, 14.0], "thickness": 0.2}}], "max_time": 60})
    for controller in ("fuzzy-5b-thesis", "fuzzy-2b-thesis"):
        trace = run_episode(scenario, make_controller(controller))
        assert trace.reached, controller
        assert np.abs(trace.steering[:30]).max() == pytest.approx(np.pi / 5)


def test_step_clearance_is_the_gap_after_one_straight_step():
    memory = _memory_of([[1.0, 0.0], [0.0, 2.0]])
    # eq IV.2: the next position is V Δt straight ahead, the body a disc of 0.3 m
    assert guard.step_clearance(memory, 0.0, 0.0, 0.0, 2.0 * 0.1, 0.3) == pytest.approx(1.0 - 0.2 - 0.3)
    memory[..., 2] = 0.0
    assert guard.step_clearance(memory, 0.0, 0.0, 0.0, 0.2, 0.3) == np.inf


def test_safety_stop_turns_a_hidden_wall_end_into_a_stop():
    controller = "fuzzy-5b-layered"
    # mixed-0-009: a thin wall end hides between the rays until no turn is free (README)
    world = generate_worlds("mixed", 10, 0)[9]
    unguarded = run_episode(world, make_controller(controller, layers=("orbit_guard", "turning_room", "hysteresis")), seed=0)
    assert unguarded.collision
    guarded = run_episode(world, make_controller(controller), seed=0)
    assert not guarded.collision and guarded.outcome == "timeout"
    assert guarded.speed[-1] == 0.0 and world.world.clearance(guarded.pose[-1:, :2])[0] > 0.3
