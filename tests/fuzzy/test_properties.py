"""Property tests (hypothesis): strong partitions, TS0 output range, symmetry of the tables."""

import math

import numpy as np
from hypothesis import given, settings, strategies as st

from fuzzynav.fuzzy import FuzzySystem, Singleton, Variable, check_strong_partition, rules_from_grid, strong_partition
from fuzzynav.fuzzy.systems import get_system

finite = st.floats(-1e3, 1e3, allow_nan=False)


@st.composite
def partitions(draw, max_sets=7):
    n = draw(st.integers(2, max_sets))
    gaps = draw(st.lists(st.floats(0.01, 50.0), min_size=n - 1, max_size=n - 1))
    start = draw(st.floats(-100.0, 100.0))
    peaks = np.concatenate(([start], start + np.cumsum(gaps)))
    margin = draw(st.floats(0.0, 10.0))
    universe = (float(peaks[0] - margin), float(peaks[-1] + margin))
    labels = [f"T{i}" for i in range(n)]
    return Variable("x", universe, strong_partition(peaks, labels, universe))


@settings(max_examples=60, deadline=None)
@given(partitions(), st.lists(finite, min_size=1, max_size=50))
def test_strong_partition_sums_to_one(var, xs):
    mu = var.fuzzify(np.array(xs))
    np.testing.assert_allclose(mu.sum(axis=1), 1.0, atol=1e-12)
    assert ((mu > 0).sum(axis=1) <= 2).all()
    assert check_strong_partition(var).strong


@settings(max_examples=40, deadline=None)
@given(partitions(4), partitions(5), st.data())
def test_ts0_output_within_singletons(v1, v2, data):
    v2 = Variable("y", v2.universe, v2.terms)
    n_out = 4
    values = data.draw(st.lists(st.floats(-10, 10), min_size=n_out, max_size=n_out))
    out = Variable("z", (-10.0, 10.0), {f"S{i}": Singleton(v) for i, v in enumerate(values)})
    cells = [[data.draw(st.sampled_from(out.labels)) for _ in v1.labels] for _ in v2.labels]
    rules = rules_from_grid("y", "x", v2.labels, v1.labels, cells, ["z"])
    X = np.column_stack([data.draw(st.lists(finite, min_size=20, max_size=20)) for _ in range(2)])
    for defuzzifier in ("weighted_sum", "weighted_average"):
        fs = FuzzySystem([v1, v2], [out], rules, defuzzifier=defuzzifier)
        y = fs.evaluate(X)[:, 0]
        assert (y >= min(values) - 1e-12).all() and (y <= max(values) + 1e-12).all()
        assert np.allclose([fs.evaluate_one(*x)[0] for x in X], y, atol=1e-12)


angles = st.floats(-math.pi, math.pi)


@settings(max_examples=200, deadline=None)
@given(angles, angles)
def test_table_V1_is_point_symmetric(theta, dtheta):
    tr = get_system("tracking")
    total = tr.evaluate_one(theta, dtheta)[0] + tr.evaluate_one(-theta, -dtheta)[0]
    assert abs(total) <= 1e-12


@settings(max_examples=200, deadline=None)
@given(st.floats(0.0, 30.0), angles)
def test_table_IV1_speed_is_symmetric_in_theta(d, theta):
    gs = get_system("goal-seeking")
    assert abs(gs.evaluate_one(d, theta)[1] - gs.evaluate_one(d, -theta)[1]) <= 1e-12


@settings(max_examples=200, deadline=None)
@given(st.floats(0.0, 5.0), st.floats(0.25, math.pi))
def test_table_IV2_mirror_outside_the_Z_row(d, theta):
    # the reconstruction of Table IV.2 (§IV.5.2.1) is mirror symmetric except row Z (obstacle ahead: steer right)
    oa = get_system("obstacle-avoidance")
    left, right = oa.evaluate_one(d, theta), oa.evaluate_one(d, -theta)
    assert abs(left[0] + right[0]) <= 1e-12 and abs(left[1] - right[1]) <= 1e-12


def test_a_sub_normal_shoulder_cell_neither_fails_nor_gives_nan():
    """A universe whose end lies a sub-normal distance beyond the first peak (found by the property
    above): the cell is too narrow for 1/width, so it is flat, and the output stays exact."""
    x = Variable("x", (-5e-324, 1.0), strong_partition(np.array([0.0, 1.0]), ["A", "B"], (-5e-324, 1.0)))
    y = Variable("y", (-1.0, 1.0), strong_partition(np.array([-1.0, 1.0]), ["N", "P"], (-1.0, 1.0)))
    out = Variable("z", (-10.0, 10.0), {"S0": Singleton(1.0), "S1": Singleton(2.0)})
    rules = rules_from_grid("y", "x", y.labels, x.labels, [["S0", "S1"], ["S1", "S0"]], ["z"])
    system = FuzzySystem([x, y], [out], rules, defuzzifier="weighted_sum")
    X = np.array([[-5e-324, 0.5], [-1e3, 0.0], [0.5, 0.2]])
    expected = [0.25 * 1.0 + 0.75 * 2.0, 1.5, 1.5]
    np.testing.assert_allclose(system.evaluate(X)[:, 0], expected, rtol=0, atol=1e-12)
    np.testing.assert_allclose([system.evaluate_one(*row)[0] for row in X], expected, rtol=0, atol=1e-12)
