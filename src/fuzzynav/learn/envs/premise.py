"""Fast firing strengths of a complete rule grid over piecewise-linear partitions (Algorithm VI.1 step i).

Fuzzy Q-learning evaluates the premise of every rule at every step of every episode. The rule
bases of chapter VI are complete grids (every combination of one term per input: 15, 35 or 8
rules) over triangular / trapezoidal partitions (Figs VI.5–VI.6, VI.11–VI.12, VI.17), so the
membership degrees of each input are an exact linear interpolation between its breakpoints and
w_r = Π_i μ_{i, t(r, i)}(x_i) (product T-norm, eq IV.5) is one gather and one product per input.
:class:`GridPremise` wraps a :class:`~fuzzynav.fuzzy.FuzzySystem` (the source of truth for the
partitions and the rule order) and gives the same strengths as its ``firing_strengths``, faster.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.errors import InputError


class _Interpolated:
    """Membership degrees of one input, gathered for the rules, by interpolation between breakpoints.

    ``columns`` selects, for every rule, the term of this input it names: ``__call__`` returns
    μ_{t(r)}(x) for every rule r, shape (N, R).
    """

    def __init__(self, variable, columns):
        lo, hi = variable.universe
        inner = {b for mf in variable.terms.values() for b in mf.breakpoints() if lo < b < hi}
        bp = np.array(sorted(inner | {lo, hi}))
        mu = variable.fuzzify(bp, clamp=False)  # (n_bp, n_terms)
        slope = np.diff(mu, axis=0) / np.diff(bp)[:, None]
        self.lo, self.hi, self.bp, self.inner = lo, hi, bp, bp[1:-1].copy()
        self.mu, self.slope = mu[:-1, columns], slope[:, columns]
        mid = 0.5 * (bp[:-1] + bp[1:])
        if not np.allclose(self(mid), variable.fuzzify(mid, clamp=False)[:, columns], atol=1e-12):
            raise InputError(f"input {variable.name!r} is not piecewise linear", field="premise")

    def __call__(self, x):
        x = np.minimum(np.maximum(x, self.lo), self.hi)
        k = np.searchsorted(self.inner, x, side="right")
        return np.take(self.mu, k, axis=0) + (x - np.take(self.bp, k))[:, None] * np.take(self.slope, k, axis=0)


class GridPremise:
    """Premise of a TS0 system whose rules cover its term grid: ``firing_strengths(X)`` (N, R)."""

    def __init__(self, system):
        premises = system.compiled.premises
        if (premises < 0).any():
            raise InputError("every rule must name one term of every input", field="premise")
        self.system = system
        self.premises = premises
        self.inputs = [_Interpolated(v, premises[:, i]) for i, v in enumerate(system.inputs)]
        self.n_rules = premises.shape[0]

    def firing_strengths(self, X, normalise: bool = True) -> np.ndarray:
        X = np.asarray(X, dtype=float)
        w = self.inputs[0](X[:, 0])
        for i in range(1, len(self.inputs)):
            w *= self.inputs[i](X[:, i])
        if normalise:
            total = w.sum(axis=1, keepdims=True)
            w = np.divide(w, total, out=np.zeros_like(w), where=total > 0)
        return w
