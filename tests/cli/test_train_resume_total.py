"""``fuzzynav train ... --resume`` reaches the requested total, episode by episode (the thesis'
protocol) and with ``--parallel N``, also when the checkpoint's last batch was a smaller one (a
budget that is not a multiple of the batch)."""

import json

import pytest

from fuzzynav.cli import main


def _curve_sizes(checkpoint):
    return [len(row) for row in json.loads(checkpoint.read_text())["curve"]["success"]]


@pytest.mark.slow
def test_resume_after_a_smaller_last_batch_runs_to_the_total(tmp_path, capsys):
    out = tmp_path / "fql.json"
    parallel = ["--parallel", "50"]
    assert main(["train", "fql-goal", "--episodes", "30", "--quiet", "--out", str(out), *parallel]) == 0
    steering = tmp_path / "fql.json.steering.checkpoint.json"
    assert _curve_sizes(steering) == [22]  # 30 episodes: 22 steering (one batch of 22), 8 speed
    capsys.readouterr()
    assert main(["train", "fql-goal", "--episodes", "60", "--quiet", "--json", "--out", str(out), "--resume",
                 *parallel]) == 0
    result = json.loads(capsys.readouterr().out)
    assert _curve_sizes(steering) == [22, 23]  # 45 steering episodes: the 22 done, then the 23 missing
    assert result["steering"]["episodes"] + result["speed"]["episodes"] == 60


@pytest.mark.slow
def test_resume_episode_by_episode_runs_to_the_total(tmp_path, capsys):
    out = tmp_path / "fql.json"
    assert main(["train", "fql-goal", "--episodes", "30", "--quiet", "--out", str(out)]) == 0
    steering = tmp_path / "fql.json.steering.checkpoint.json"
    assert _curve_sizes(steering) == [1] * 22  # the thesis' protocol: one robot, one episode a batch
    capsys.readouterr()
    assert main(["train", "fql-goal", "--episodes", "60", "--quiet", "--json", "--out", str(out), "--resume"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert _curve_sizes(steering) == [1] * 45
    assert result["steering"]["episodes"] + result["speed"]["episodes"] == 60


def test_resume_without_a_checkpoint_says_it_trained_from_the_start(tmp_path, capsys):
    out = tmp_path / "q.json"
    assert main(["train", "q-goal", "--episodes", "5", "--quiet", "--out", str(out), "--resume"]) == 0
    assert "--resume: no checkpoint at" in capsys.readouterr().err
    assert main(["train", "q-goal", "--episodes", "10", "--quiet", "--out", str(out), "--resume"]) == 0
    err = capsys.readouterr().err  # the checkpoint of the first run was there, and the run says so
    assert "no checkpoint" not in err
    assert err.strip() == f"--resume: the steering phase goes on from {out}.steering.checkpoint.json, 5 episodes done"


def test_resume_of_a_one_pass_task_is_refused_without_promising_a_fresh_start(tmp_path, capsys):
    assert main(["train", "anfis-tracker", "--resume", "--out", str(tmp_path / "a.json")]) == 2
    err = capsys.readouterr().err
    assert "--resume: not supported" in err and "training from the start" not in err
