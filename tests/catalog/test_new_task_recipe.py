"""CONTRIBUTING.md's recipe for a training task holds: a task module plus its one line in
``catalog.tasks.TASKS`` is all ``fuzzynav train`` and ``fuzzynav run --model`` need."""

import json

from fuzzynav.catalog import tasks
from fuzzynav.cli import main

ENTRY = ("tests.catalog.toy_task:train_toy", "toy-q-goal", "toy tabular goal seeker (tests)")


def add_task(monkeypatch):
    """What the one line in TASKS does once the catalog is imported: the task, its trainer, its loader."""
    monkeypatch.setitem(tasks.TASKS, "toy", ENTRY)
    monkeypatch.setitem(tasks.TRAINERS, "toy", (ENTRY[0], ENTRY[2]))
    monkeypatch.setitem(tasks.MODEL_LOADERS, ENTRY[1], "tests.catalog.toy_task:load_model")


def test_the_loader_of_a_kind_is_the_load_model_of_its_task_module():
    for task, (train, kind, _) in tasks.TASKS.items():
        assert tasks.MODEL_LOADERS[kind] == train.split(":")[0] + ":load_model", task


def test_a_new_task_trains_and_its_model_runs(monkeypatch, capsys, tmp_path):
    add_task(monkeypatch)
    out = tmp_path / "toy.npz"
    assert main(["train", "toy", "--episodes", "100", "--quiet", "--out", str(out)]) == 0
    assert "steering: 100 episodes" in capsys.readouterr().out
    assert main(["run", "example-goal", "--model", str(out), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["controller"] == "toy" and result["outcome"] in ("reached", "timeout", "collision")
    assert "toy" in tasks.available()
