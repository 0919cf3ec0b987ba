"""Fuzzy Q-learning (Algorithm VI.1) on a 1-D toy task learns the known best conclusions."""

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import FuzzySystem, Singleton, Variable, strong_partition
from fuzzynav.learn.checkpoint import train_loop
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.fql import FuzzyQLearner, extract_system
from fuzzynav.learn.schedules import InverseVisits

LABELS = ("NG", "NP", "Z", "PP", "PG")
PEAKS = (-1.0, -0.5, 0.0, 0.5, 1.0)
MOVES = np.array([-0.25, 0.0, 0.25])  # head 0: displacement candidates
LEVELS = np.array([0.0, 0.5, 1.0])  # head 1: "speed" candidates, best ≈ |x|
BEST_MOVE = [2, 2, 1, 0, 0]  # towards 0: right, right, stay, left, left
BEST_LEVEL = [2, 1, 0, 1, 2]  # the level nearest |peak|


def line_premise() -> FuzzySystem:
    """Five rules over x ∈ [−1, 1] on a strong triangular partition (the fuzzy library's system)."""
    x = Variable("x", (-1.0, 1.0), strong_partition(PEAKS, LABELS))
    u = Variable("u", (-1.0, 1.0), {"Z": Singleton(0.0)})
    return FuzzySystem([x], [u], [f"IF x IS {label} THEN u IS Z" for label in LABELS])


class LineEnv:
    """B episodes on a line, starts in ±1.5: x' = x + move, reward (−|x'|, −|level − |x||), 15 steps."""

    def __init__(self, rows, horizon=15):
        self.rows, self.horizon = rows, horizon

    def reset(self, rng):
        self.t = 0
        self.x = rng.uniform(-1.5, 1.5, size=self.rows)
        return self.x[:, None]

    def step(self, action, rng):
        self.t += 1
        level_error = np.abs(action[:, 1] - np.abs(self.x)) if action.shape[1] > 1 else 0.0
        self.x = np.clip(self.x + action[:, 0], -1.5, 1.5)  # beyond the rules: NG, PG saturate
        reward = np.stack([-np.abs(self.x), -level_error * np.ones(self.rows)], axis=1)
        done = np.zeros(self.rows, dtype=bool)
        return self.x[:, None], reward[:, : action.shape[1]], done, np.full(self.rows, self.t >= self.horizon), {}


def make(rows=8, lam=0.0, learners=None, **options):
    return FuzzyQLearner.separate(line_premise(), [MOVES, LEVELS], gamma=0.8, alpha=InverseVisits(power=0.7), lam=lam,
                                  policy=EpsilonGreedy(0.2), n_learners=learners or rows, **options)


@pytest.mark.parametrize("lam, episodes", [(0.0, 100), (0.7, 100)])
def test_learns_best_conclusions(lam, episodes):
    learner = make(lam=lam)
    result = train_loop(LineEnv(8), learner, episodes, np.random.default_rng(11))
    assert learner.q.shape == (8, 2, 5, 3)
    assert np.argmax(learner.q[:, 0], axis=-1).tolist() == [BEST_MOVE] * 8
    assert np.argmax(learner.q[:, 1], axis=-1).tolist() == [BEST_LEVEL] * 8
    table = learner.greedy_conclusions()
    assert np.allclose(table[:, 0, :, 0], MOVES[BEST_MOVE]) and np.allclose(table[:, 1, :, 0], LEVELS[BEST_LEVEL])
    curve = np.mean(np.asarray(result.curve["mean_reward"])[:, :, 0], axis=1)
    assert curve[-10:].mean() > curve[:10].mean() + 0.05
    # every learner's extracted controller drives every start to 0 (within one move)
    for k in range(8):
        x = np.linspace(-1, 1, 9)[:, None]
        for _ in range(15):
            x = np.clip(x + learner.greedy_action(x, learner=k)[:, :1], -1, 1)
        assert np.abs(x).max() <= 0.25 + 1e-9


class TwoRules:
    """A fixed premise: w = (x, 1 − x) for x ∈ [0, 1] (N, 1) inputs."""

    n_rules = 2

    def firing_strengths(self, X, normalise=True):
        x = np.asarray(X)[:, 0]
        return np.stack([x, 1 - x], axis=1)


