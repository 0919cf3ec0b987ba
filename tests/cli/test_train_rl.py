"""``fuzzynav train`` for the chapter VI tasks: model files that run, resume after Ctrl-C equals an
uninterrupted run, learning-curve plot."""

import json
import os
import signal
import subprocess
import sys
import time

import pytest

from fuzzynav.cli import main

GOAL_SCENARIO = """name: open-goal
robot: {x: 3.0, y: 4.0, theta: 2.5}
goal: {x: 15.0, y: 14.0, tolerance: 0.3}
max_time: 60
"""


def train(task, out, *extra):
    return main(["train", task, "--out", str(out), "--quiet", *extra])


@pytest.mark.slow
@pytest.mark.parametrize("task", ["q-goal", "fql-goal"])
def test_trained_goal_models_drive_to_the_goal(tmp_path, capsys, task):
    out = tmp_path / f"{task}.json"
    assert train(task, out, "--episodes", "600", "--seed", "2", "--curve", str(tmp_path / "c.png")) == 0
    assert (tmp_path / "c.png").stat().st_size > 0
    scenario = tmp_path / "goal.yaml"
    scenario.write_text(GOAL_SCENARIO)
    capsys.readouterr()
    assert main(["run", str(scenario), "--model", str(out), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["outcome"] == "reached"


def test_fql_model_is_a_readable_rule_table(tmp_path, capsys):
    out = tmp_path / "m.json"
    assert train("fql-goal", out, "--episodes", "200") == 0
    capsys.readouterr()
    assert main(["fis", "show", str(out)]) == 0  # the model file is an ordinary fuzzy system
    shown = capsys.readouterr().out
    assert "theta \\ drg" in shown and "output v" in shown
    document = json.loads(out.read_text())
    assert document["kind"] == "fql-goal" and document["format"] == "fuzzynav-fis"
    assert len(document["rules"]) == 15
    assert all(r.startswith("IF drg IS") and "THEN alpha IS" in r and "AND v IS" in r for r in document["rules"])


@pytest.mark.slow
def test_resume_after_ctrl_c_equals_an_uninterrupted_run(tmp_path):
    args = ["fql-goal-traces", "--episodes", "1000", "--seed", "5", "--checkpoint-every", "100", "--quiet"]
    whole, part = tmp_path / "whole.json", tmp_path / "part.json"
    assert main(["train", *args, "--out", str(whole)]) == 0
    checkpoint = tmp_path / "part.json.steering.checkpoint.json"
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    process = subprocess.Popen([sys.executable, "-m", "fuzzynav", "train", *args, "--out", str(part)], env=env,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.time() + 60
    while not checkpoint.exists() and time.time() < deadline and process.poll() is None:
        time.sleep(0.02)
    process.send_signal(signal.SIGINT)
    process.wait(timeout=60)
    assert process.returncode == 130, process.stderr.read()  # interrupted before the end
    assert not part.exists()
    saved = json.loads(checkpoint.read_text())
    assert 0 < saved["episode"] < 20  # batches of 50 episodes (random starts)
    assert main(["train", *args, "--out", str(part), "--resume"]) == 0
    assert json.loads(part.read_text()) == json.loads(whole.read_text())
