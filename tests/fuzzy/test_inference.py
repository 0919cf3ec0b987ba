"""TS1, Mamdani (min/max and product variants), Tsukamoto and the min T-norm, by hand (§II.4.3)."""

import math

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import FuzzySystem, Linear, Ramp, Singleton, Triangular, Variable, strong_partition
from fuzzynav.fuzzy.systems import get_system

PI = math.pi


@pytest.fixture
def x_var():
    return Variable("x", (0.0, 1.0), strong_partition([0.0, 1.0], ["L", "H"]))


def test_ts1_affine_conclusions(x_var):
    y = Variable("y", (-10.0, 10.0), {"up": Linear([2.0], 1.0), "down": Linear([-1.0], 3.0)})
    fs = FuzzySystem([x_var], [y], ["IF x IS L THEN y IS up", "IF x IS H THEN y IS down"], method="ts1")
    # x = 0.25: 0.75 (2x + 1) + 0.25 (-x + 3) = 1.125 + 0.6875
    assert fs.evaluate_one(0.25) == pytest.approx((1.8125,), abs=1e-15)
    contrib = fs.contributions(np.array([[0.25]]))
    np.testing.assert_allclose(contrib[0, :, 0], [1.125, 0.6875])
    assert not fs.fast


def _mamdani(x_var, **options):
    y = Variable("y", (0.0, 10.0), {"A": Triangular(0.0, 2.0, 4.0), "B": Triangular(6.0, 8.0, 10.0)})
    return FuzzySystem([x_var], [y], ["IF x IS L THEN y IS A", "IF x IS H THEN y IS B"], method="mamdani",
                       resolution=2000, **options)


def test_mamdani_product_variants_by_hand(x_var):
    # product implication scales both triangles (equal areas): centroid = (0.75·2 + 0.25·8) / 1
    for aggregation in ("max", "sum"):
        fs = _mamdani(x_var, implication="product", aggregation=aggregation)
        assert fs.evaluate_one(0.25)[0] == pytest.approx(3.5, abs=1e-9)
    assert _mamdani(x_var).evaluate_one(0.0)[0] == pytest.approx(2.0, abs=1e-9)


def test_mamdani_min_max_centroid_by_hand(x_var):
    # clipped triangle of base 4 at height h has area 4h - 2h²: 1.875 (h=.75) and 0.875 (h=.25)
    fs = _mamdani(x_var)
    expected = (1.875 * 2 + 0.875 * 8) / (1.875 + 0.875)
    assert fs.evaluate_one(0.25)[0] == pytest.approx(expected, abs=1e-5)
    with pytest.raises(ValueError, match="additive"):
        fs.contributions(np.array([[0.25]]))


def test_mamdani_sum_aggregation_differs_from_max_where_sets_overlap(x_var):
    y = Variable("y", (0.0, 10.0), {"A": Triangular(0.0, 4.0, 8.0), "B": Triangular(2.0, 6.0, 10.0)})
    rules = ["IF x IS L THEN y IS A", "IF x IS H THEN y IS B"]
    high = FuzzySystem([x_var], [y], rules, method="mamdani", aggregation="max", resolution=4000)
    total = FuzzySystem([x_var], [y], rules, method="mamdani", aggregation="sum", resolution=4000)
    # by symmetry both are 5 at x = 0.5; at x = 0.25 they differ
    assert high.evaluate_one(0.5)[0] == pytest.approx(5.0, abs=1e-9)
    assert total.evaluate_one(0.5)[0] == pytest.approx(5.0, abs=1e-9)
    assert abs(high.evaluate_one(0.25)[0] - total.evaluate_one(0.25)[0]) > 1e-3


def test_tsukamoto_monotone_conclusions(x_var):
    y = Variable("y", (0.0, 10.0), {"up": Ramp(0.0, 10.0), "down": Ramp(8.0, 0.0)})
    fs = FuzzySystem([x_var], [y], ["IF x IS L THEN y IS down", "IF x IS H THEN y IS up"], method="tsukamoto")
    # w = (0.75, 0.25): z_L = 8 - 0.75·8 = 2, z_H = 0.25·10 = 2.5 -> 0.75·2 + 0.25·2.5
    assert fs.evaluate_one(0.25) == pytest.approx((2.125,), abs=1e-15)
    with pytest.raises(InputError, match="cannot conclude"):
        FuzzySystem([x_var], [Variable("y", (0, 1), {"a": Triangular(0, 0.5, 1)})], ["IF x IS L THEN y IS a"],
                    method="tsukamoto")


