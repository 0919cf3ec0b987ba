"""The vectorised exp and log of the fused kernel against NumPy's, and the terms built on them."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from fuzzynav.fuzzy.engine.fuzzify_terms import BELL, GAUSSIAN, SIGMOID, pack_term, term_column
from fuzzynav.fuzzy.engine.vmath import exp_column, log_column
from fuzzynav.fuzzy.membership import Bell, Gaussian, Sigmoid

SPECIALS = np.array([0.0, -0.0, np.inf, -np.inf, np.nan, 1.0, -1.0, 5e-324, -5e-324, 2.2250738585072014e-308,
                     1e-310, 1.7976931348623157e308, 709.782712893384, 709.7827128933841, 710.0, -708.3964185322641,
                     -708.4, -745.1332191019411, -745.1332191019412, -746.0, 1e-20, -1e-20, 0.5 * np.log(2),
                     -0.5 * np.log(2), np.nextafter(1.0, 2.0), np.nextafter(1.0, 0.0)])


def _ulps(ours: np.ndarray, numpy: np.ndarray) -> np.ndarray:
    """|ours − numpy| in units of the last place of NumPy's value (0 where both are the same value,
    NaN included); the unit of a subnormal is the smallest subnormal."""
    same = (ours == numpy) | (np.isnan(ours) & np.isnan(numpy))
    with np.errstate(invalid="ignore"):
        gap = np.abs(ours - numpy) / np.spacing(np.abs(numpy))
    return np.where(same, 0.0, gap)


def _column(function, x: np.ndarray, in_place: bool) -> np.ndarray:
    out = x.copy() if in_place else np.empty_like(x)
    function(out if in_place else x, out)
    return out


@pytest.mark.parametrize("in_place", [False, True])
def test_exp_within_one_ulp_of_numpy_over_the_whole_range(in_place):
    rng = np.random.default_rng(0)
    x = np.concatenate([rng.uniform(-760.0, 720.0, 2_000_000), rng.uniform(-1.0, 1.0, 500_000),
                        rng.normal(0.0, 20.0, 500_000), SPECIALS, -SPECIALS])
    with np.errstate(over="ignore"):
        expected = np.exp(x)
    ours = _column(exp_column, x, in_place)
    assert _ulps(ours, expected).max() <= 1.0  # gradual underflow included (one subnormal step)
    special = np.concatenate([SPECIALS, -SPECIALS])
    np.testing.assert_array_equal(ours[-special.size:][~np.isfinite(special)], expected[-special.size:][~np.isfinite(special)])
    assert ours[x == 0.0].tolist() == [1.0] * int((x == 0.0).sum())


@pytest.mark.parametrize("in_place", [False, True])
def test_log_within_one_ulp_of_numpy_with_its_special_values(in_place):
    rng = np.random.default_rng(1)
    x = np.concatenate([np.exp(rng.uniform(-744.0, 709.0, 2_000_000)), rng.uniform(0.0, 4.0, 1_000_000),
                        rng.uniform(-1e-300, 1e-300, 1000), SPECIALS, -SPECIALS])
    with np.errstate(divide="ignore", invalid="ignore"):
        expected = np.log(x)
    ours = _column(log_column, x, in_place)
    assert _ulps(ours, expected).max() <= 1.0
    np.testing.assert_array_equal(ours[~np.isfinite(expected)], expected[~np.isfinite(expected)])  # -inf, inf, NaN
    assert ours[x == 1.0].tolist() == [0.0] * int((x == 1.0).sum())


@pytest.mark.parametrize("mf", [Gaussian(1.5, 6.0), Gaussian(1e-3, -2.0), Sigmoid(4.0, 2.0), Sigmoid(-0.7, 1.0),
                                Sigmoid(300.0, 0.0), Bell(5.0, 2.0, 3.0), Bell(0.785, 4.0, 1.571), Bell(1.5, 1.0, -1.5),
                                Bell(0.3, 16.22, -1.0), Bell(2.0, 0.2, 0.0), Bell(1.2, 3.0, 0.5)],
                         ids=repr)
def test_exp_terms_in_the_kernel_against_numpy(mf):
    """Gaussian and Sigmoid within 4 ulp of NumPy's formulas (exp's ulp, moved by a rounding of
    1 + exp(z) where exp(z) is large); Bell — a power computed as exp(v), v = 2b log z — within 4 + 2 |v| ulp (log's and the
    product's roundings are relative errors of v, so absolute errors of |v| times as many ulp in exp(v)); a Bell of power
    2b = 2, 4 or 8, computed by squarings (each doubles the relative error before it and adds a rounding), within 4 + b ulp."""
    rng = np.random.default_rng(2)
    x = np.concatenate([rng.uniform(-20.0, 20.0, 200_000), rng.normal(0.0, 1e3, 20_000), SPECIALS, -SPECIALS])
    code, params, height = pack_term(mf)
    assert code in (GAUSSIAN, BELL, SIGMOID)
    ours = np.empty_like(x)
    term_column(code, np.array(params), 0, len(params), height, x, ours)
    with np.errstate(all="ignore"):
        expected = mf(x)
        squared = code == BELL and 2.0 * mf.b in (2.0, 4.0, 8.0)
        power_error = 2.0 * np.abs(2.0 * mf.b * np.log(np.abs((x - mf.c) / mf.a))) if code == BELL else 0.0
        bound = 4.0 + (mf.b if squared else power_error)
    ulps = _ulps(ours, expected)
    assert np.all(np.where(np.isfinite(bound), ulps <= bound, ulps == 0.0))
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(expected))


PLAIN_PYTHON = """
import json, numpy as np
from fuzzynav.fuzzy.engine.sampled_defuzzify import centroid_sums
from fuzzynav.fuzzy.engine.vmath import exp_column, log_column
x = np.array(json.loads(input()))
e, g = np.empty_like(x), np.empty_like(x)
exp_column(x, e)
log_column(np.abs(x), g)
mu = np.abs(np.sin(np.arange(208.0)))
mu[200:] = 0.0
print(json.dumps({"jit": hasattr(exp_column, "py_func"), "exp": e.tolist(), "log": g.tolist(),
                  "centroid": centroid_sums(mu, np.linspace(0.0, 2.0, 208), 5, 200)}))
"""


def test_exp_log_and_centroid_sums_run_as_plain_python():
    """Under ``NUMBA_DISABLE_JIT=1`` the bit casts and the vector sums run as NumPy: the same numbers
    (the sums the same bits; exp and log within 1 ulp, the compiled polynomials may use FMA)."""
    x = np.concatenate([np.random.default_rng(4).uniform(-750.0, 720.0, 300), SPECIALS, -SPECIALS])
    runs = {}
    for disable in ("1", "0"):
        done = subprocess.run([sys.executable, "-c", PLAIN_PYTHON], input=json.dumps(x.tolist()), capture_output=True,
                              text=True, env={**os.environ, "NUMBA_DISABLE_JIT": disable}, timeout=600)
        assert done.returncode == 0, done.stderr
        runs[disable] = json.loads(done.stdout)
    plain, compiled = runs["1"], runs["0"]
    assert not plain["jit"] and compiled["jit"]
    assert plain["centroid"] == compiled["centroid"]
    for name in ("exp", "log"):
        assert np.all(_ulps(np.array(plain[name]), np.array(compiled[name])) <= 1.0), name
