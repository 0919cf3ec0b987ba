"""``tune --resume`` refuses a checkpoint whose stored objective values no simulation gives (NaN,
infinite or outside their objective's range), naming the file and the field; it used to take
them as measured and write a worse system."""

import shutil

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.tune.session import TuneRequest, tune

OPTIONS = dict(target="goal-seeking:gsb", worlds="mixed:1", population=2, validation="none", progress=False)


@pytest.fixture(scope="module")
def checkpoint(tmp_path_factory):
    """A checkpoint of two generations of two candidates on one world (the review's reproducer)."""
    folder = tmp_path_factory.mktemp("checkpoint")
    tune(TuneRequest(out=str(folder / "t9.yaml"), budget=4, **OPTIONS))
    return folder / "t9.yaml.tune.npz"


def _forged(checkpoint, tmp_path, edit):
    shutil.copy(checkpoint, tmp_path / "t9.yaml.tune.npz")
    arrays = dict(np.load(tmp_path / "t9.yaml.tune.npz"))
    edit(arrays)
    with open(tmp_path / "t9.yaml.tune.npz", "wb") as handle:
        np.savez(handle, **arrays)
    return TuneRequest(out=str(tmp_path / "t9.yaml"), budget=6, resume=True, **OPTIONS)


def _set(name, where, value):
    return lambda arrays: arrays[name].__setitem__(where, value)


@pytest.mark.parametrize("edit, expected", [
    (_set("f", (3, slice(None)), -1e300), r"f\[3, 0\]: the cost of candidate 3 must lie in \[0, 30\], got -1e\+300"),
    (_set("f", (3, 0), np.nan), r"f\[3, 0\]: the cost of candidate 3 must be finite, got nan"),
    (_set("f", (3, 2), np.inf), r"f\[3, 2\]: the mean time \(s\) of candidate 3 must be finite, got inf"),
    (_set("f", (2, 0), 30.5), r"f\[2, 0\]: the cost of candidate 2 must lie in \[0, 30\]"),
    (_set("f", (2, 1), -0.5), r"f\[2, 1\]: the failure rate of candidate 2 must lie in \[0, 1\]"),
    (_set("f", (2, 1), 0.5), r"f\[2, 1\]: .* a multiple of 1/1 \(the worlds\), got 0\.5"),
    (_set("f", (1, 2), 1e6), r"f\[1, 2\]: the mean time \(s\) of candidate 1 must lie in \[0, "),
    (_set("f", (0, 3), -1e6), r"f\[0, 3\]: the minus mean least clearance \(m\) of candidate 0 must lie in"),
    (_set("f", (0, 3), 1.5), r"f\[0, 3\]: the minus mean least clearance \(m\) of candidate 0 must lie in"),
    (_set("x", (3, 0), np.nan), r"t9\.yaml\.tune\.npz: x: the populations must be finite"),
    (lambda arrays: arrays.pop("worlds"), r"worlds: the checkpoint does not say which training worlds"),
    (lambda arrays: arrays.__setitem__("sizes", np.array([2**64 - 2, 6], dtype=np.uint64)),  # wrapped to 4
     r"sizes: the generations' sizes must be whole numbers ≥ 0 adding up to the 4 rows"),
])
def test_impossible_stored_values_are_refused(checkpoint, tmp_path, edit, expected):
    request = _forged(checkpoint, tmp_path, edit)
    with pytest.raises(InputError, match=r"t9\.yaml\.tune\.npz: " + expected.removeprefix(r"t9\.yaml\.tune\.npz: ")):
        tune(request)


def test_the_command_line_reports_the_file_and_field(checkpoint, tmp_path, capsys):
    _forged(checkpoint, tmp_path, _set("f", (3, slice(None)), -1e300))
    assert main(["tune", "goal-seeking:gsb", "--worlds", "mixed:1", "--budget", "6", "--population", "2",
                 "--validation", "none", "--quiet", "--out", str(tmp_path / "t9.yaml"), "--resume"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "t9.yaml.tune.npz: f[3, 0]" in err, err


def test_an_untouched_checkpoint_still_resumes(checkpoint, tmp_path):
    result = tune(_forged(checkpoint, tmp_path, lambda arrays: None))
    assert result["episodes"] == 6 and (tmp_path / "t9.yaml.tune.npz").is_file()
