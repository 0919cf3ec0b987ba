"""Tabular learners on a tiny deterministic MDP converge to Q* computed by value iteration."""

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.learn.checkpoint import train_loop
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.schedules import ExponentialDecay, InverseVisits
from fuzzynav.learn.tabular import TabularLearner, ZoneSectorDiscretiser

N_STATES, GOAL, STEP_COST, GOAL_REWARD, GAMMA = 5, 4, -0.1, 1.0, 0.9


def chain_model(s, a):
    """5-state chain: action 0 left, 1 right (walls at both ends); entering state 4 ends (+1)."""
    s_next = np.clip(s + np.where(a == 1, 1, -1), 0, N_STATES - 1)
    done = s_next == GOAL
    return s_next, np.where(done, GOAL_REWARD, STEP_COST), done


def optimal_q(gamma=GAMMA, sweeps=200):
    """Q* by value iteration (terminal state 4 has value 0)."""
    q = np.zeros((N_STATES, 2))
    s = np.repeat(np.arange(N_STATES), 2)
    a = np.tile([0, 1], N_STATES)
    s_next, r, done = chain_model(s, a)
    for _ in range(sweeps):
        q = (r + gamma * (1 - done) * q.max(axis=1)[s_next]).reshape(N_STATES, 2)
        q[GOAL] = 0.0
    return q


class ChainEnv:
    """A batch of ``rows`` chain episodes with random non-terminal starts, truncated at 30 steps."""

    def __init__(self, rows, horizon=30):
        self.rows, self.horizon = rows, horizon

    def reset(self, rng):
        self.t = 0
        self.s = rng.integers(0, GOAL, size=self.rows)
        return self.s

    def step(self, action, rng):
        self.t += 1
        self.s, r, done = chain_model(self.s, np.asarray(action))
        success = done.copy()
        return self.s, r, done, np.full(self.rows, self.t >= self.horizon), {"success": success}


def epsilon_greedy_q(epsilon, gamma=GAMMA, sweeps=300):
    """Q of the ε-greedy policy of its own Q (the fixed point SARSA converges to, ε constant)."""
    q = np.zeros((N_STATES, 2))
    s = np.repeat(np.arange(N_STATES), 2)
    a = np.tile([0, 1], N_STATES)
    s_next, r, done = chain_model(s, a)
    for _ in range(sweeps):
        pi = np.full((N_STATES, 2), epsilon / 2)
        pi[np.arange(N_STATES), q.argmax(axis=1)] += 1 - epsilon
        q = (r + gamma * (1 - done) * (pi * q).sum(axis=1)[s_next]).reshape(N_STATES, 2)
        q[GOAL] = 0.0
    return q


def test_value_iteration_reference():
    q = optimal_q()
    # from state 3 one step right reaches the goal; from state 0 four steps.
    assert q[3, 1] == pytest.approx(1.0)
    assert q[0, 1] == pytest.approx(-0.1 - 0.09 - 0.081 + 0.9**3)
    assert np.all(q[:GOAL, 1] > q[:GOAL, 0])
    # the ε-greedy values are clearly lower: SARSA's fixed point is not Q*
    assert np.abs(epsilon_greedy_q(0.3) - q).max() > 0.15


@pytest.mark.parametrize(
    "method, options, episodes, reference, tolerance",
    [
        ("q_learning", {"alpha": 0.5}, 200, optimal_q, 0.02),
        ("q_learning", {"alpha": InverseVisits(power=0.55)}, 300, optimal_q, 0.03),
        ("sarsa", {"alpha": InverseVisits(power=0.7)}, 1500, lambda: epsilon_greedy_q(0.3), 0.04),
        ("q_lambda", {"alpha": 0.3, "lam": 0.8}, 300, optimal_q, 0.02),
    ],
)
def test_learners_converge_to_their_fixed_point(method, options, episodes, reference, tolerance):
    """Q-learning and Watkins' Q(λ) reach Q*; SARSA with ε = 0.3 the ε-greedy policy's Q."""
    rows = 8
    learner = TabularLearner(N_STATES, 2, method=method, gamma=GAMMA, n_tables=rows,
                             policy=EpsilonGreedy(0.3), **options)
    result = train_loop(ChainEnv(rows), learner, episodes, np.random.default_rng(3))
    error = np.abs(learner.q[:, :GOAL] - reference()[:GOAL])
    assert error.max() < tolerance, (method, error.max())
    assert np.all(learner.greedy()[:, :GOAL] == 1)
    assert np.mean(result.curve["success"][-20:]) > 0.9


