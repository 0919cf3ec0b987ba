"""Exploration policies (§III.4.10) draw from their stated distributions; schedules (eq III.24)."""

import numpy as np
import pytest
from scipy import stats

from fuzzynav.errors import InputError
from fuzzynav.learn.exploration import Boltzmann, EpsilonGreedy, Greedy, Softmax, policy_from_dict, row_max
from fuzzynav.learn.schedules import (
    Constant,
    ExponentialDecay,
    InverseVisits,
    as_schedule,
    schedule_from_dict,
    schedule_to_dict,
)

Q_ROW = np.array([0.5, 2.0, -1.0, 1.5])
DRAWS = 40_000


def frequencies(policy, q_row=Q_ROW, t=0, seed=0):
    """Empirical action frequencies from one vectorised call on DRAWS identical rows."""
    q = np.broadcast_to(q_row, (DRAWS, q_row.size))
    choice = policy.choose(q, np.random.default_rng(seed), t)
    assert choice.shape == (DRAWS,)
    return np.bincount(choice, minlength=q_row.size)


def assert_distribution(counts, p):
    """χ² goodness of fit at the 0.1 % level (fixed seeds: deterministic outcome)."""
    p = np.asarray(p)
    support = p > 0
    assert counts[~support].sum() == 0
    if support.sum() == 1:
        return
    assert stats.chisquare(counts[support], DRAWS * p[support]).pvalue > 1e-3


@pytest.mark.parametrize(
    "policy, expected",
    [
        (Greedy(), [0, 1, 0, 0]),
        (EpsilonGreedy(0.2), [0.05, 0.85, 0.05, 0.05]),
        (Softmax(offset=1.0), (Q_ROW + 2.0) / (Q_ROW + 2.0).sum()),
        (Boltzmann(0.5), np.exp(Q_ROW / 0.5) / np.exp(Q_ROW / 0.5).sum()),
    ],
)
def test_policies_sample_their_distribution(policy, expected):
    np.testing.assert_allclose(policy.probabilities(Q_ROW), expected)
    assert_distribution(frequencies(policy), expected)


def test_greedy_breaks_exact_ties_uniformly():
    counts = frequencies(Greedy(), np.array([1.0, 3.0, 3.0, 3.0]))
    assert_distribution(counts, [0, 1 / 3, 1 / 3, 1 / 3])


def test_boltzmann_temperature_limits_and_decay():
    cold = Boltzmann(1e-3).probabilities(Q_ROW)
    hot = Boltzmann(1e3).probabilities(Q_ROW)
    assert cold[1] == pytest.approx(1.0) and np.allclose(hot, 0.25, atol=1e-3)
    decaying = EpsilonGreedy(ExponentialDecay(1.0, 0.5, floor=0.1))
    assert decaying.probabilities(Q_ROW, t=0)[0] == pytest.approx(0.25)  # ε = 1: uniform
    assert decaying.probabilities(Q_ROW, t=10)[0] == pytest.approx(0.1 / 4)  # ε at its floor
    assert_distribution(frequencies(decaying, t=1), [0.125, 0.625, 0.125, 0.125])


def test_rows_are_independent_and_reproducible():
    q = np.random.default_rng(3).normal(size=(5, 7, 4))
    a = EpsilonGreedy(0.5).choose(q, np.random.default_rng(9))
    b = EpsilonGreedy(0.5).choose(q, np.random.default_rng(9))
    assert a.shape == (5, 7) and np.array_equal(a, b)
    assert len(np.unique(a)) == 4


def test_schedules():
    assert Constant(0.3)(7) == 0.3 and Constant(0.3)(np.arange(3)).tolist() == [0.3] * 3
    assert ExponentialDecay(1.0, 0.9, 0.5)(np.array([0, 1, 100])).tolist() == pytest.approx([1.0, 0.9, 0.5])
    # eq III.24: β = 1 / (1 + visits)
    assert InverseVisits()(np.array([0, 1, 3])).tolist() == pytest.approx([1.0, 0.5, 0.25])
    assert InverseVisits(power=0.5 + 1e-9, floor=0.2)(99) == pytest.approx(0.2)
    for schedule in (Constant(0.1), ExponentialDecay(0.5, 0.99, 0.01), InverseVisits(2.0, 0.8)):
        assert schedule_from_dict(schedule_to_dict(schedule)) == schedule
    assert as_schedule(0.2) == Constant(0.2)
    for rate in (1.5, 0.0):  # in (0, 1]
        with pytest.raises(InputError, match="rate"):
            ExponentialDecay(1.0, rate)
    assert ExponentialDecay(1.0, 1.0)(5) == 1.0
    for power in (0.4, 0.5, 1.1):  # in (0.5, 1]
        with pytest.raises(InputError, match="power"):
            InverseVisits(power=power)
    with pytest.raises(InputError, match="alpha"):
        as_schedule("fast", "alpha")
    with pytest.raises(InputError, match="schedule kind"):
        schedule_from_dict({"kind": "cosine"})


def test_policy_round_trip_and_bad_parameters():
    for policy in (Greedy(), EpsilonGreedy(ExponentialDecay(0.5, 0.99)), Softmax(0.5), Boltzmann(2.0)):
        copy = policy_from_dict(policy.to_dict())
        assert type(copy) is type(policy) and copy.to_dict() == policy.to_dict()
        assert copy == policy  # each parameter itself, not one dropped from both documents
        np.testing.assert_array_equal(copy.probabilities(Q_ROW, t=50), policy.probabilities(Q_ROW, t=50))
    with pytest.raises(InputError, match="offset"):
        Softmax(0.0)
    with pytest.raises(InputError, match="tau"):
        Boltzmann(0.0).probabilities(Q_ROW)
    with pytest.raises(InputError, match="policy kind"):
        policy_from_dict({"kind": "ucb"})


def test_row_max_and_greedy_on_large_batches_match_numpy():
    q = np.random.default_rng(2).normal(size=(64, 2, 35, 5))
    np.testing.assert_array_equal(row_max(q), q.max(axis=-1))
    assert np.array_equal(Greedy().choose(q, np.random.default_rng(0)), q.argmax(axis=-1))
    shared = Greedy().choose(q[0], np.random.default_rng(0), batch=3)
    assert shared.shape == (3, 2, 35) and np.array_equal(shared[2], q[0].argmax(axis=-1))
