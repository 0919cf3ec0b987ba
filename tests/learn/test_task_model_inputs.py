"""Learned model files (q-goal, fql-*): every bad field is an InputError naming the file and the
field — through ``fuzzynav run SCENARIO --model BAD.json`` (exit 2, no traceback) — and every
learned controller is named by its training task."""

import json

import pytest

from fuzzynav.cli import main
from fuzzynav.learn.tasks import tabular_goal

GOOD_Q = {"kind": "q-goal", "zone_edges": [1.0, 4.0], "n_sectors": 6, "merge_inner": True,
          "steering": [0.0, -0.6, 0.6], "speed": 1.0, "q": [[0.0, 0.0, 1.0]] * 13,
          "training": {"task": "q-goal"}}


def run_model(tmp_path, capsys, document):
    path = tmp_path / "BAD.json"
    path.write_text(json.dumps(document))
    capsys.readouterr()
    code = main(["run", "fig-IV-12a", "--model", str(path), "--json"])
    out, err = capsys.readouterr()
    return code, out, err, str(path)


@pytest.mark.parametrize("field, value", [
    ("q", [[0.0, float("nan"), 1.0]] + [[0.0, 0.0, 1.0]] * 12),
    ("q", [[0.0, 0.0, 1.0]] * 12),  # 12 rows for 13 states
    ("q", [[0.0, "x", 1.0]] * 13),
    ("speed", -1.0),
    ("speed", float("nan")),
    ("speed", "fast"),
    ("steering", [0, "x", 1]),
    ("steering", [0.0, float("inf"), 0.6]),
    ("steering", []),
    ("zone_edges", [4.0, 1.0]),
    ("zone_edges", ["1", 4.0]),
    ("n_sectors", 0),
    ("n_sectors", "x"),
    ("merge_inner", "yes"),
    ("training.task", {"task": 3}),
])
def test_a_bad_q_goal_field_is_named_without_a_traceback(tmp_path, capsys, field, value):
    document = dict(GOOD_Q, **{field.split(".")[0]: value})
    code, out, err, path = run_model(tmp_path, capsys, document)
    assert code == 2 and out == ""
    assert f"{path}: {field}:" in err, err
    assert "Traceback" not in err


@pytest.mark.parametrize("field, value, problem", [
    ("version", 99, "unsupported version 99"),
    ("version", True, "unsupported version True"),
    ("q_tabel", [[0.0, 0.0, 1.0]] * 13, "unknown key 'q_tabel'"),
])
def test_an_unknown_field_or_version_is_refused(tmp_path, capsys, field, value, problem):
    code, out, err, path = run_model(tmp_path, capsys, dict(GOOD_Q, **{field: value}))
    assert code == 2 and out == "" and f"{path}: {field}: {problem}" in err, err


def test_a_trained_q_goal_model_says_its_version(tmp_path):
    model = tmp_path / "q.json"
    assert main(["train", "q-goal", "--out", str(model), "--episodes", "4", "--quiet"]) == 0
    assert json.loads(model.read_text())["version"] == tabular_goal.Q_GOAL_VERSION  # and GOOD_Q, without it, loads


def test_a_missing_field_is_named(tmp_path, capsys):
    document = {k: v for k, v in GOOD_Q.items() if k != "steering"}
    code, _, err, path = run_model(tmp_path, capsys, document)
    assert code == 2 and f"{path}: steering: missing field" in err


def test_every_learned_model_is_named_by_its_training_task(tmp_path, capsys):
    code, out, _, _ = run_model(tmp_path, capsys, GOOD_Q)  # the good table drives: named q-goal
    assert code == 0 and json.loads(out)["controller"] == "q-goal"
    for task, kind in (("fql-goal-35", "fql-goal"), ("q-goal", "q-goal")):
        model = tmp_path / f"{task}.json"
        assert main(["train", task, "--out", str(model), "--episodes", "20", "--quiet"]) == 0
        assert json.loads(model.read_text())["kind"] == kind
        capsys.readouterr()
        assert main(["run", "fig-IV-12a", "--model", str(model), "--json"]) == 0
        assert json.loads(capsys.readouterr().out)["controller"] == task


def test_the_loader_gives_the_trained_greedy_policy():
    controller = tabular_goal.load_model(GOOD_Q, "m.json")
    assert controller.greedy.tolist() == [2] * 13 and controller.speed == 1.0
