"""The learned controllers' inputs, the learned navigator's drive and the grid premise, compiled
(thesis §VI.5, Figs VI.17, VI.20, VI.24; Algorithm VI.1 step i).

What each computes is documented where it is used: :mod:`fuzzynav.control.learned` (the inputs
d_rg, θ_r − θ_d, front / right / left distances, openness, and the navigator's blend and
supervisor) and :class:`fuzzynav.learn.envs.GridPremise` (firing strengths of a complete rule
grid). The same functions serve the controller a model file runs and its training.
The sums follow NumPy's order term for term, so the results are the same numbers.
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit
from fuzzynav.kernels import guard
from fuzzynav.kernels.motion import wrap
from fuzzynav.kernels.navigators import guarded_goal_seeking


@jit
def goal_inputs(relative, direction, headings, out):
    """(d_rg, θ_r − θ_d) into ``out`` (N, 2) from the targets' offsets (N, 2) and directions
    atan2(dy, dx) (N,) and the robots' headings (N,)."""
    for n in range(relative.shape[0]):
        out[n, 0] = math.hypot(relative[n, 0], relative[n, 1])
        out[n, 1] = -wrap(wrap(direction[n] - headings[n]))


@jit
def module_inputs(ranges, groups, open_side, out):
    """Per row of ``ranges`` (N, S): the nearest reading of each sensor group ``groups`` (3, 3)
    (front, right, left) and, with ``open_side``, the mean of the left group minus that of the
    right one, into ``out`` (N, 3 or 4)."""
    for n in range(ranges.shape[0]):
        r = ranges[n]
        for g in range(3):
            out[n, g] = min(min(r[groups[g, 0]], r[groups[g, 1]]), r[groups[g, 2]])
        if open_side:
            left = (r[groups[2, 0]] + r[groups[2, 1]] + r[groups[2, 2]]) / 3.0
            right = (r[groups[1, 0]] + r[groups[1, 1]] + r[groups[1, 2]]) / 3.0
            out[n, 3] = left - right


@jit
def seeking_far(ranges, goal, supervisor, far, x):
    """Where the supervisor (``supervisor`` = detection, front, keep, clear, vision) hands the
    robot to goal seeking, set the three distances of ``x`` (N, 3 or 4) to ``far``."""
    for n in range(ranges.shape[0]):
        if _select(ranges[n], goal[n, 0], -goal[n, 1], supervisor) == guard.GSB:
            x[n, 0] = x[n, 1] = x[n, 2] = far


@jit
def _select(readings, distance, bearing, supervisor):
    return guard.select(readings, distance, bearing, supervisor[0], supervisor[1], supervisor[2], supervisor[3],
                        supervisor[4])


@jit
def supervise_one(blend_alpha, blend_speed, goal_alpha, goal_speed, readings, distance, bearing, supervisor):
    """(α, V_r, goal seeking?) of one robot: goal seeking alone where the supervisor finds the
    way clear — no faster than the blend while something is sensed — the blend otherwise."""
    seek = _select(readings, distance, bearing, supervisor) == guard.GSB
    if not seek:
        return blend_alpha, blend_speed, False
    nearest = readings[0]
    for j in range(1, readings.shape[0]):
        nearest = min(nearest, readings[j])
    return goal_alpha, (min(goal_speed, blend_speed) if nearest < supervisor[0] else goal_speed), True


@jit
def drive(shares, ranges, goal, tables, wheelbase, supervisor, out):
    """The learned navigator of every row into ``out`` (N, 3) = α, V_r, goal seeking (0/1): the
    avoider's ``shares`` (a :class:`~fuzzynav.kernels.records.Shares`: α, V_r) plus w_free
    times the guarded goal seeker's command for ``goal`` (N, 2) = (d_rg, θ_r − θ_d), then
    :func:`supervise_one`."""
    alpha, speed, free = shares.alpha, shares.speed, shares.free
    for n in range(ranges.shape[0]):
        g_alpha, g_speed, _ = guarded_goal_seeking(tables, 0, goal[n, 0], -goal[n, 1], wheelbase)
        out[n, 0], out[n, 1], out[n, 2] = supervise_one(alpha[n] + free[n] * g_alpha, speed[n] + free[n] * g_speed,
                                                        g_alpha, g_speed, ranges[n], goal[n, 0], -goal[n, 1],
                                                        supervisor)


@jit
def grid_strengths(X, lo, hi, bp, n_inner, mu, slope, out):
    """Firing strengths (N, R) of a complete rule grid: per input i, its value clamped to
    [lo_i, hi_i], located among its inner breakpoints ``bp[i, 1 : n_inner_i + 1]``, and the
    membership of each rule's term interpolated (``mu``, ``slope`` (I, P, R)); the product over
    the inputs in order."""
    for n in range(X.shape[0]):
        for i in range(X.shape[1]):
            x = X[n, i]
            x = lo[i] if x < lo[i] else x
            x = hi[i] if x > hi[i] else x
            k = 0
            while k < n_inner[i] and bp[i, k + 1] <= x:
                k += 1
            if x != x:
                k = n_inner[i]
            offset = x - bp[i, k]
            for r in range(out.shape[1]):
                value = mu[i, k, r] + offset * slope[i, k, r]
                out[n, r] = value if i == 0 else out[n, r] * value
