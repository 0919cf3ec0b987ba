"""Membership functions against values computed by hand from §II.2.2 and eq V.8."""

import math

import numpy as np
import pytest

from fuzzynav.fuzzy import (
    Bell,
    Gaussian,
    Ramp,
    Sigmoid,
    Singleton,
    Trapezoidal,
    Triangular,
    Variable,
    check_strong_partition,
    strong_partition,
)
from fuzzynav.fuzzy.membership import Linear, make


def test_triangle_by_hand():
    mf = Triangular(0.0, 2.0, 3.0)
    x = np.array([-1.0, 0.0, 1.0, 2.0, 2.5, 3.0, 4.0])
    np.testing.assert_allclose(mf(x), [0, 0, 0.5, 1, 0.5, 0, 0])
    assert mf(np.zeros((2, 3))).shape == (2, 3)


def test_triangle_shoulders_and_vertical_edges():
    left = Triangular(-math.inf, 0.1, 3.5)
    np.testing.assert_allclose(left(np.array([-5.0, 0.1, 1.8, 3.5])), [1, 1, 0.5, 0])
    right = Triangular(13.0, 18.0, math.inf)
    np.testing.assert_allclose(right(np.array([13.0, 15.5, 18.0, 1e9])), [0, 0.5, 1, 1])
    edge = Triangular(0.0, 0.0, 2.0)
    np.testing.assert_allclose(edge(np.array([-0.1, 0.0, 1.0])), [0, 1, 0.5])
    assert left.params() == (-math.inf, 0.1, 3.5)


def test_trapezoid_by_hand_and_open_shoulders():
    mf = Trapezoidal(0.5, 1.0, 2.8, 4.0)
    np.testing.assert_allclose(mf(np.array([0.5, 0.75, 1.0, 2.0, 3.4, 4.0])), [0, 0.5, 1, 1, 0.5, 0])
    left = Trapezoidal(-math.inf, -math.inf, 1.0, 2.0)
    np.testing.assert_allclose(left(np.array([-1e9, 1.0, 1.5])), [1, 1, 0.5])
    right = Trapezoidal(2.8, 4.0, math.inf, math.inf)
    np.testing.assert_allclose(right(np.array([2.8, 3.4, 1e9])), [0, 0.5, 1])
    with pytest.raises(ValueError, match="trapezoid needs"):
        Trapezoidal(1.0, 0.0, 2.0, 3.0)
    with pytest.raises(ValueError, match=r"triangle needs a <= b <= c, got \(0.5, 0.0, -0.5\)"):
        Triangular(0.5, 0.0, -0.5)  # a file's triangle is named as one, not as the trapezoid it becomes


def test_gaussian_bell_sigmoid_singleton_by_hand():
    np.testing.assert_allclose(Gaussian(2.0, 1.0)(np.array([1.0, 3.0])), [1.0, math.exp(-0.5)])
    bell = Bell(2.0, 3.0, 1.0)  # 1 / (1 + |(x - c)/a|^(2b)), eq V.8
    np.testing.assert_allclose(bell(np.array([1.0, 3.0, 5.0])), [1.0, 0.5, 1 / (1 + 2.0 ** 6)])
    sig = Sigmoid(2.0, 1.0)
    np.testing.assert_allclose(sig(np.array([1.0, 2.0])), [0.5, 1 / (1 + math.exp(-2.0))])
    np.testing.assert_allclose(sig.inverse(sig(np.array([0.3, 1.7]))), [0.3, 1.7])
    np.testing.assert_allclose(Singleton(0.5)(np.array([0.5, 0.50001])), [1.0, 0.0])
    ramp = Ramp(4.0, 0.0)
    np.testing.assert_allclose(ramp(np.array([-1.0, 1.0, 5.0])), [1.0, 0.75, 0.0])
    np.testing.assert_allclose(ramp.inverse(0.25), 3.0)


def test_make_round_trips_params():
    for mf in (Triangular(-math.inf, 0.0, 1.0), Trapezoidal(0, 1, 2, 3), Gaussian(1, 2), Bell(1, 2, 3),
               Sigmoid(-3, 1), Singleton(0.25), Ramp(1, 0)):
        assert make(mf.kind, mf.params()) == mf
    with pytest.raises(ValueError, match="unknown membership function"):
        make("zigzag", [1])


def test_strong_partition_sums_to_one_and_validator_reports_gaps():
    terms = strong_partition([0.1, 3.5, 8, 13, 18], ["Z", "P", "M", "G", "TG"], (0, 28))
    var = Variable("drg", (0.0, 28.0), terms)
    x = np.linspace(0, 28, 1001)
    np.testing.assert_allclose(var.fuzzify(x).sum(axis=1), 1.0)
    assert check_strong_partition(var).strong
    gappy = Variable("x", (0.0, 4.0), {"A": Triangular(-math.inf, 0.0, 1.0), "B": Triangular(2.0, 3.0, math.inf)})
    report = check_strong_partition(gappy)
    assert not report.strong and report.max_deviation == pytest.approx(1.0)
    assert report.problems and "on [" in report.problems[0]
    # the reported interval is where the sets leave a hole: (0, 3)
    lo, hi = (float(v) for v in report.problems[0].split("on [")[1].rstrip("]").split(","))
    assert lo == pytest.approx(0.0, abs=5e-3) and hi == pytest.approx(3.0, abs=5e-3)


def test_strong_partition_rejects_bad_peaks():
    with pytest.raises(ValueError, match="increasing"):
        strong_partition([0, 0, 1], "ABC")
    with pytest.raises(ValueError, match="outside"):
        strong_partition([0, 1, 5], "ABC", (0, 4))


def test_fuzzify_batch_shape_and_clamp():
    var = Variable("x", (0.0, 1.0), strong_partition([0.0, 1.0], ["L", "H"]))
    mu = var.fuzzify(np.array([-1.0, 0.25, 2.0]))
    np.testing.assert_allclose(mu, [[1, 0], [0.75, 0.25], [0, 1]])
    # closed triangles: only the clamp to the universe [0, 1] gives full membership outside it
    closed = Variable("x", (0.0, 1.0), {"L": Triangular(-1.0, 0.0, 1.0), "H": Triangular(0.0, 1.0, 2.0)})
    np.testing.assert_allclose(closed.fuzzify(np.array([-1.0, 0.25, 2.0])), [[1, 0], [0.75, 0.25], [0, 1]])
    np.testing.assert_allclose(closed.fuzzify(np.array([-1.0, 0.25, 2.0]), clamp=False), [[0, 0], [0.75, 0.25], [0, 0]])


@pytest.mark.parametrize("build, message", [
    (lambda: Gaussian(1.0, math.inf), "mean must be finite"),  # a term that would never fire
    (lambda: Sigmoid(2.0, -math.inf), "c must be finite"),
    (lambda: Bell(1.0, 2.0, math.inf), "c must be finite"),
    (lambda: Linear([math.inf, 0.0]), r"coefficients\[0\] must be finite"),  # NaN conclusions
    (lambda: Linear([1.0], constant=-math.inf), "constant must be finite"),
])
def test_a_term_placed_at_infinity_is_refused(build, message):
    with pytest.raises(ValueError, match=message):
        build()
