"""Learning-core step rate: fuzzy Q-learning (Algorithm VI.1) and tabular Q(λ) updates.

For the 35-rule goal-seeking premise of Table IV.1 (5 candidates per rule, as in §VI.5.1 (b)),
with B = 1, 16 and 256 parallel episodes, it times separately
- the premise (``FuzzySystem.firing_strengths``, the fuzzy library),
- the learner's own work per step (policy, Q(s, A), V*, ΔQ, traces) with the strengths given,
- and a tabular Watkins Q(λ) step over 19 states × 5 actions (Table VI.1's largest table).
Then it extrapolates the learner-side cost of 3,000 FQL episodes of 250 steps (the target:
under 30 s, simulator excluded). Prints a table and one JSON line (medians of 5 timed chunks, CPU time).
Run:  python benchmarks/learn_core.py [--batches 1,16,256]
"""

from __future__ import annotations

import json
import statistics
import time

import numpy as np

from fuzzynav.cli import Parser
from fuzzynav.fuzzy.constants import STEERING_SINGLETONS
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.fql import FuzzyQLearner
from fuzzynav.learn.tabular import TabularLearner

STEPS, CHUNKS = 200, 5


class GivenStrengths:
    """A premise that returns precomputed strengths: isolates the learner's own cost."""

    def __init__(self, w):
        self.w, self.n_rules = w, w.shape[1]

    def firing_strengths(self, X, normalise=True):
        return self.w


def median_time(function) -> float:
    """Median seconds per call over CHUNKS chunks of STEPS calls."""
    times = []
    for _ in range(CHUNKS):
        start = time.process_time()
        for _ in range(STEPS):
            function()
        times.append((time.process_time() - start) / STEPS)
    return statistics.median(times)


def main(argv=None) -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--batches", default="1,16,256", help="parallel episodes B, comma-separated")
    batches = [int(b) for b in parser.parse_args(argv).batches.split(",")]
    rng = np.random.default_rng(0)
    system = goal_seeking()
    candidates = np.array([STEERING_SINGLETONS[k] for k in ("NG", "NM", "Z", "PM", "PG")])  # Fig IV.7
    rows = []
    for batch in batches:
        X = np.column_stack([rng.uniform(0, 20, batch), rng.uniform(-np.pi, np.pi, batch)])
        premise_s = median_time(lambda X=X: system.firing_strengths(X))
        w = system.firing_strengths(X)
        learner = FuzzyQLearner(GivenStrengths(w), candidates, gamma=0.9, alpha=0.1, lam=0.7,
                                policy=EpsilonGreedy(0.1), n_learners=batch)
        learner.begin(X, rng)
        reward, done = np.zeros(batch), np.zeros(batch, dtype=bool)
        learner_s = median_time(lambda learner=learner, X=X, reward=reward, done=done: learner.step(reward, X, done, rng))
        table = TabularLearner(19, 5, method="q_lambda", lam=0.7, n_tables=batch)
        s = rng.integers(0, 19, batch)
        table.begin(s, rng)
        tabular_s = median_time(lambda table=table, s=s, reward=reward, done=done: table.step(reward, s, done, rng))
        rows.append({"batch": batch, "premise_us": premise_s * 1e6, "fql_learner_us": learner_s * 1e6,
                     "tabular_qlambda_us": tabular_s * 1e6,
                     "fql_3000x250_learner_s": 3000 * 250 * (premise_s + learner_s) / batch})
    print(f"{'B':>5} {'premise µs':>11} {'FQL learner µs':>15} {'tab Q(λ) µs':>12} {'3000 ep. (s)':>13}")
    for r in rows:
        print(f"{r['batch']:>5} {r['premise_us']:>11.1f} {r['fql_learner_us']:>15.1f} "
              f"{r['tabular_qlambda_us']:>12.1f} {r['fql_3000x250_learner_s']:>13.2f}")
    print(json.dumps({"benchmark": "learn_core", "rows": rows}))


if __name__ == "__main__":
    main()
