"""The thesis' systems (Tables IV.1, IV.2, V.1) and the TS0 engine, checked by hand."""

import math

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import (
    FuzzySystem,
    Linear,
    Singleton,
    Triangular,
    Variable,
    check_strong_partition,
    parse_rule,
    strong_partition,
)
from fuzzynav.fuzzy.systems import SYSTEMS, TABLE_IV_1, get_system

PI = math.pi


def test_goal_seeking_structure():
    gs = get_system("goal-seeking")
    assert gs.input_names == ["drg", "theta"] and gs.output_names == ["alpha", "v"]
    assert len(gs.rules) == 35 and gs.fast
    for var in gs.inputs:
        assert check_strong_partition(var).strong


def test_goal_seeking_at_rule_peaks_equals_table_cells():
    gs = get_system("goal-seeking")
    alpha = dict(zip(gs.outputs[0].labels, (v.value for v in gs.outputs[0].terms.values())))
    speed = {k: mf.value for k, mf in gs.outputs[1].terms.items()}
    drg_peaks = [0.1, 3.5, 8, 13, 18]
    theta_peaks = [-1.5, -0.75, -0.25, 0, 0.25, 0.75, 1.5]
    for i, row in enumerate(TABLE_IV_1):
        for j, cell in enumerate(row.split()):
            a, v = cell.split("/")
            got = gs.evaluate_one(drg_peaks[j], theta_peaks[i])
            assert got == pytest.approx((alpha[a], speed[v]), abs=1e-15)


def test_goal_seeking_between_peaks_by_hand():
    # drg = 5.75 (half-way P..M), theta = -0.5 (half-way NM..NP): 4 rules at weight 1/4 (IV.4, IV.5)
    # NM/P = PG/F, NM/M = PM/F, NP/P = PM/F, NP/M = PP/M
    gs = get_system("goal-seeking")
    alpha, v = gs.evaluate_one(5.75, -0.5)
    assert alpha == pytest.approx((PI / 5 + PI / 10 + PI / 10 + PI / 20) / 4, abs=1e-15)
    assert v == pytest.approx((1 + 1 + 1 + 1.8) / 4, abs=1e-15)
    X = np.array([[5.75, -0.5]])
    assert np.allclose(gs.evaluate(X), [[alpha, v]], atol=1e-15)
    w = gs.firing_strengths(X)
    assert np.count_nonzero(w) == 4 and w.sum() == pytest.approx(1.0)
    contrib = gs.contributions(X)
    np.testing.assert_allclose(contrib.sum(axis=1), gs.evaluate(X), atol=1e-15)


def test_inputs_are_clamped_to_the_universe():
    gs = get_system("goal-seeking")
    assert gs.evaluate_one(1e6, -10.0) == gs.evaluate_one(gs.inputs[0].universe[1], -PI)
    np.testing.assert_array_equal(gs.evaluate(np.array([[1e6, -10.0]])), [gs.evaluate_one(1e6, -10.0)])
    # the outer sets of Table IV.1 are open shoulders, the same inside and outside the universe; on
    # closed triangles only the clamp makes x < 0 fire L alone (y = 2) and x > 1 fire H alone (y = 5)
    x = Variable("x", (0.0, 1.0), {"L": Triangular(-1.0, 0.0, 1.0), "H": Triangular(0.0, 1.0, 2.0)})
    rules = ["IF x IS L THEN y IS a", "IF x IS H THEN y IS b"]
    fast = FuzzySystem([x], [Variable("y", (0.0, 10.0), {"a": Singleton(2.0), "b": Singleton(5.0)})], rules)
    generic = FuzzySystem([x], [Variable("y", (0.0, 10.0), {"a": Linear([0.0], 2.0), "b": Linear([0.0], 5.0)})],
                          rules, method="ts1")
    assert fast.fast and not generic.fast
    for system in (fast, generic):
        assert (system.evaluate_one(-10.0), system.evaluate_one(0.25), system.evaluate_one(1e6)) == ((2.0,), (2.75,), (5.0,))
        np.testing.assert_array_equal(system.evaluate(np.array([[-10.0], [0.25], [1e6]])), [[2.0], [2.75], [5.0]])
    with pytest.raises(InputError, match="theta"):
        gs.evaluate(np.array([[1.0, np.nan]]))
    with pytest.raises(InputError, match="shape"):
        gs.evaluate(np.zeros((3, 3)))


def test_fast_kernel_equals_generic_kernel():
    rng = np.random.default_rng(1)
    for name in SYSTEMS:
        system = get_system(name)
        lo = np.array([v.universe[0] for v in system.inputs]) - 1
        hi = np.array([v.universe[1] for v in system.inputs]) + 1
        X = rng.uniform(lo, hi, (5000, len(system.inputs)))
        fast = system.evaluate(X)
        generic = system._generic(system._batch(X))
        np.testing.assert_allclose(fast, generic, rtol=0, atol=1e-14)
        one = np.array([system.evaluate_one(*x) for x in X[:500]])
        np.testing.assert_allclose(one, fast[:500], rtol=0, atol=1e-14)


