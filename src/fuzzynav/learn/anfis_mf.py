"""ANFIS layer 1 (thesis §V.3.4, eq V.8): premise membership functions with analytic gradients.

Two families, vectorised over a batch of samples and over every membership function of the grid
at once — ``x`` has one column per MF, holding the input that MF reads:

- ``"bell"`` — generalized bell, parameters (a, b, c): μ = 1 / (1 + |(x − c)/a|^(2b)) (eq V.8);
- ``"gaussian"`` — parameters (σ, m): μ = exp(−(x − m)² / (2σ²)) (the thesis' §V.3.5.1 choice).

Parameter order is the constructor order of :class:`fuzzynav.fuzzy.Bell` / :class:`~fuzzynav.fuzzy.Gaussian`,
so a trained premise row is exported as it is.
"""

from __future__ import annotations

import math

import numpy as np

FAMILIES = ("bell", "gaussian")
PARAMETER_NAMES = {"bell": ("a", "b", "c"), "gaussian": ("sigma", "mean")}

# Smallest width (fraction of the input span) and the slope bounds kept after a gradient step.
_MIN_WIDTH = 1e-3
_B_BOUNDS = (0.05, 100.0)


def grid_premises(family: str, lo: float, hi: float, n: int) -> np.ndarray:
    """Jang's initial grid partition of [lo, hi]: ``n`` evenly spaced MFs, neighbours crossing at 0.5.

    Bell: c on the grid, a = half the spacing, b = 2. Gaussian: m on the grid, σ such that
    μ = 0.5 half-way between two centres. One MF covers the whole interval.
    """
    span = hi - lo
    centres = np.linspace(lo, hi, n) if n > 1 else np.array([(lo + hi) / 2.0])
    half = span / (2.0 * (n - 1)) if n > 1 else span / 2.0
    if family == "bell":
        return np.column_stack([np.full(n, half), np.full(n, 2.0), centres])
    return np.column_stack([np.full(n, half / math.sqrt(2.0 * math.log(2.0))), centres])


def evaluate(family: str, x: np.ndarray, params: np.ndarray) -> np.ndarray:
    """Membership degrees μ (N, M) of ``x`` (N, M) for the M rows of ``params`` (M, P)."""
    if family == "bell":
        a, b, c = params[:, 0], params[:, 1], params[:, 2]
        u = (x - c) / a
        with np.errstate(over="ignore"):
            return 1.0 / (1.0 + (u * u) ** b)
    sigma, mean = params[:, 0], params[:, 1]
    z = (x - mean) / sigma
    return np.exp(-0.5 * z * z)


def evaluate_with_gradient(family: str, x: np.ndarray, params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """μ (N, M) and ∂μ/∂params (N, M, P), analytically (Jang 1993, backward pass of Table V.2).

    Bell, with u = (x − c)/a and q = μ(1 − μ): ∂μ/∂a = 2b q / a, ∂μ/∂b = −ln(u²) q,
    ∂μ/∂c = 2b q / (a u) (all 0 at u = 0). Gaussian, z = (x − m)/σ: ∂μ/∂σ = μ z² / σ, ∂μ/∂m = μ z / σ.
    """
    if family == "bell":
        a, b, c = params[:, 0], params[:, 1], params[:, 2]
        u = (x - c) / a
        s = u * u
        with np.errstate(over="ignore"):
            mu = 1.0 / (1.0 + s ** b)
        q = mu * (1.0 - mu)
        nonzero = s > 0.0
        inv_u = np.divide(1.0, u, out=np.zeros_like(u), where=nonzero)
        log_s = np.log(s, out=np.zeros_like(s), where=nonzero)
        grad = np.stack([2.0 * b * q / a, -log_s * q, 2.0 * b * q * inv_u / a], axis=-1)
        return mu, grad
    sigma, mean = params[:, 0], params[:, 1]
    z = (x - mean) / sigma
    mu = np.exp(-0.5 * z * z)
    return mu, np.stack([mu * z * z / sigma, mu * z / sigma], axis=-1)


def parameter_scale(family: str, initial: np.ndarray) -> np.ndarray:
    """Per-parameter scale (M, P) of the normalised step, from the initial premises (M, P).

    Gradient steps are taken in dimensionless coordinates: widths and centres in units of the
    MF's initial width (a or σ — half the grid spacing for Jang's partition), the bell slope b in
    units of its initial value. A step of length k then moves every kind of parameter by the same
    relative amount, whatever the units of the input.
    """
    width = np.abs(initial[:, 0])
    if family == "bell":
        return np.column_stack([width, np.abs(initial[:, 1]), width])
    return np.column_stack([width, width])


def keep_valid(family: str, params: np.ndarray, spans: np.ndarray) -> None:
    """Clip in place what a gradient step may break: widths > 0 and a bell slope b within bounds."""
    np.maximum(params[:, 0], _MIN_WIDTH * spans, out=params[:, 0])
    if family == "bell":
        np.clip(params[:, 1], *_B_BOUNDS, out=params[:, 1])
