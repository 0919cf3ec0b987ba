"""Defuzzification of one output for a batch (fuzzylite 8 semantics).

Integral defuzzifiers sample the aggregated set on ``resolution`` midpoints of the output range
(or, as MATLAB does, on ``resolution`` points from end to end): centroid Σyμ/Σμ; bisector, the
sample where the running area is closest to half (averaged over ties); mean / smallest / largest
of the samples of maximum membership (the sampling and the reductions compiled, in
:mod:`fuzzynav.fuzzy.engine.staged_kernels`). Weighted defuzzifiers group the activations by term (aggregated with the output's S-norm, or summed when it has none)
and average (``WeightedAverage``) or sum (``WeightedSum``) the terms' crisp values: a constant's
value, a linear term on the input values, a function of the degree, or — ``Tsukamoto`` — the
abscissa where a monotone term reaches the degree.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from fuzzynav.fuzzy.engine.model import OutputVariable
from fuzzynav.fuzzy.engine.records import Affine, Groups, Sampled, Units
from fuzzynav.fuzzy.engine.sampled_defuzzify import reduction_of
from fuzzynav.fuzzy.formula import Function
from fuzzynav.fuzzy.membership import Linear, Singleton
from fuzzynav.fuzzy.operators import SNORMS, TNORMS
from fuzzynav.fuzzy.terms import Constant, Scaled


def midpoints(lo: float, hi: float, resolution: int) -> np.ndarray:
    """``resolution`` cell midpoints of [lo, hi] (fuzzylite's Op.midpoints)."""
    return lo + (np.arange(resolution) + 0.5) * ((hi - lo) / resolution)


def is_takagi_sugeno(mf) -> bool:
    """Terms whose crisp value does not come from an inverse: constants, linear terms, functions."""
    return isinstance(mf, (Constant, Singleton, Linear, Function))


def _crisp(mf, degree, inputs: np.ndarray, values: dict, tsukamoto: bool) -> np.ndarray:
    if isinstance(mf, (Constant, Singleton, Linear)):
        return _affine([mf], inputs)[0]
    if isinstance(mf, Function):
        return mf(degree, values)
    if tsukamoto:
        with np.errstate(all="ignore"):
            return np.asarray(mf.inverse(degree), dtype=float)
    return mf(degree)


class Activations(NamedTuple):
    """An output's activations in order: activation a has degree ``degrees[rows[a]]`` (N,) on the
    term ``labels[a]``, with the T-norm ``implications[a]``; ``triggered`` (A, N) where not
    every row triggers, else None."""

    degrees: np.ndarray
    rows: np.ndarray
    labels: list
    implications: list
    triggered: np.ndarray | None


_EVERY_ROW = np.ones((0, 0), dtype=bool)  # a "triggered" array the kernels never read


def _groups(var: OutputVariable, acts: Activations) -> tuple:
    """Term labels in order of first activation, and the arguments of the compiled grouping."""

    index: dict = {}
    opens = np.zeros(len(acts.labels), dtype=bool)
    for a, label in enumerate(acts.labels):
        if label not in index:
            index[label], opens[a] = len(index), True
    labels = list(index)
    groups = np.array([index[label] for label in acts.labels], dtype=np.int64)
    masked = acts.triggered is not None
    return labels, (acts.degrees, Groups(acts.rows, groups, opens, acts.triggered if masked else _EVERY_ROW, masked,
                                         SNORMS.index(var.aggregation or "UnboundedSum")))


def group(var: OutputVariable, acts: Activations) -> tuple[list, np.ndarray, np.ndarray]:
    """Term labels in order of first activation, their degrees (n_terms, N) folded with the
    output's S-norm (or summed), and where each was triggered at all (n_terms, N)."""
    from fuzzynav.fuzzy.engine import staged_kernels

    labels, args = _groups(var, acts)
    n = acts.degrees.shape[1]
    degree, present = np.empty((len(labels), n)), np.empty((len(labels), n), dtype=bool)
    staged_kernels.group(*args, degree, present)
    return labels, degree, present


def weighted(var: OutputVariable, acts: Activations, inputs: np.ndarray, values: dict) -> np.ndarray:
    """Weighted average / sum over the activated terms; ``inputs`` holds the input values as rows
    (n_inputs, N)."""
    from fuzzynav.fuzzy.engine import staged_kernels

    n = inputs.shape[1]
    if not acts.labels:
        return np.full(n, np.nan)
    kind, out = var.defuzzifier.type, np.empty(n)
    weighted_sum = var.defuzzifier.kind == "WeightedSum"
    labels = list(dict.fromkeys(acts.labels))
    mfs = [var.terms[label] for label in labels]
    if kind != "Tsukamoto" and all(isinstance(mf, (Constant, Singleton, Linear)) for mf in mfs):
        _, args = _groups(var, acts)
        staged_kernels.weighted_affine(*args, Affine(*_affine_terms(mfs, inputs.shape[0])), inputs, weighted_sum, out)
        return out
    labels, degrees, present = group(var, acts)
    z = np.stack([np.broadcast_to(_crisp(mf, d, inputs, values, _tsukamoto(mf, kind)), (n,))
                  for mf, d in zip(mfs, degrees)])
    staged_kernels.weighted_average(degrees, present, z, weighted_sum, out)
    return out


def _tsukamoto(mf, kind: str) -> bool:
    base = mf.term if isinstance(mf, Scaled) else mf
    return kind == "Tsukamoto" or (kind == "Automatic" and not is_takagi_sugeno(mf) and hasattr(base, "inverse"))


def _affine_terms(mfs: list, n_inputs: int) -> tuple[np.ndarray, np.ndarray]:
    """Coefficients (n_terms, n_inputs) and constants (n_terms,) of constant and linear terms."""
    coef = np.zeros((len(mfs), n_inputs))
    const = np.empty(len(mfs))
    for k, mf in enumerate(mfs):
        if isinstance(mf, Linear):
            coef[k], const[k] = mf.coefficients, mf.constant
        else:
            const[k] = mf.params()[0]
    return coef, const


def _affine(mfs: list, inputs: np.ndarray) -> np.ndarray:
    """Values of constant and linear terms on every row: (n_terms, N)."""
    from fuzzynav.fuzzy.engine import staged_kernels

    z = np.empty((len(mfs), inputs.shape[1]))
    staged_kernels.affine(*_affine_terms(mfs, inputs.shape[0]), inputs, z)
    return z


def sampled(var: OutputVariable) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The terms of an integral output sampled at its defuzzifier's points: (shapes (T, R),
    support (T, 2), points (R,)), ``support[t]`` the first and past-the-last non-zero sample of
    term t, or (-1, R) when a sample is not in [0, 1]."""
    d = var.defuzzifier
    x = np.linspace(var.minimum, var.maximum, d.resolution) if d.grid == "linspace" else \
        midpoints(var.minimum, var.maximum, d.resolution)
    shapes = np.empty((len(var.terms), x.shape[0]))
    support = np.empty((len(var.terms), 2), dtype=np.int64)
    for t, mf in enumerate(var.terms.values()):
        with np.errstate(all="ignore"):
            shapes[t] = np.broadcast_to(np.asarray(mf(x), dtype=float), x.shape)
        nonzero = np.flatnonzero(shapes[t])
        if not ((shapes[t] >= 0) & (shapes[t] <= 1)).all():
            support[t] = (-1, x.shape[0])
        else:
            support[t] = (nonzero[0], nonzero[-1] + 1) if nonzero.size else (0, 0)
    return shapes, support, x


def integral(var: OutputVariable, acts: Activations, sampled_terms: tuple, n: int) -> np.ndarray:
    """Centroid, bisector or mean / smallest / largest of maximum for every row, on the terms
    ``sampled_terms`` (:func:`sampled`); NaN where the aggregated set is empty. With the
    ``Maximum`` aggregation the activations of one term and implication max-combine first
    (max_r T(w_r, μ) = T(max_r w_r, μ)); otherwise every activation is folded in order, as
    fuzzylite does."""
    from fuzzynav.fuzzy.engine import staged_kernels

    shapes, support, x = sampled_terms
    degrees, rows = acts.degrees, acts.rows
    if acts.triggered is not None:  # a rule that does not trigger adds nothing
        degrees, rows = np.where(acts.triggered, degrees[rows], 0.0), np.arange(len(rows), dtype=np.int64)
    keys = list(zip(acts.labels, acts.implications))
    if var.aggregation == "Maximum":
        index = {key: u for u, key in enumerate(dict.fromkeys(keys))}
        unique, units = list(index), np.array([index[key] for key in keys], dtype=np.int64)
    else:
        unique, units = keys, np.arange(len(keys), dtype=np.int64)
    terms = {label: t for t, label in enumerate(var.terms)}
    unit_term = np.array([terms[label] for label, _ in unique], dtype=np.int64)
    unit_implication = np.array([TNORMS.index(implication) for _, implication in unique], dtype=np.int64)
    out = np.empty(n)
    staged_kernels.integral(degrees, rows,
                            Units(units, unit_term, unit_implication, SNORMS.index(var.aggregation or "UnboundedSum")),
                            Sampled(shapes, support, x, reduction_of(var.defuzzifier)), out)
    return out
