"""Vectorised inference kernels (thesis §II.4.3): firing strengths, TS0, TS1, Tsukamoto, Mamdani.

All kernels take a batch: firing strengths ``w`` of shape (N, n_rules) and return (N,) per
output. Notation of the thesis: w_i = T(μ_A1(x1), μ_A2(x2)) (IV.5, product or min), TS output
y = Σ w_i b_i (IV.4, weighted sum, exact for strong partitions) or y = Σ w_i b_i / Σ w_i
(II.40, weighted average). Where no rule concludes on an output with a non-zero strength, the
weighted average (and Mamdani's centroid) is NaN: there is nothing to average.
"""

from __future__ import annotations

import numpy as np

TNORMS = ("product", "min")
DEFUZZIFIERS = ("weighted_sum", "weighted_average", "centroid")
IMPLICATIONS = ("min", "product")
AGGREGATIONS = ("max", "sum")

# elements of one (rows × rules × samples) Mamdani block; bounds the memory of a batch
_MAMDANI_BLOCK = 4_000_000


def firing(memberships: list[np.ndarray], premises: np.ndarray, weights: np.ndarray, tnorm: str) -> np.ndarray:
    """Rule firing strengths (N, n_rules) from per-input memberships (N, n_terms_i) (eq IV.5).

    ``premises[r, i]`` is the term index of input i in rule r, or −1 if rule r ignores input i.
    The rule weight multiplies the T-norm of the premises.
    """
    n = memberships[0].shape[0]
    w = np.ones((n, premises.shape[0]))
    for i, mu in enumerate(memberships):
        cols = premises[:, i]
        used = cols >= 0
        if not used.any():
            continue
        degrees = mu[:, np.where(used, cols, 0)]
        degrees[:, ~used] = 1.0
        w = w * degrees if tnorm == "product" else np.minimum(w, degrees)
    return w * weights


def combine(w: np.ndarray, values: np.ndarray, concludes: np.ndarray, defuzzifier: str) -> np.ndarray:
    """Σ_r w_r z_r (weighted sum) or Σ_r w_r z_r / Σ_r w_r (weighted average) over the rules
    that conclude on this output (``concludes`` mask, (n_rules,)); ``values`` is (n_rules,) or
    (N, n_rules)."""
    wc = w * concludes
    num = (wc * values).sum(axis=1) if values.ndim == 2 else wc @ values
    if defuzzifier == "weighted_sum":
        return num
    den = wc.sum(axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(den > 0, num / np.where(den > 0, den, 1.0), np.nan)


def normalised(w: np.ndarray) -> np.ndarray:
    """w̄_i = w_i / Σ_j w_j row by row (ANFIS layer 3, eq V.9); rows with Σ w = 0 stay 0."""
    total = w.sum(axis=1, keepdims=True)
    return np.divide(w, total, out=np.zeros_like(w), where=total > 0)


def tsukamoto_values(w: np.ndarray, terms: list, concl: np.ndarray) -> np.ndarray:
    """z_r = B_r⁻¹(w_r) for monotone consequents B_r (Tsukamoto, §II.4.3.3); (N, n_rules).

    Per rule, as in the textbook method (fuzzylite 8 instead sums the strengths of rules that
    share a conclusion term before inverting). A rule that does not fire (w_r = 0) gets z_r = 0,
    so that a sigmoid's infinite inverse at 0 adds nothing.
    """
    z = np.zeros_like(w)
    for r, t in enumerate(concl):
        if t >= 0:
            fired = w[:, r] > 0
            z[fired, r] = terms[t].inverse(np.clip(w[fired, r], 0.0, 1.0))
    return z


def centroid_grid(universe: tuple[float, float], resolution: int) -> np.ndarray:
    """Sample abscissae of the centroid: midpoints of ``resolution`` equal cells (as fuzzylite)."""
    lo, hi = universe
    return lo + (np.arange(resolution) + 0.5) * (hi - lo) / resolution


def mamdani(w: np.ndarray, samples: np.ndarray, term_mu: np.ndarray, concl: np.ndarray,
            implication: str, aggregation: str) -> np.ndarray:
    """Mamdani inference with centroid defuzzification (§II.4.3.1), one output.

    ``term_mu`` (n_terms, R) holds each output term sampled at ``samples`` (R,); rule r clips
    (``min``) or scales (``product``) its conclusion by w_r; the implied sets are aggregated by
    ``max`` or ``sum`` (the product–sum variant); the centroid is Σ y μ(y) / Σ μ(y).
    """
    used = np.flatnonzero(concl >= 0)
    shapes = term_mu[concl[used]]  # (n_used, R)
    out = np.empty(w.shape[0])
    block = max(1, _MAMDANI_BLOCK // max(1, used.size * samples.size))
    for start in range(0, w.shape[0], block):
        wb = w[start : start + block, used][:, :, None]
        implied = np.minimum(wb, shapes) if implication == "min" else wb * shapes
        agg = implied.max(axis=1) if aggregation == "max" else implied.sum(axis=1)
        area = agg.sum(axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            out[start : start + block] = np.where(area > 0, (agg @ samples) / np.where(area > 0, area, 1.0), np.nan)
    return out
