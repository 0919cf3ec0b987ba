"""CONTRIBUTING.md's recipe for a training task holds: a task module plus its one registration
(:func:`fuzzynav.catalog.tasks.register_task`, or an entry point of an installed distribution) is
all ``fuzzynav train`` and ``fuzzynav run --model`` need."""

import json

import pytest

from fuzzynav.catalog import tasks
from fuzzynav.catalog.specs import TaskSpec
from fuzzynav.cli import main
from tests.catalog.plugins import installed

TOY = TaskSpec("toy", "tests.catalog.toy_task:train_toy", "toy-q-goal", "toy tabular goal seeker (tests)")


@pytest.fixture
def toy():
    """The one registration line, from outside the package, undone after the test."""
    tasks.register_task(TOY)
    yield
    tasks.TASKS.unregister("toy")


def test_the_loader_of_a_kind_is_the_load_model_of_its_task_module():
    for task, spec in tasks.TASKS.items():
        assert tasks.model_loaders()[spec.kind] == spec.trainer.split(":")[0] + ":load_model", task
    assert TOY.loader == "tests.catalog.toy_task:load_model"


def test_a_task_name_or_a_kind_read_by_another_loader_is_refused():
    with pytest.raises(ValueError, match="'fql-goal' is already registered"):
        tasks.register_task(TaskSpec("fql-goal", "tests.catalog.toy_task:train_toy", "toy-q-goal", "twin"))
    with pytest.raises(ValueError, match="model kind 'fql-goal' is already read by fuzzynav.learn.tasks.fql_goal"):
        tasks.register_task(TaskSpec("toy-2", "tests.catalog.toy_task:train_toy", "fql-goal", "a toy"))
    assert "toy-2" not in tasks.TASKS


def test_the_tasks_a_model_kind_drives_are_checked_and_one_per_kind():
    with pytest.raises(ValueError, match="tasks must be some of goal, path, target"):
        TaskSpec("toy-3", "tests.catalog.toy_task:train_toy", "toy-3", "a toy", tasks=("fly",))
    with pytest.raises(ValueError, match="tasks must be some of"):
        TaskSpec("toy-3", "tests.catalog.toy_task:train_toy", "toy-3", "a toy", tasks="goal")
    tracker = TaskSpec("toy-4", "fuzzynav.learn.tasks.trackers:train_toy", "anfis-tracker", "a toy", tasks=("goal",))
    with pytest.raises(ValueError, match="model kind 'anfis-tracker' drives path, target tasks"):
        tasks.register_task(tracker)
    assert "toy-4" not in tasks.TASKS


def _train_and_run(capsys, tmp_path):
    out = tmp_path / "toy.npz"
    assert main(["train", "toy", "--episodes", "100", "--quiet", "--out", str(out)]) == 0
    assert "steering: 100 episodes" in capsys.readouterr().out
    assert main(["run", "example-goal", "--model", str(out), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["controller"] == "toy" and result["outcome"] in ("reached", "timeout", "collision")
    assert result["path_length_m"] > 1.0  # the model drives the robot
    assert "toy" in tasks.available()


def test_a_new_task_trains_and_its_model_runs(toy, capsys, tmp_path):
    _train_and_run(capsys, tmp_path)


def test_a_task_from_an_installed_distribution(monkeypatch, capsys, tmp_path):
    with installed(monkeypatch, tmp_path / "site", tasks.TASKS, {"toy": "tests.catalog.test_new_task_recipe:TOY"}):
        _train_and_run(capsys, tmp_path)
    assert "toy" not in tasks.TASKS
