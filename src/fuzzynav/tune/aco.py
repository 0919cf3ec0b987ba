"""Ant colony system over the discrete rule conclusions of a fuzzy rule base.

The thesis' last perspective: "l'optimisation des contrôleurs flous par les algorithmes de
colonies de fourmis". This is the Ant Colony System of Dorigo & Gambardella (*IEEE Trans. Evol.
Comput.* 1(1), 1997) on the graph Casillas, Cordón & Herrera use to learn fuzzy rules (*Learning
fuzzy rules using ant colony optimization algorithms*, ANTS 2000): one node per (rule, output),
one edge per term that can conclude it; an ant walks every node once, choosing a conclusion at
each. Casillas et al. take the heuristic η from the training data; here the data are closed-loop
episodes, so η leans towards the conclusion the rule base started with: η = 1 / (1 + |k − k₀|)
(k the term's rank by value, k₀ the start's), and the first iteration's best ant is no worse
than the start (it is the start's own walk, ant 0).

Each ant (ACS): with probability :data:`Q0` the edge maximising τ η^β (exploitation), otherwise
one drawn ∝ τ η^β; local update τ ← (1 − φ) τ + φ τ₀ on every edge walked; after each
iteration the global update τ ← (1 − ρ) τ + ρ / cost on the edges of the best walk so far
(τ₀ = 1 / (nodes × cost of the start), as ACS sets it from a first tour).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.errors import InputError

BETA, Q0, RHO, PHI = 2.0, 0.9, 0.1, 0.1  # ACS's β, q₀, ρ, φ (Dorigo & Gambardella 1997, §IV)


class AntColonySystem:
    """ACS over ``space.choices`` (ask: one walk per ant as genes; tell: the walks' costs)."""

    def __init__(self, space, ants: int, seed: int):
        if space.n_mf:
            raise InputError("the ant colony walks rule conclusions only: use --what rules", field="--method")
        self.space, self.ants = space, ants
        self.rng = np.random.default_rng(seed)
        self.start = space.picks(space.start)
        width = max(space.choices)
        ranks = np.arange(width)[None, :]
        self.allowed = ranks < np.asarray(space.choices)[:, None]
        self.eta = np.where(self.allowed, 1.0 / (1.0 + np.abs(ranks - self.start[:, None])), 0.0) ** BETA
        self.tau = None  # set from the start's cost at the first tell
        self.best, self.best_cost = self.start.copy(), np.inf

    def _walk(self) -> np.ndarray:
        weights = (self.tau if self.tau is not None else np.ones_like(self.eta)) * self.eta
        picks = np.empty(len(weights), dtype=int)
        for node, row in enumerate(weights):
            if self.rng.random() < Q0:
                picks[node] = int(np.argmax(row))
            else:
                picks[node] = int(self.rng.choice(len(row), p=row / row.sum()))
            if self.tau is not None:
                self.tau[node, picks[node]] = (1 - PHI) * self.tau[node, picks[node]] + PHI * self.tau0
        return picks

    def ask(self) -> np.ndarray:
        walks = [self._walk() for _ in range(self.ants)]
        if self.tau is None:
            walks[0] = self.start
        return np.stack([self.space.genes_of(w) for w in walks])

    def tell(self, population: np.ndarray, values: np.ndarray) -> None:
        costs = np.asarray(values, dtype=float)[:, 0]
        walks = [self.space.picks(genes) for genes in population]
        if self.tau is None:
            self.tau0 = 1.0 / (len(self.start) * max(costs[0], 1e-9))
            self.tau = np.where(self.allowed, self.tau0, 0.0)
        i = int(np.argmin(costs))
        if costs[i] < self.best_cost:
            self.best, self.best_cost = walks[i], float(costs[i])
        nodes = np.arange(len(self.best))
        self.tau[nodes, self.best] = (1 - RHO) * self.tau[nodes, self.best] + RHO / max(self.best_cost, 1e-9)
