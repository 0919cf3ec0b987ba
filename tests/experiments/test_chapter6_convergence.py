"""Episodes to converge of real training runs do not depend on the training budget."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from fuzzynav.learn.curves import episodes_to_converge
from fuzzynav.learn.tasks import common, fql_avoid, fql_goal, tabular_goal
from fuzzynav.learn.tasks.common import TrainRequest


@pytest.mark.slow
def test_fixed_start_fql_converges_at_the_same_episode_with_twice_the_budget(tmp_path):
    """Under the thesis' protocol (the default of TrainRequest)."""
    task = replace(fql_goal.GOAL_TASKS["fql-goal"], fixed=True, learn_speed=False)
    counts = []
    for episodes in (1000, 2000):
        request = TrainRequest(out=tmp_path / f"fixed-{episodes}.json", episodes=episodes, seed=1, progress=False)
        steering = fql_goal.train_goal_fql(task, request)["steering"]
        assert steering["episodes"] == episodes
        counts.append(steering["converged_at"])
    assert counts[0] == counts[1]  # the criterion reads the first k + 500 episodes only
    assert counts[0] <= 1000 - common.GOAL_CONVERGENCE["hold"]  # settled within the shorter budget
    # the thesis' protocol: one robot, so the count is any single episode (no batch to round up to)


def test_world_tasks_count_their_window_in_worlds():
    """One batch is one random world: the avoider's 10-episode batches and the wall follower's
    50-episode ones both judge 10-world windows and 15-world holds; the thesis' single robot
    (a new world every episode) judges 100-episode windows and a 500-episode hold."""
    assert common.convergence_window(common.WORLD_CONVERGENCE, fql_avoid.AVOID_BATCH) == (100, 150)
    assert common.convergence_window(common.WORLD_CONVERGENCE, common.BATCH) == (500, 750)
    assert common.convergence_window(common.WORLD_CONVERGENCE, 1) == (100, 500)
    assert common.convergence_window(common.GOAL_CONVERGENCE, common.BATCH) == (50, 500)  # goal tasks: in episodes
    steering = next(fql_avoid.fql_avoid_phases(Path("avoid.json"), 200))
    assert steering.env.batch == fql_avoid.AVOID_BATCH and steering.convergence is common.WORLD_CONVERGENCE


def test_the_curve_plot_marks_the_count_the_training_reports(tmp_path, monkeypatch):
    """``--curve`` marks each phase's own episodes to converge (its task's criterion and window),
    not a recount under the plot's defaults."""
    import fuzzynav.viz.curves as curves

    marked, plot = [], curves.plot_learning_curve
    monkeypatch.setattr(curves, "plot_learning_curve",
                        lambda values, **kw: marked.append((kw["window"], kw["converged_at"])) or plot(values, **kw))
    request = TrainRequest(out=tmp_path / "q.json", episodes=800, seed=0, progress=False, curve=tmp_path / "q.png")
    summary = tabular_goal.train_q_goal(request)["steering"]
    assert (tmp_path / "q.png").stat().st_size > 0
    assert summary["converged_at"] is not None and marked == [(common.GOAL_CONVERGENCE["window"], summary["converged_at"])]


def _world_curve(rise_until: int, n: int = 1500, seed: int = 0, rise: float = 0.15):
    """A one-robot world task's rewards: σ 0.25 per episode (the avoider's), rising by ``rise``
    up to episode ``rise_until`` then flat (the avoider's curves rise −0.37 → −0.22)."""
    rng = np.random.default_rng(seed)
    level = -0.37 + rise * np.minimum(np.arange(n) / rise_until, 1.0)
    return level + rng.normal(0.0, 0.25, n)


@pytest.mark.parametrize("seed", range(3))
def test_one_robot_world_criterion_sees_a_rise_the_first_window_cannot_pass(seed):
    """The thesis' single robot on random worlds: a curve that rises over its first 400 episodes
    converges once the rise is (mostly) over, not at its first window — the former 5-episode
    "worlds" (window 50, hold 75, 3 standard errors) answered the first window on such a curve."""
    curve = _world_curve(400, seed=seed)
    k = common.converged_at(curve, np.ones_like(curve), 1, common.WORLD_CONVERGENCE)
    assert 200 <= k <= 1000
    former = episodes_to_converge(curve, window=50, hold=75, clustered=True)
    assert former < 200  # the defect the one-robot settings remove


def test_one_robot_world_criterion_can_fail():
    """A curve still rising at the end of its budget (0.2 per 500 episodes) has not converged
    (count = budget + 1), and one flat from the start converges at its first window."""
    rising = _world_curve(1500, n=1500, rise=0.6)
    assert common.converged_at(rising, np.ones_like(rising), 1, common.WORLD_CONVERGENCE) == rising.size + 1
    flat = _world_curve(1, n=1500)
    assert common.converged_at(flat, np.ones_like(flat), 1, common.WORLD_CONVERGENCE) < 300
