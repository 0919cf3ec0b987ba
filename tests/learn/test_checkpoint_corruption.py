"""A damaged checkpoint is refused with the file and field named (``fuzzynav train --resume``),
never a traceback and never a silent resume from NaN qualities (resumable training)."""

import json

import pytest

from fuzzynav.cli import main


@pytest.fixture(scope="module")
def checkpoint(tmp_path_factory):
    folder = tmp_path_factory.mktemp("ck")
    assert main(["train", "q-goal", "--episodes", "50", "--quiet", "--out", str(folder / "m.json")]) == 0
    return json.loads((folder / "m.json.steering.checkpoint.json").read_text())


def _damage(document, change):
    document = json.loads(json.dumps(document))
    change(document)
    return document


CASES = [
    ("q-string", lambda d: d["learner"]["q"][0][0].__setitem__(0, "abc"), "learner.q: must be a table of numbers"),
    ("q-ragged", lambda d: d["learner"]["q"][0].__setitem__(0, [1.0]), "learner.q: must be a table of numbers"),
    ("q-nan", lambda d: d["learner"]["q"][0][0].__setitem__(0, float("nan")), "learner.q: holds NaN"),
    ("visits-shape", lambda d: d["learner"].__setitem__("visits", [[0.0]]), "learner.visits: table shape"),
    ("visits-negative", lambda d: d["learner"]["visits"][0][0].__setitem__(0, -3.0),
     "learner.visits: visit counts must not be negative"),  # β = 1/(1 + visits) would make NaN qualities
    ("episode-text", lambda d: d.__setitem__("episode", "x"), "episode: must be a non-negative integer"),
    ("episode-negative", lambda d: d.__setitem__("episode", -3), "episode: must be a non-negative integer"),
    ("curve-not-lists", lambda d: d.__setitem__("curve", {"mean_reward": 1}), "curve: must map mean_reward"),
]


@pytest.mark.parametrize("change, message", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_damaged_checkpoint_is_refused(checkpoint, tmp_path, capsys, change, message):
    out = tmp_path / "m.json"
    damaged = tmp_path / "m.json.steering.checkpoint.json"
    damaged.write_text(json.dumps(_damage(checkpoint, change)))
    status = main(["train", "q-goal", "--episodes", "100", "--quiet", "--resume", "--out", str(out)])
    err = capsys.readouterr().err
    assert status == 2
    assert f"{damaged}: {message}" in err
    assert not out.exists()


def test_intact_checkpoint_resumes(checkpoint, tmp_path, capsys):
    (tmp_path / "m.json.steering.checkpoint.json").write_text(json.dumps(checkpoint))
    assert main(["train", "q-goal", "--episodes", "100", "--quiet", "--resume", "--json",
                 "--out", str(tmp_path / "m.json")]) == 0
    assert json.loads(capsys.readouterr().out)["steering"]["episodes"] == 100


def test_learner_from_dict_shares_the_checks():
    from fuzzynav.errors import InputError
    from fuzzynav.learn.tabular import TabularLearner

    document = TabularLearner(4, 3).to_dict()
    assert TabularLearner.from_dict(document).q.shape == (1, 4, 3)
    document["q"][0][1][2] = float("inf")
    with pytest.raises(InputError, match=r"learner\.q: holds NaN or infinite values"):
        TabularLearner.from_dict(document)
