"""Coverage of an input universe by its terms: a point where every membership is 0 fires no rule,
and a Takagi–Sugeno system then outputs 0/0 = NaN there.

Between two consecutive breakpoints (term parameters) a piecewise-linear membership is linear,
so testing the breakpoints and the midpoints between them finds every gap of triangles,
trapezoids and ramps exactly; smooth terms (Gaussian, bell, sigmoid) are positive everywhere.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.errors import InputError


def uncovered_point(variable) -> float | None:
    """A value of ``variable``'s universe where every term's membership is 0, or None."""
    lo, hi = variable.universe
    cuts = {lo, hi}
    for mf in variable.terms.values():
        cuts.update(p for p in mf.params() if math.isfinite(p) and lo <= p <= hi)
    cuts = np.array(sorted(cuts))
    points = np.concatenate([cuts, 0.5 * (cuts[1:] + cuts[:-1])])
    with np.errstate(all="ignore"):
        degrees = np.column_stack([np.asarray(mf(points), dtype=float) for mf in variable.terms.values()])
    empty = np.flatnonzero(~(np.nan_to_num(degrees, nan=0.0).max(axis=1) > 0.0))
    return float(points[empty[0]]) if empty.size else None


def check_covered(system, source=None) -> None:
    """Refuse a system with an input value that no term covers (its output there would be NaN)."""
    for variable in system.inputs:
        gap = uncovered_point(variable)
        if gap is not None:
            raise InputError(f"no term covers {variable.name} = {gap:g} (every membership is 0 there, so no rule "
                             "fires and the output would be NaN)", source=source, field=f"inputs.{variable.name}")
