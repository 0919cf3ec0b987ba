"""``tune --resume`` with a smaller ``--budget`` than the checkpoint already spent is refused
before anything is written; it used to cut the stored generations short and rewrite both the
checkpoint and the tuned file (``train --resume`` refuses the same case)."""

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.tune.session import TuneRequest, tune

OPTIONS = dict(target="goal-seeking:gsb", worlds="mixed:1", population=2, progress=False)


def test_a_smaller_budget_is_refused_and_nothing_is_rewritten(tmp_path, capsys):
    out = tmp_path / "t.yaml"
    tune(TuneRequest(out=str(out), budget=4, validation="none", **OPTIONS))
    checkpoint = out.with_name("t.yaml.tune.npz")
    before = checkpoint.read_bytes()
    assert main(["tune", "goal-seeking:gsb", "--worlds", "mixed:1", "--budget", "2", "--population", "2",
                 "--validation", "none", "--quiet", "--out", str(out), "--resume"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.endswith("t.yaml.tune.npz: --budget: the checkpoint already holds 4 episodes, more than the 2 this "
                        "run asks for: resume with at least as large a --budget, or tune afresh without --resume"), err
    assert checkpoint.read_bytes() == before
    assert np.load(checkpoint)["sizes"].tolist() == [2, 2]


def test_the_validation_episodes_do_not_count_as_room_for_the_stored_ones(tmp_path):
    out = str(tmp_path / "t.yaml")
    tune(TuneRequest(out=out, budget=8, validation="auto", **OPTIONS))  # 4 training + 4 validation episodes
    with pytest.raises(InputError, match=r"--budget: the checkpoint already holds 4 episodes, more than the 3 "
                                         r"training episodes \(4 of --budget 7 validate\)"):
        tune(TuneRequest(out=out, budget=7, validation="auto", resume=True, **OPTIONS))


def test_the_same_budget_still_resumes(tmp_path):
    out = str(tmp_path / "t.yaml")
    tune(TuneRequest(out=out, budget=4, validation="none", **OPTIONS))
    assert tune(TuneRequest(out=out, budget=4, validation="none", resume=True, **OPTIONS))["episodes"] == 4
