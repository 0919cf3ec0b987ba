"""fuzzy-2b-thesis (Fig IV.9, Table IV.2) and fuzzy-5b-thesis (Fig IV.16, Tables IV.3–IV.6) in closed loop."""

import numpy as np
import pytest

from fuzzynav.bench.evaluate import evaluate
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.sim import run_episode
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import load_scenario


def _changes(labels):
    return int(np.sum(labels[1:] != labels[:-1]))


@pytest.mark.parametrize("name", ["fig-IV-15a", "fig-IV-15b"])
def test_two_behaviours_reach_the_goal_past_the_circles(name):
    scenario = load_scenario(name)
    trace = run_episode(scenario, make_controller("fuzzy-2b-thesis"))
    assert trace.outcome == "reached" and not trace.collision
    assert trace.speed[-1] < 0.15
    assert {"GSB", "OA"} <= set(trace.behaviour.tolist())
    assert _changes(trace.behaviour) >= 2  # switches A, B, … of Fig IV.15


def test_goal_seeking_alone_collides_where_fuzzy_2b_avoids():
    scenario = load_scenario("fig-IV-15a")
    assert run_episode(scenario, make_controller("goal-seeking")).outcome == "collision"


@pytest.mark.parametrize("name", ["fig-IV-22a", "fig-IV-22b", "fig-IV-23", "fig-IV-15a"])
def test_five_behaviours_reach_the_goal_in_unknown_worlds(name):
    trace = run_episode(load_scenario(name), make_controller("fuzzy-5b-thesis"))
    assert trace.outcome == "reached" and not trace.collision
    assert trace.speed[-1] < 0.15
    assert any(label.endswith("+VRB") for label in trace.behaviour)


def test_u_shaped_wall_is_followed_to_the_goal_inside():
    scenario = load_scenario("fig-IV-23")
    trace = run_episode(scenario, make_controller("fuzzy-5b-thesis"))
    labels = set(trace.behaviour.tolist())
    assert trace.outcome == "reached"
    assert labels & {"ROA+VRB", "LOA+VRB"}  # along the walls (Fig IV.23: "suivi de mur")
    assert trace.pose[:, 1].min() < 5.0  # it went round the U, below its open side (y = 5)


def test_vrb_lowers_the_speed_near_obstacles():
    trace = run_episode(load_scenario("fig-IV-22a"), make_controller("fuzzy-5b-thesis"))
    near = trace.ranges[:-1].min(axis=1) < 1.5
    assert near.any() and trace.speed[near].max() <= 1.0 + 1e-9
    assert trace.speed[~near].max() > 2.0


def test_batch_equals_one_robot_at_a_time():
    scenario = load_scenario("fig-IV-22b")
    rng = np.random.default_rng(0)
    starts = np.column_stack([rng.uniform(2, 4, 6), rng.uniform(14, 16, 6), rng.uniform(-1, 1, 6)])
    batch = BatchSimulator(scenario, make_controller("fuzzy-5b-thesis"), starts=starts, max_time=15).run()
    single = [BatchSimulator(scenario, [make_controller("fuzzy-5b-thesis")], starts=s, max_time=15).run() for s in starts]
    np.testing.assert_allclose(batch.pose, np.vstack([s.pose for s in single]), atol=1e-12)
    assert batch.outcomes() == [s.outcomes()[0] for s in single]


@pytest.mark.slow
def test_fuzzy_2b_on_circle_worlds():
    result = evaluate("fuzzy-2b-thesis", "circles", n=15, seed=0)
    assert result["success_rate"] >= 0.85  # 100 worlds: see the README / `fuzzynav evaluate`


@pytest.mark.slow
def test_fuzzy_5b_on_mixed_worlds():
    result = evaluate("fuzzy-5b-thesis", "mixed", n=15, seed=0)
    assert result["success_rate"] >= 0.8
