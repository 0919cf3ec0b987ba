"""Goal seeking (Table IV.1, §IV.5.1): closed loop on the built-in scenarios and many start/goal pairs."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.base import BatchController, thesis_angle_error
from fuzzynav.control.goal_seeking import GoalSeekingController, GuardedGoalSeeking
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.sim import run_episode
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import load_scenario, scenario_from_dict


class RawTable(BatchController):
    """Table IV.1 without the anti-orbit guard (the orbiting of docs/thesis.md, chapter IV)."""

    def __init__(self, sign=1.0):
        self.system, self.sign = goal_seeking(), sign

    def act_batch(self, obs):
        out = self.system.evaluate(np.column_stack([obs.target_distance,
                                                    self.sign * thesis_angle_error(obs.target_bearing)]))
        return out[:, 0], out[:, 1], np.full(len(out), "raw")


def _open_world(goal, tolerance=0.3, max_time=60, robot=(10, 10)):
    """The empty workspace with a goal; ``robot`` is the scenario's start (a batch's ``starts`` replace it)."""
    return scenario_from_dict({"robot": {"x": robot[0], "y": robot[1]}, "goal": {"x": goal[0], "y": goal[1],
                                                                                 "tolerance": tolerance},
                               "max_time": max_time})


@pytest.mark.parametrize("name", ["fig-IV-12a", "fig-IV-12b", "fig-IV-13"])
def test_builtin_free_navigation_reaches_the_goal_and_stops(name):
    scenario = load_scenario(name)
    trace = run_episode(scenario, make_controller("goal-seeking"))
    assert trace.outcome == "reached"
    assert trace.speed[-1] < 0.15  # the speed falls to ~0 at the goal (Figs IV.12, IV.14)
    assert trace.speed.max() > 1.8  # and is high when far and aligned


def test_fig_IV_14_commands_turn_left_first_then_accelerate():
    trace = run_episode(load_scenario("fig-IV-13"), make_controller("goal-seeking"))
    assert trace.steering[0] >= np.pi / 10 - 1e-9  # positive (left) steering towards the goal: PM when far
    assert trace.speed[0] <= 1.0 + 1e-9  # at the low speed F
    k = int(np.argmax(trace.speed))
    assert trace.speed[k] > 3.0 and abs(trace.steering[k]) < 0.05  # full speed once aligned


def test_many_starts_converge_in_one_batch():
    rng = np.random.default_rng(3)
    starts = np.column_stack([rng.uniform(2, 18, 60), rng.uniform(2, 18, 60), rng.uniform(-np.pi, np.pi, 60)])
    starts = starts[np.hypot(starts[:, 0] - 10, starts[:, 1] - 10) > 1.0]
    sim = BatchSimulator(_open_world((10, 10), robot=(2, 2)), GoalSeekingController(), starts=starts, record=False).run()
    assert sim.outcomes().count("reached") == len(starts)


def test_literal_sign_steers_away_and_the_flip_fixes_it():
    starts = np.array([[4.0, 4.0, 0.0], [16.0, 4.0, 2.0], [4.0, 16.0, -1.0], [16.0, 16.0, 3.0]])
    world = _open_world((10, 10), robot=(2, 2))  # a goal at the scenario's own start is refused
    literal = BatchSimulator(world, RawTable(sign=-1.0), starts=starts, record=False).run()
    flipped = BatchSimulator(world, RawTable(sign=1.0), starts=starts, record=False).run()
    assert literal.outcomes().count("reached") == 0
    assert flipped.outcomes().count("reached") == 4


def test_goal_inside_the_turning_circle_orbits_without_the_guard():
    # goal 0.6 m to the left of a robot heading +x: inside the circle of radius l/tan(π/5) = 0.69 m
    # (tolerance 0.3 m: Table IV.1's speed is Z at d_rg = 0.1 m, so no tolerance below that is met)
    scenario = _open_world((10.0, 10.6), tolerance=0.3, max_time=40)
    raw = run_episode(scenario, RawTable())
    guarded = run_episode(scenario, GoalSeekingController())
    assert raw.outcome == "timeout"
    assert guarded.outcome == "reached"


def test_guard_modes():
    gsb = GuardedGoalSeeking()
    steering, speed, guard = gsb(np.array([10.0, 1.0, 0.5]), np.array([0.3, 0.3, 1.2]))
    assert guard.tolist() == [0, 1, 2]
    assert steering[2] == 0.0 and steering[1] > 0  # left towards a goal on the left
    np.testing.assert_allclose(steering[1], np.arctan(2 * 0.5 * np.sin(0.3) / 1.0))