def test_sarsa_with_decaying_epsilon_acts_optimally():
    learner = TabularLearner(N_STATES, 2, method="sarsa", gamma=GAMMA, alpha=0.5, n_tables=4,
                             policy=EpsilonGreedy(ExponentialDecay(0.5, 0.95)))
    result = train_loop(ChainEnv(4), learner, 150, np.random.default_rng(5))
    assert np.all(learner.greedy()[:, :GOAL] == 1)
    assert np.abs(learner.q[:, :GOAL, 1] - optimal_q()[:GOAL, 1]).max() < 0.02
    assert np.all(np.asarray(result.curve["success"][-10:]))


def test_shared_table_learns_from_parallel_episodes():
    learner = TabularLearner(N_STATES, 2, gamma=GAMMA, alpha=0.5, policy=EpsilonGreedy(0.3))
    train_loop(ChainEnv(16), learner, 60, np.random.default_rng(0))
    assert np.abs(learner.q[0, :GOAL] - optimal_q()[:GOAL]).max() < 0.02


def test_watkins_cut_and_terminal_updates():
    learner = TabularLearner(3, 2, method="q_lambda", gamma=0.5, lam=1.0, alpha=1.0)
    learner.q[0] = [[0.0, 1.0], [0.0, 2.0], [0.0, 0.0]]
    learner.begin(np.array([0]), np.random.default_rng(0))
    learner._a = np.array([1])
    # exploratory next action (0 is not greedy in state 1): traces are cut after the update
    learner.update(np.array([0]), np.array([1]), np.array([0.0]), np.array([1]), np.array([False]),
                   a_next=np.array([0]))
    assert learner.q[0, 0, 1] == pytest.approx(1.0)  # δ = 0 + 0.5·2 − 1 = 0
    assert not learner._traces.any()
    delta = learner.update(np.array([1]), np.array([1]), np.array([3.0]), np.array([2]),
                           np.array([True]), a_next=np.array([1]))
    assert delta[0] == pytest.approx(1.0)  # terminal: no bootstrap, 3 − 2
    assert learner.q[0, 1, 1] == pytest.approx(3.0)
    assert learner.q[0, 0, 1] == pytest.approx(1.0)  # the cut trace no longer credits state 0


def test_inactive_rows_are_not_updated():
    learner = TabularLearner(N_STATES, 2, alpha=1.0, n_tables=2)
    learner.update([0, 0], [1, 1], [5.0, 5.0], [1, 1], [True, True], active=[True, False])
    assert learner.q[0, 0, 1] == 5.0 and learner.q[1, 0, 1] == 0.0
    assert learner.visits[:, 0, 1].tolist() == [1.0, 0.0]


def test_round_trip_and_bad_input():
    learner = TabularLearner(N_STATES, 2, method="sarsa", lam=0.0, alpha=InverseVisits(), n_tables=3)
    learner.q += np.random.default_rng(1).normal(size=learner.q.shape)
    learner.episode = 7
    copy = TabularLearner.from_dict(learner.to_dict())
    assert np.array_equal(copy.q, learner.q) and copy.episode == 7 and copy.method == "sarsa"
    with pytest.raises(InputError, match="method"):
        TabularLearner(3, 2, method="td")
    with pytest.raises(InputError, match="gamma"):
        TabularLearner(3, 2, gamma=1.5)
    with pytest.raises(InputError, match="batch"):
        TabularLearner(3, 2, n_tables=2).act(np.zeros(3, dtype=int), np.random.default_rng(0))
    with pytest.raises(InputError, match="a_next"):
        TabularLearner(3, 2, method="sarsa").update([0], [0], [0.0], [1], [False])


def test_zone_sector_discretiser_counts_and_mapping():
    for n_zones, n_sectors, expected in ((3, 4, 9), (3, 5, 11), (3, 6, 13), (4, 6, 19)):
        disc = ZoneSectorDiscretiser.from_counts(n_zones, n_sectors, d_max=20.0, merge_inner=True)
        assert disc.n_states == expected
    disc = ZoneSectorDiscretiser([1.0, 5.0], 4)
    assert disc.n_states == 12
    d = np.array([0.5, 0.5, 3.0, 10.0, 10.0, 10.0])
    theta = np.array([0.0, np.pi / 2, np.pi / 4 - 1e-9, np.pi, -np.pi / 2, 3 * np.pi / 4 + 1e-9])
    # sector 0 is centred on 0 (±π/4), sector 1 left (π/2), 2 behind, 3 right
    assert disc(d, theta).tolist() == [0, 1, 4, 10, 11, 10]
    merged = ZoneSectorDiscretiser([1.0, 5.0], 4, merge_inner=True)
    assert merged(d, theta).tolist() == [0, 0, 1, 7, 8, 7]
    assert set(merged(np.random.default_rng(0).uniform(0, 30, 500),
                      np.random.default_rng(1).uniform(-np.pi, np.pi, 500))) == set(range(9))
    with pytest.raises(InputError, match="zone_edges"):
        ZoneSectorDiscretiser([5.0, 1.0], 4)