def test_one_step_update_is_algorithm_VI_1():
    """Hand-computed ΔQ = β[r + γ V*(s') − Q(s, A)], q[i, j_i] += ΔQ · w_i(s)."""
    learner = FuzzyQLearner(TwoRules(), [[-1.0, 1.0], [-2.0, 2.0]], gamma=0.5, alpha=0.2,
                            policy=EpsilonGreedy(0.0))
    learner.q[0] = [[[0.0, 1.0], [3.0, 0.0]]]
    rng = np.random.default_rng(0)
    action = learner.begin(np.array([[0.25]]), rng)  # greedy: rule 0 → j=1 (+1), rule 1 → j=0 (−2)
    assert action[0, 0] == pytest.approx(0.25 * 1.0 + 0.75 * -2.0)
    q_sa = 0.25 * 1.0 + 0.75 * 3.0
    learner.step(np.array([1.0]), np.array([[1.0]]), np.array([False]), rng)
    v_star = 1.0 * 1.0 + 0.0 * 3.0
    delta = 0.2 * (1.0 + 0.5 * v_star - q_sa)
    np.testing.assert_allclose(learner.q[0, 0], [[0.0, 1.0 + delta * 0.25], [3.0 + delta * 0.75, 0.0]])
    np.testing.assert_allclose(learner.visits[0, 0], [[0.0, 0.25], [0.75, 0.0]])


def test_a_reward_that_is_not_a_number_is_refused_before_it_spreads():
    learner = FuzzyQLearner(TwoRules(), [[-1.0, 1.0], [-2.0, 2.0]], policy=EpsilonGreedy(0.0))
    rng = np.random.default_rng(0)
    learner.begin(np.array([[0.25]]), rng)
    with pytest.raises(InputError, match="reward: rewards must be finite"):
        learner.step(np.array([np.nan]), np.array([[1.0]]), np.array([False]), rng)
    assert np.isfinite(learner.q).all()


@pytest.mark.parametrize("terminal_bootstrap", [False, True])
def test_a_terminal_step_is_bootstrapped_only_when_asked(terminal_bootstrap):
    """Algorithm VI.1 computes V*(s') at every step, the one into the terminal set F included
    (steps vi–viii come before "jusqu'à s_t ∈ F"); by default a terminal transition is not bootstrapped."""
    learner = FuzzyQLearner(TwoRules(), [[-1.0, 1.0], [-2.0, 2.0]], gamma=0.5, alpha=1.0,
                            policy=EpsilonGreedy(0.0), terminal_bootstrap=terminal_bootstrap)
    learner.q[0] = [[[-2.0, -2.0], [-2.0, -2.0]]]
    rng = np.random.default_rng(0)
    learner.begin(np.array([[1.0]]), rng)  # rule 0 alone, candidate 0 (a tie: the first)
    learner.step(np.array([-4.0]), np.array([[1.0]]), np.array([True]), rng)  # a collision, s' valued −2
    target = -4.0 + (0.5 * -2.0 if terminal_bootstrap else 0.0)
    assert learner.q[0, 0, 0, 0] == pytest.approx(target)
    copy = FuzzyQLearner.from_dict(learner.to_dict(), TwoRules())
    assert copy.terminal_bootstrap is terminal_bootstrap


def test_shared_learner_from_parallel_episodes():
    learner = make(rows=16, learners=1)
    train_loop(LineEnv(16), learner, 40, np.random.default_rng(2))
    assert learner.q.shape == (1, 2, 5, 3)
    assert np.argmax(learner.q[0, 0], axis=-1).tolist() == BEST_MOVE
    assert np.argmax(learner.q[0, 1], axis=-1).tolist() == BEST_LEVEL


