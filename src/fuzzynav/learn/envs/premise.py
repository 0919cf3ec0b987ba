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

    ``columns`` selects, for every rule, the term of this input it names: between consecutive
    breakpoints ``bp`` the degrees of the rules' terms are ``mu[k] + (x − bp[k]) · slope[k]``
    (each (n_bp − 1, R)), evaluated by :func:`fuzzynav.kernels.learned.grid_strengths`.
    """

    def __init__(self, variable, columns):
        lo, hi = variable.universe
        inner = {b for mf in variable.terms.values() for b in mf.breakpoints() if lo < b < hi}
        bp = np.array(sorted(inner | {lo, hi}))
        mu = variable.fuzzify(bp, clamp=False)  # (n_bp, n_terms)
        slope = np.diff(mu, axis=0) / np.diff(bp)[:, None]
        self.lo, self.hi, self.bp = lo, hi, bp
        self.mu, self.slope = mu[:-1, columns], slope[:, columns]
        mid = 0.5 * (bp[:-1] + bp[1:])
        if not np.allclose(_strengths([self], mid[:, None]), variable.fuzzify(mid, clamp=False)[:, columns],
                           atol=1e-12):
            raise InputError(f"input {variable.name!r} is not piecewise linear", field="premise")


def _pack(inputs) -> tuple:
    """The kernel's arrays of the inputs' interpolations (padded to the longest breakpoint list)."""
    size = max(len(p.bp) for p in inputs)
    n_rules = inputs[0].mu.shape[1]
    bp = np.zeros((len(inputs), size))
    mu, slope = np.zeros((len(inputs), size - 1, n_rules)), np.zeros((len(inputs), size - 1, n_rules))
    for i, p in enumerate(inputs):
        bp[i, :len(p.bp)], mu[i, :len(p.mu)], slope[i, :len(p.slope)] = p.bp, p.mu, p.slope
    return (np.array([p.lo for p in inputs], dtype=float), np.array([p.hi for p in inputs], dtype=float), bp,
            np.array([len(p.bp) - 2 for p in inputs]), mu, slope)


def _strengths(inputs, X, packed=None) -> np.ndarray:
    import fuzzynav.kernels.learned as learned  # numba, imported when first needed

    X = np.ascontiguousarray(X, dtype=float)
    out = np.empty((X.shape[0], inputs[0].mu.shape[1]))
    learned.grid_strengths(X, *(packed or _pack(inputs)), out)
    return out


class GridPremise:
    """Premise of a TS0 system whose rules cover its term grid: ``firing_strengths(X)`` (N, R)."""

    def __init__(self, system):
        premises = system.compiled.premises
        if (premises < 0).any():
            raise InputError("every rule must name one term of every input", field="premise")
        self.system = system
        self.premises = premises
        self.inputs = [_Interpolated(v, premises[:, i]) for i, v in enumerate(system.inputs)]
        self.packed = _pack(self.inputs)
        self.n_rules = premises.shape[0]

    def firing_strengths(self, X, normalise: bool = True) -> np.ndarray:
        w = _strengths(self.inputs, np.asarray(X, dtype=float).reshape(-1, len(self.inputs)), self.packed)
        if normalise:
            total = w.sum(axis=1, keepdims=True)
            w = np.divide(w, total, out=np.zeros_like(w), where=total > 0)
        return w
