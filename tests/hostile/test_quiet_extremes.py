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


# terms whose parameters overflow an intermediate value (an edge 1e-320 wide, a slope of 1e308):
# numpy warned on stderr, and the spike answered NaN (inf × 0) at its own centre
EXTREME_TERMS = [
    ("Triangular(0.0, 1e-320, 8.0)", [1.0, 8.0, -1.0], [0.875, 0.0, 0.0]),
    ("Gaussian(1e-300, 3.5)", [1.0, 3.5], [0.0, 1.0]),
    ("Bell(1e-300, 1.0, 3.5)", [1.0, 3.5], [0.0, 1.0]),
    ("Bell(1.0, 1e300, 3.5)", [1.0, 3.0, 3.5], [0.0, 1.0, 1.0]),
    ("Sigmoid(-1e308, 3.5)", [1.0, 5.0], [1.0, 0.0]),
    ("Spike(3.5, 1e-320)", [3.5, 3.6], [1.0, 0.0]),
    ("GaussianProduct(3.0, 1e-300, 4.0, 1e-300)", [1.0, 3.5, 5.0], [0.0, 1.0, 0.0]),
]


@pytest.mark.parametrize("term, x, mu", EXTREME_TERMS, ids=[term for term, _, _ in EXTREME_TERMS])
def test_terms_of_extreme_parameters_answer_their_limits_without_a_warning(term, x, mu):
    from fuzzynav.fuzzy.membership import Bell, Gaussian, Sigmoid, Triangular  # noqa: F401 - read by eval
    from fuzzynav.fuzzy.terms import GaussianProduct, Spike  # noqa: F401

    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        assert eval(term)(x).tolist() == pytest.approx(mu, abs=1e-300)  # noqa: S307 - the table's own text


def test_a_fll_term_of_extreme_parameters_evaluates_without_a_warning(tmp_path, capsys):
    from fuzzynav.fuzzy.io import to_fll
    from fuzzynav.fuzzy.systems import get_system

    text = to_fll(get_system("goal-seeking")).replace("term: P Triangle 0.1 3.5 8.0", "term: P Bell 3.5 1.0 1e300")  # centre, width, slope
    assert "P Bell" in text
    (tmp_path / "g.fll").write_text(text)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        assert main(["fis", "eval", str(tmp_path / "g.fll"), "--input", "drg=1", "--input", "theta=0.1"]) == 0
    assert capsys.readouterr().err == ""
