"""Episodes to converge of real training runs do not depend on the training budget."""

from dataclasses import replace
from pathlib import Path

import pytest

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
    50-episode ones both judge 10-world windows and 15-world holds."""
    assert common.convergence_window(common.WORLD_CONVERGENCE, fql_avoid.AVOID_BATCH) == (100, 150)
    assert common.convergence_window(common.WORLD_CONVERGENCE, common.BATCH) == (500, 750)
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