def test_tracking_rules_quoted_in_the_text():
    tr = get_system("tracking")
    assert len(tr.rules) == 25
    # R1: θer NG, dθer PG -> Z; R2: θer NM, dθer Z -> PM; R25: PG, PG -> NG (§V.3.1)
    assert tr.evaluate_one(-PI / 2, PI / 2) == pytest.approx((0.0,))
    assert tr.evaluate_one(-PI / 6, 0.0) == pytest.approx((PI / 8,))
    assert tr.evaluate_one(PI / 2, PI / 2) == pytest.approx((-PI / 4,))
    assert tr.rules[0].text() == "IF theta_er IS NG AND dtheta_er IS NG THEN alpha IS PG"


def test_obstacle_avoidance_structure():
    oa = get_system("obstacle-avoidance")
    assert oa.input_names == ["dro", "theta_o"] and len(oa.rules) == 21 and oa.fast
    assert check_strong_partition(oa.inputs[0]).strong
    # obstacle in front and near: low speed, steer right (R1 of §IV.5.2.1)
    alpha, v = oa.evaluate_one(0.2, 0.0)
    assert alpha == pytest.approx(-PI / 5) and v == pytest.approx(1.0)


def test_text_rules_weights_and_weighted_average():
    x = Variable("x", (0.0, 1.0), strong_partition([0.0, 1.0], ["L", "H"]))
    y = Variable("y", (0.0, 10.0), {"A": Singleton(2.0), "B": Singleton(6.0)})
    fs = FuzzySystem([x], [y], ["IF x IS L THEN y IS A", "IF x IS H THEN y IS B WITH 0.5"],
                     defuzzifier="weighted_average")
    # x = 0.5: w = (0.5, 0.25) -> (0.5*2 + 0.25*6) / 0.75
    assert fs.evaluate_one(0.5) == pytest.approx(((1.0 + 1.5) / 0.75,))
    assert fs.evaluate(np.array([[0.5]]))[0, 0] == pytest.approx((1.0 + 1.5) / 0.75)
    assert parse_rule(fs.rules[1].text()) == fs.rules[1]


def test_unknown_names_are_reported():
    with pytest.raises(InputError, match="unknown term 'XX'"):
        FuzzySystem(get_system("tracking").inputs, get_system("tracking").outputs,
                    ["IF theta_er IS XX THEN alpha IS Z"])
    with pytest.raises(InputError, match="unknown input variable 'speed'"):
        FuzzySystem(get_system("tracking").inputs, get_system("tracking").outputs,
                    ["IF speed IS NG THEN alpha IS Z"])
    with pytest.raises(InputError, match="unknown fuzzy system"):
        get_system("nope")


def test_fast_kernel_three_inputs_partial_weighted_rules():
    # rules that skip an input, weights, weighted average, trapezoids
    from fuzzynav.fuzzy import Trapezoidal

    a = Variable("a", (0.0, 4.0), {"P": Trapezoidal(0, 0, 0.5, 1), "M": Trapezoidal(0.5, 1, 2.8, 4),
                                   "G": Trapezoidal(2.8, 4, math.inf, math.inf)})
    b = Variable("b", (-1.0, 1.0), strong_partition([-1.0, 0.2, 1.0], ["N", "Z", "P"]))
    c = Variable("c", (0.0, 10.0), strong_partition([1.0, 9.0], ["L", "H"]))
    y = Variable("y", (-2.0, 2.0), {"lo": Singleton(-2.0), "mid": Singleton(0.5), "hi": Singleton(2.0)})
    rules = ["IF a IS P AND b IS N THEN y IS lo", "IF a IS M THEN y IS mid WITH 0.3",
             "IF b IS P AND c IS H THEN y IS hi WITH 0.8", "IF a IS G AND b IS Z AND c IS L THEN y IS lo"]
    X = np.random.default_rng(5).uniform([-1, -2, -1], [5, 2, 11], (3000, 3))
    for tnorm in ("product", "min"):
        fs = FuzzySystem([a, b, c], [y], rules, tnorm=tnorm, defuzzifier="weighted_average")
        # a rule skipping input c sums over c's terms in the fast table: exact for product only
        assert fs.fast == (tnorm == "product")
        generic = fs._generic(fs._batch(X))
        np.testing.assert_allclose(fs.evaluate(X), generic, rtol=0, atol=1e-12, equal_nan=True)
        one = np.array([fs.evaluate_one(*x) for x in X[:300]])
        np.testing.assert_allclose(one, generic[:300], rtol=0, atol=1e-12, equal_nan=True)
