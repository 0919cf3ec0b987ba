"""A training checkpoint whose curve holds values no run gives (a success of 7, a NaN mean
reward, negative steps), or without a digest whose learner's episode counter disagrees with the
checkpoint's, is refused naming the file and the field; it used to resume and report a success
rate of 180 %."""

import json

import pytest

from fuzzynav.cli import main


@pytest.fixture(scope="module")
def checkpoint(tmp_path_factory):
    folder = tmp_path_factory.mktemp("ck")
    assert main(["train", "q-goal", "--episodes", "4", "--quiet", "--out", str(folder / "q.json")]) == 0
    document = json.loads((folder / "q.json.steering.checkpoint.json").read_text())
    del document["digest"]  # written by hand or by an older version: checked for its structure only
    return document


def _set_all(key, value):
    return lambda curve: curve.__setitem__(key, [[value]] * len(curve[key]))


CASES = [
    ("success-7", _set_all("success", 7), "curve.success[0]: must be true or false, got 7"),
    ("success-half", _set_all("success", 0.5), "curve.success[0]: must be true or false, got 0.5"),
    ("reward-nan", lambda curve: curve["mean_reward"].__setitem__(2, [float("nan")]),
     "curve.mean_reward[2]: must be a finite number, got nan"),
    ("steps-negative", lambda curve: curve["steps"].__setitem__(1, [-3]),
     "curve.steps[1]: must be a whole number of steps ≥ 1, got -3"),
    ("steps-fraction", lambda curve: curve["steps"].__setitem__(0, [2.5]),
     "curve.steps[0]: must be a whole number of steps ≥ 1, got 2.5"),
    ("steps-empty", lambda curve: curve["steps"].__setitem__(3, []),
     "curve.steps[3]: must be a list of the batch's episodes, got []"),
    ("success-nested", lambda curve: curve["success"].__setitem__(0, [[True]]),
     "curve.success[0]: must be a list of the batch's episodes"),
]


@pytest.mark.parametrize("edit, message", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_impossible_curve_values_are_refused(checkpoint, tmp_path, capsys, edit, message):
    document = json.loads(json.dumps(checkpoint))
    edit(document["curve"])
    _refused(document, tmp_path, capsys, message)


def test_a_learner_counting_other_episodes_is_refused(checkpoint, tmp_path, capsys):
    document = json.loads(json.dumps(checkpoint))
    document["learner"]["episode"] = 9
    _refused(document, tmp_path, capsys, "learner.episode: the learner counts 9 batches of episodes, but the "
                                         "checkpoint says 4 were done")


def test_an_intact_checkpoint_without_digest_still_resumes(checkpoint, tmp_path, capsys):
    (tmp_path / "q.json.steering.checkpoint.json").write_text(json.dumps(checkpoint))
    assert main(["train", "q-goal", "--episodes", "8", "--quiet", "--resume", "--json",
                 "--out", str(tmp_path / "q.json")]) == 0
    assert json.loads(capsys.readouterr().out)["steering"]["episodes"] == 8


def _refused(document, tmp_path, capsys, message):
    damaged = tmp_path / "q.json.steering.checkpoint.json"
    damaged.write_text(json.dumps(document))
    status = main(["train", "q-goal", "--episodes", "8", "--quiet", "--resume", "--out", str(tmp_path / "q.json")])
    err = capsys.readouterr().err
    assert status == 2 and f"{damaged}: {message}" in err, err
    assert "Traceback" not in err and not (tmp_path / "q.json").exists()