def test_min_tnorm_by_hand_fast_and_generic():
    gs = get_system("goal-seeking")
    fs = FuzzySystem(gs.inputs, gs.outputs, gs.rules, tnorm="min", defuzzifier="weighted_average")
    assert fs.fast
    p = (8 - 4.6) / 4.5  # μ_P(4.6); μ_M = 1 - p; θ = -0.5: μ_NM = μ_NP = 0.5
    w = np.array([0.5, min(0.5, 1 - p), 0.5, min(0.5, 1 - p)])  # NM/P, NM/M, NP/P, NP/M
    alpha = w @ [PI / 5, PI / 10, PI / 10, PI / 20] / w.sum()
    v = w @ [1, 1, 1, 1.8] / w.sum()
    assert fs.evaluate_one(4.6, -0.5) == pytest.approx((alpha, v), abs=1e-15)
    X = np.array([[4.6, -0.5]])
    np.testing.assert_allclose(fs.evaluate(X), [[alpha, v]], atol=1e-15)
    np.testing.assert_allclose(fs._generic(fs._batch(X)), [[alpha, v]], atol=1e-15)


def test_weighted_average_is_nan_where_no_rule_fires(x_var):
    y = Variable("y", (0.0, 1.0), {"a": Singleton(1.0)})
    fs = FuzzySystem([x_var], [y], ["IF x IS L THEN y IS a"], defuzzifier="weighted_average")
    assert math.isnan(fs.evaluate_one(1.0)[0]) and fs.evaluate_one(0.0) == (1.0,)
    assert np.isnan(fs.evaluate(np.array([[1.0]]))[0, 0])
    summed = FuzzySystem([x_var], [y], ["IF x IS L THEN y IS a"], defuzzifier="weighted_sum")
    assert summed.evaluate_one(1.0) == (0.0,)


def test_firing_strengths_normalised_and_raw(x_var):
    gs = get_system("goal-seeking")
    X = np.array([[5.75, -0.5], [0.0, 0.0]])
    raw = gs.firing_strengths(X, normalise=False)
    assert raw.shape == (2, 35)
    np.testing.assert_allclose(raw.sum(axis=1), 1.0)
    np.testing.assert_allclose(gs.firing_strengths(X), raw)
    assert np.count_nonzero(raw[1]) == 1
    # weighted rules: raw w_r = weight_r · μ(x) sums to less than 1; normalised divides by the sum
    y = Variable("y", (0.0, 1.0), {"a": Singleton(0.0), "b": Singleton(1.0)})
    fs = FuzzySystem([x_var], [y], ["IF x IS L THEN y IS a WITH 0.5", "IF x IS H THEN y IS b WITH 0.8"])
    X = np.array([[0.25], [0.0]])
    np.testing.assert_allclose(fs.firing_strengths(X, normalise=False), [[0.375, 0.2], [0.5, 0.0]], atol=1e-15)
    np.testing.assert_allclose(fs.firing_strengths(X), [[0.375 / 0.575, 0.2 / 0.575], [1.0, 0.0]], atol=1e-15)
    lone = FuzzySystem([x_var], [y], ["IF x IS L THEN y IS a WITH 0.5"])  # x = 1: no rule fires, the row stays 0
    np.testing.assert_array_equal(lone.firing_strengths(np.array([[1.0]])), [[0.0]])


def test_fast_kernel_handles_a_subnormal_interval():
    """Regression (found by hypothesis): a universe starting at -1e-308 next to a breakpoint at 0
    made the lookup-grid size infinite; the kernel now falls back to a binary search."""
    x = Variable("x", (-1.1125369292536007e-308, 1.0), strong_partition([0.0, 1.0], ["T0", "T1"], (-1.1125369292536007e-308, 1.0)))
    out = Variable("y", (0.0, 1.0), {"S0": Singleton(0.0), "S1": Singleton(1.0)})
    system = FuzzySystem([x], [out], ["IF x IS T0 THEN y IS S0", "IF x IS T1 THEN y IS S1"])
    assert system.fast
    np.testing.assert_allclose(system.evaluate(np.array([[0.0], [0.25], [1.0]]))[:, 0], [0.0, 0.25, 1.0])