def test_joint_outputs_share_one_quality():
    """One head with (move, level) vector conclusions, learned under one summed reward."""
    pairs = np.array([[m, v] for m in MOVES for v in LEVELS])  # 9 joint candidates
    learner = FuzzyQLearner.joint(line_premise(), pairs, gamma=0.8, alpha=InverseVisits(power=0.7),
                                  policy=EpsilonGreedy(0.3), n_learners=4)

    class SummedReward(LineEnv):
        def step(self, action, rng):
            obs, reward, *rest = super().step(action, rng)
            return (obs, reward.sum(axis=1), *rest)

    train_loop(SummedReward(4), learner, 150, np.random.default_rng(4))
    assert learner.n_outputs == 2 and learner.q.shape == (4, 1, 5, 9)
    best = np.argmax(learner.q[:, 0], axis=-1)
    assert (best // 3).tolist() == [BEST_MOVE] * 4 and (best % 3).tolist() == [BEST_LEVEL] * 4


def test_extraction_keeps_the_prior_on_near_ties():
    learner = FuzzyQLearner(TwoRules(), [-1.0, 0.0, 1.0], prior=[1, 0])
    learner.q[0, 0] = [[0.0, 0.0, 0.0], [1.0, 1.0 + 1e-9, 0.5]]
    assert learner.greedy_indices().tolist() == [[[1, 1]]]  # exact tie → prior; 1e-9 wins at tol 0
    assert learner.greedy_indices(tolerance=1e-6).tolist() == [[[1, 0]]]
    learner.q[0, 0, 1] = [1.0, 2.0, 0.5]
    assert learner.greedy_indices(tolerance=0.5).tolist() == [[[1, 1]]]
    assert learner.greedy_indices(tolerance=0.5, prior=[2, 2]).tolist() == [[[2, 1]]]  # gap 1.5 > 0.5
    assert learner.greedy_conclusions(tolerance=0.5)[0, 0, :, 0].tolist() == [0.0, 0.0]


def test_round_trip_and_bad_input():
    learner = make(rows=3, lam=0.5)
    learner.q += np.random.default_rng(0).normal(size=learner.q.shape)
    learner.episode = 5
    copy = FuzzyQLearner.from_dict(learner.to_dict(), line_premise())
    assert np.array_equal(copy.q, learner.q) and copy.episode == 5 and copy.lam == 0.5
    assert np.array_equal(copy.candidates, learner.candidates)
    with pytest.raises(InputError, match="candidates"):
        FuzzyQLearner(line_premise(), np.zeros((4, 3)))  # 4 rules of candidates for 5 rules
    with pytest.raises(InputError, match="same number"):
        FuzzyQLearner.separate(line_premise(), [MOVES, [0.0, 1.0]])
    with pytest.raises(InputError, match="prior"):
        FuzzyQLearner(line_premise(), MOVES, prior=3)
    with pytest.raises(InputError, match="batch"):
        make(rows=3).begin(np.zeros((2, 1)), np.random.default_rng(0))


def test_reward_columns_must_match_the_heads():
    learner = make(rows=2)
    rng = np.random.default_rng(0)
    learner.begin(np.zeros((2, 1)), rng)
    with pytest.raises(InputError, match="reward"):
        learner.step(np.zeros((2, 3)), np.zeros((2, 1)), np.zeros(2, dtype=bool), rng)


def test_extracted_system_is_an_ordinary_fuzzy_controller():
    learner = make(rows=2)
    learner.q[:, 0] = np.eye(3)[BEST_MOVE]  # rule i prefers candidate BEST_MOVE[i]
    learner.q[:, 1] = np.eye(3)[BEST_LEVEL]
    system = extract_system(learner, ["u", "level"], learner_index=1)
    x = np.linspace(-1.5, 1.5, 13)[:, None]
    np.testing.assert_allclose(system.evaluate(x), learner.greedy_action(x, learner=1))
    assert [str(rule) for rule in system.rules][0] == "IF x IS NG THEN u IS c2 AND level IS c2"
    named = Variable("u", (-1, 1), {"L": Singleton(-0.25), "S": Singleton(0.0), "R": Singleton(0.25)})
    system = extract_system(learner, [named, "level"])
    assert [rule.conclusions[0][1] for rule in system.rules] == ["R", "R", "S", "L", "L"]
    with pytest.raises(InputError, match="outputs"):
        extract_system(learner, ["u"])
    with pytest.raises(InputError, match="premise"):
        extract_system(FuzzyQLearner(TwoRules(), MOVES), ["u"])


def test_large_batches_take_the_scatter_path_with_the_same_result():
    learner = FuzzyQLearner(line_premise(), MOVES, n_learners=1)
    x = np.random.default_rng(0).uniform(-1, 1, (400, 1))
    j = np.random.default_rng(1).integers(0, 3, (400, 1, 5))
    w = learner.strengths(x)
    np.testing.assert_array_equal(learner._shares(w, j), (j[..., None] == np.arange(3)) * w[:, None, :, None])
