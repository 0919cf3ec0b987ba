"""The thesis' protocol is the default of every reinforcement-learning task (one robot, q = 0, the
conclusion of best quality); ``--parallel N`` is the batch learner; ``--prior none`` learns avoidance
from nothing and the model says how many rules it changed."""

import json

import numpy as np
import pytest

from fuzzynav.catalog.tasks import load_controller
from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.experiments.chapter6 import initial_avoider
from fuzzynav.experiments.evaluation import evaluate_avoid
from fuzzynav.learn.envs import GridPremise
from fuzzynav.learn.schedules import InverseVisits
from fuzzynav.learn.tasks import common, fql_avoid, fql_goal, fql_wall, tabular_goal
from fuzzynav.learn.tasks.common import TrainRequest


def test_one_robot_zero_q_and_best_quality_unless_parallel_is_asked(tmp_path):
    assert common.robots(TrainRequest(out=tmp_path / "m.json")) == 1
    assert common.robots(TrainRequest(out=tmp_path / "m.json", parallel=50)) == 50
    assert common.extraction_tolerance(1, 0.05) == 0.0 and common.extraction_tolerance(50, 0.05) == 0.05
    learner = common.fql_learner(GridPremise(fql_avoid.avoid_template()), np.zeros((16, 3)), batch=1)
    assert np.all(learner.q == 0.0) and isinstance(learner.alpha, InverseVisits) and learner.alpha.floor == 0.01
    steering = next(fql_avoid.fql_avoid_phases(tmp_path / "a.json", 10, batch=1, prior="none"))
    assert steering.env.batch == 1 and tuple(steering.learner.prior[0]) == (1,) * 16  # Z: nothing chosen
    # the avoider values the state a collision reaches, as Algorithm VI.1 writes it; the batch learner does not
    assert steering.learner.terminal_bootstrap
    parallel = next(fql_avoid.fql_avoid_phases(tmp_path / "p.json", 10, batch=10, prior="none"))
    assert not parallel.learner.terminal_bootstrap
    # so does the wall follower, in both phases
    steering, speed = fql_wall.fql_wall_phases(tmp_path / "w.json", 10, batch=1)
    assert steering.learner.terminal_bootstrap and speed.learner.terminal_bootstrap
    assert not next(fql_wall.fql_wall_phases(tmp_path / "wp.json", 10, batch=10)).learner.terminal_bootstrap
    # and the goal seekers (every FQL task of the thesis' protocol: common.fql_learner)
    task = fql_goal.GOAL_TASKS["fql-goal"]
    assert all(phase.learner.terminal_bootstrap for phase in fql_goal.goal_fql_phases(task, tmp_path / "g.json", 10))
    assert not next(fql_goal.goal_fql_phases(task, tmp_path / "gp.json", 10, batch=10)).learner.terminal_bootstrap


def test_the_initial_tables_of_the_priors():
    assert fql_avoid.initial_tables("none") == ((1,) * 16, 1)
    assert fql_avoid.initial_tables("thesis") == (fql_avoid.avoid_prior(), 0)
    with pytest.raises(Exception, match="--prior"):
        fql_avoid.initial_tables("chapter-iv")


@pytest.mark.parametrize("args, field", [(["fql-goal", "--prior", "none"], "--prior"),
                                         (["fql-goal", "--parallel", "0"], "--parallel"),
                                         (["anfis-tracker", "--parallel", "4"], "--parallel")])
def test_flags_a_task_does_not_take_are_refused_in_one_line(tmp_path, capsys, args, field):
    try:
        status = main(["train", *args, "--out", str(tmp_path / "m.json")])
    except SystemExit as refused:  # argparse's own refusal of a value out of bounds (--parallel 0)
        status = refused.code
    assert status == 2
    err = capsys.readouterr().err
    assert field in err and "Traceback" not in err and not (tmp_path / "m.json").exists()


@pytest.mark.slow
def test_an_avoider_learned_from_zero_q_differs_from_its_initial_table_and_beats_it(tmp_path, capsys):
    """A short version of fig-VI-22 (the full protocol, 2,000 episodes, runs in ``reproduce``)."""
    out = tmp_path / "avoid.json"
    assert main(["train", "fql-avoid", "--prior", "none", "--episodes", "300", "--seed", "1", "--out", str(out),
                 "--quiet"]) == 0
    training = json.loads(out.read_text())["training"]
    assert training["protocol"] == "thesis" and training["prior"] == "none"
    assert 1 <= training["rules_changed"] <= training["rules_learned"] == 14
    capsys.readouterr()
    assert main(["fis", "show", str(out)]) == 0
    assert f"{training['rules_changed']} of 14 rules differ from the initial table" in capsys.readouterr().out
    learned, initial = evaluate_avoid(load_controller(out), 20), evaluate_avoid(initial_avoider(), 20)
    assert learned["success"] > initial["success"] and learned["collisions"] < initial["collisions"]


@pytest.mark.slow
def test_parallel_is_the_batch_learner_and_its_model_says_so(tmp_path):
    out = tmp_path / "goal.json"
    assert main(["train", "fql-goal", "--parallel", "10", "--episodes", "40", "--out", str(out), "--quiet"]) == 0
    training = json.loads(out.read_text())["training"]
    assert training["protocol"] == "parallel" and training["robots_per_batch"] == 10
    checkpoint = json.loads(common.checkpoint_path(out, "steering").read_text())
    assert checkpoint["extra"]["batch"] == 10 and len(checkpoint["curve"]["success"]) == 3  # 30 episodes: 3 batches


def test_fig_vi_8s_tabular_learner_explores_and_learns_as_fql_does():
    """Fig VI.8 against Fig VI.1: with ``schedule="fql"`` the tabular learner's ε and β are FQL's
    under the thesis' protocol, not its own faster-decaying ones; a bad schedule is refused."""
    alpha, policy = common.thesis_schedules()
    _, tabular, _, _ = tabular_goal.q_goal_parts(fixed=True, batch=1, schedule="fql")
    _, own, _, _ = tabular_goal.q_goal_parts(fixed=True, batch=1)
    episodes = np.array([0, 100, 500, 2000])
    assert np.array_equal(tabular.policy.epsilon(episodes), policy.epsilon(episodes))
    assert tabular.alpha == alpha
    assert not np.array_equal(own.policy.epsilon(episodes), policy.epsilon(episodes))
    assert own.alpha != alpha
    with pytest.raises(InputError, match="schedule"):
        tabular_goal.q_goal_parts(schedule="fast")
