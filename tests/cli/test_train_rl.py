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
@pytest.mark.parametrize("stop", [signal.SIGINT, signal.SIGTERM, signal.SIGKILL], ids=["ctrl-c", "term", "kill-9"])
def test_resume_after_ctrl_c_or_kill_equals_an_uninterrupted_run(tmp_path, stop):
    args = ["fql-goal-traces", "--episodes", "1000", "--seed", "5", "--checkpoint-every", "100", "--quiet", "--parallel", "50"]
    whole, part = tmp_path / "whole.json", tmp_path / "part.json"
    assert main(["train", *args, "--out", str(whole)]) == 0
    checkpoint = tmp_path / "part.json.steering.checkpoint.json"
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    process = subprocess.Popen([sys.executable, "-m", "fuzzynav", "train", *args, "--out", str(part)], env=env,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               # a shell's background job inherits SIGINT ignored: restore it for the child
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.time() + 60
    while not checkpoint.exists() and time.time() < deadline and process.poll() is None:
        time.sleep(0.02)
    process.send_signal(stop)
    process.wait(timeout=60)
    expected = {signal.SIGINT: (130, "interrupted"), signal.SIGTERM: (143, "terminated")}.get(stop, (-stop, ""))
    err = process.stderr.read().decode()
    assert process.returncode == expected[0], err  # before the end
    assert expected[1] in err and "Traceback" not in err
    assert not part.exists()
    saved = json.loads(checkpoint.read_text())
    assert 0 < saved["episode"] < 20  # batches of 50 episodes (random starts)
    assert main(["train", *args, "--out", str(part), "--resume"]) == 0
    assert json.loads(part.read_text()) == json.loads(whole.read_text())
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")] == []


def _curve_sizes(checkpoint):
    return [len(row) for row in json.loads(checkpoint.read_text())["curve"]["mean_reward"]]


def test_episodes_is_the_total_with_a_smaller_last_batch(tmp_path, capsys):
    out = tmp_path / "q.json"
    assert train("q-goal", out, "--episodes", "70", "--parallel", "50", "--json") == 0
    result = json.loads(capsys.readouterr().out)
    assert result["steering"]["episodes"] == 70
    assert _curve_sizes(tmp_path / "q.json.steering.checkpoint.json") == [50, 20]  # one batch of 50, then 20
    assert train("q-goal", out, "--episodes", "7", "--json") == 0  # the thesis' protocol: one episode at a time
    assert _curve_sizes(tmp_path / "q.json.steering.checkpoint.json") == [1] * 7
    capsys.readouterr()
    out = tmp_path / "f.json"
    assert train("fql-goal", out, "--episodes", "5", "--parallel", "10", "--json") == 0  # fewer than a batch
    result = json.loads(capsys.readouterr().out)
    assert (result["steering"]["episodes"], result["speed"]["episodes"]) == (4, 1)  # SPEED_SHARE = 0.25
    assert _curve_sizes(tmp_path / "f.json.speed.checkpoint.json") == [1]
    assert json.loads(out.read_text())["training"]["speed"]["episodes"] == 1
    assert train("fql-goal", out, "--episodes", "1") == 2  # two phases need two episodes
    assert "--episodes" in capsys.readouterr().err


def test_resume_into_a_partial_batch_equals_an_uninterrupted_run(tmp_path):
    whole, part = tmp_path / "whole.json", tmp_path / "part.json"
    batches = ("--parallel", "50")
    assert train("q-goal", whole, "--episodes", "70", "--seed", "3", *batches) == 0
    assert train("q-goal", part, "--episodes", "50", "--seed", "3", *batches) == 0  # stopped after the full batch
    assert train("q-goal", part, "--episodes", "70", "--seed", "3", "--resume", *batches) == 0
    assert json.loads(part.read_text()) == json.loads(whole.read_text())


def test_a_curve_that_never_settled_reports_null_and_says_so(tmp_path, capsys):
    out = tmp_path / "q.json"
    assert train("q-goal", out, "--episodes", "100", "--json") == 0  # shorter than a window + the hold
    assert json.loads(capsys.readouterr().out)["steering"]["converged_at"] is None
    assert json.loads(out.read_text())["training"]["steering"]["converged_at"] is None
    assert train("q-goal", out, "--episodes", "100") == 0
    lines = capsys.readouterr().out.splitlines()
    line = next(line for line in lines if line.startswith("steering:"))
    assert "steering: 100 episodes, not converged within 100 episodes" in line and "101" not in line  # not the model path
    notes = [line for line in lines if "no plateau of the mean reward" in line]
    assert len(notes) == 1 and notes[0].startswith("note: success:")  # the words explained once, after the phases


def test_the_help_states_the_phases_shares_as_the_tasks_set_them(capsys):
    from fuzzynav.learn.tasks import common, fql_avoid

    with pytest.raises(SystemExit):
        main(["train", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    shares = {0.25: "a quarter", 0.5: "a half"}
    quarter, half = shares[common.SPEED_SHARE], shares[fql_avoid.AVOID_SPEED_SHARE]
    assert f"speed phase {quarter} (fql-goal, fql-goal-35, fql-wall) or {half} (fql-avoid)" in text


def test_reinforcement_learning_checkpoints_every_100_episodes_unless_told(tmp_path, monkeypatch):
    """A Ctrl-C'd run must leave a checkpoint for --resume without --checkpoint-every."""
    from fuzzynav.learn import checkpoint

    saved = []
    real = checkpoint.save_checkpoint
    monkeypatch.setattr(checkpoint, "save_checkpoint",
                        lambda path, learner, rng, episode, *rest: (saved.append(episode), real(path, learner, rng, episode, *rest)))
    assert train("q-goal", tmp_path / "q.json", "--episodes", "250") == 0
    assert saved == [100, 200, 250]
    saved.clear()
    assert train("q-goal", tmp_path / "r.json", "--episodes", "250", "--checkpoint-every", "120") == 0
    assert saved == [120, 240, 250]


def test_a_stopped_training_says_how_to_go_on(tmp_path, monkeypatch, capsys):
    from fuzzynav.catalog import tasks

    def stopped(request):
        raise KeyboardInterrupt

    monkeypatch.setattr(tasks, "trainer", lambda task: stopped)
    assert train("fql-goal", tmp_path / "m.json") == 130
    assert capsys.readouterr().err.strip() == ("interrupted: the same command with --resume goes on from the last "
                                               "checkpoint (m.json.….checkpoint.json)")
    assert main(["train", "anfis-tracker", "--out", str(tmp_path / "a.json"), "--quiet"]) == 130  # trains in one go
    assert capsys.readouterr().err.strip() == "interrupted"
