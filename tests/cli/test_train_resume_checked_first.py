"""``fuzzynav train --resume`` checks every checkpoint it would go on from before it says where it
resumes (it used to print "--resume: the steering phase goes on from ..." for each phase, then
refuse the seed); a later phase's checkpoint is checked only while the phases before it are
complete, as only then does the run go on from it."""

import json

import pytest

from fuzzynav.cli import main


@pytest.fixture(scope="module")
def trained(tmp_path_factory):
    """fql-goal, 8 episodes with seed 5: 6 steering, 2 speed."""
    out = tmp_path_factory.mktemp("fql") / "a.json"
    assert main(["train", "fql-goal", "--episodes", "8", "--seed", "5", "--quiet", "--out", str(out)]) == 0
    return out


def _copy(trained, tmp_path, edit_speed=None):
    for phase in ("steering", "speed"):
        document = json.loads(trained.with_name(f"a.json.{phase}.checkpoint.json").read_text())
        if phase == "speed" and edit_speed is not None:
            edit_speed(document)
        (tmp_path / f"a.json.{phase}.checkpoint.json").write_text(json.dumps(document))
    return tmp_path / "a.json"


@pytest.mark.parametrize("argv, expected", [
    (["--episodes", "16"], "a.json.steering.checkpoint.json: seed: the checkpoint was written by a run with seed 5, "
                           "this run has 0"),
    (["--episodes", "4", "--seed", "5"], "a.json.steering.checkpoint.json: episodes: the checkpoint has already done "
                                         "6 episodes of phase 'steering', more than the 3"),
    (["--episodes", "16", "--seed", "5", "--parallel", "2"], "a.json.steering.checkpoint.json: batch:"),
])
def test_a_refused_resume_says_nothing_of_where_it_would_go_on(trained, tmp_path, capsys, argv, expected):
    out = _copy(trained, tmp_path)
    assert main(["train", "fql-goal", *argv, "--quiet", "--resume", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "goes on from" not in err and len(err.splitlines()) == 1 and expected in err, err


def test_a_later_phase_of_another_run_is_refused_before_anything_is_said(trained, tmp_path, capsys):
    out = _copy(trained, tmp_path, lambda document: document["extra"].update(seed=6) or document.pop("digest"))
    assert main(["train", "fql-goal", "--episodes", "8", "--seed", "5", "--quiet", "--resume", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "goes on from" not in err and "a.json.speed.checkpoint.json: seed:" in err, err


def test_a_resume_says_each_phase_it_goes_on_from(trained, tmp_path, capsys):
    out = _copy(trained, tmp_path)
    assert main(["train", "fql-goal", "--episodes", "8", "--seed", "5", "--quiet", "--resume", "--out", str(out)]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == [f"--resume: the steering phase goes on from {out}.steering.checkpoint.json, 6 episodes done",
                   f"--resume: the speed phase goes on from {out}.speed.checkpoint.json, 2 episodes done"]


def test_a_phase_that_will_be_retrained_is_not_checked_nor_said(trained, tmp_path, capsys):
    """More steering episodes: the speed phase is retrained on the new steering, its checkpoint unused."""
    out = _copy(trained, tmp_path, lambda document: document["extra"].update(seed=6) or document.pop("digest"))
    assert main(["train", "fql-goal", "--episodes", "12", "--seed", "5", "--quiet", "--resume", "--out", str(out)]) == 0
    assert capsys.readouterr().err.splitlines() == [
        f"--resume: the steering phase goes on from {out}.steering.checkpoint.json, 6 episodes done"]
