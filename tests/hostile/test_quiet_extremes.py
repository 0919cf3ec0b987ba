"""Inputs at the ends of the float range answer without a numpy warning: ``fis eval goal-seeking
--input drg=1e308 --input theta=1e308`` printed ``RuntimeWarning: overflow encountered in reduce``
and a line of numpy's code on stderr before its (right) answer — the NaN screen of
``FuzzySystem`` sums the inputs, and that sum overflows. Each input is clamped to its universe:
drg to 28.28 m (TG), θ to π (PG), whose rule concludes NM / F."""

from __future__ import annotations

import json
import math
import warnings

import pytest

from fuzzynav.cli import main

TABLE_IV_1_NM_F = {"alpha": -math.pi / 10, "v": 1.0}  # rule PG × TG of Table IV.1


@pytest.mark.parametrize("inputs", [("drg=1e308", "theta=1e308"), ("drg=1.7e308", "theta=4e307")])
def test_inputs_of_1e308_answer_without_a_warning(inputs, capsys):
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # numpy's overflow warning raises here
        assert main(["fis", "eval", "goal-seeking", *(arg for value in inputs for arg in ("--input", value))]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out) == pytest.approx(TABLE_IV_1_NM_F) and err == ""


def test_a_csv_of_infinities_of_both_signs_answers_without_a_warning(tmp_path, capsys):
    (tmp_path / "in.csv").write_text("drg,theta\ninf,-inf\n-1e308,-1e308\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        assert main(["fis", "eval", "goal-seeking", "--csv", str(tmp_path / "in.csv")]) == 0
    assert len(capsys.readouterr().out.splitlines()) == 3
