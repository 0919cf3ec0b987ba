"""Coverage of an input universe by its terms: a point where every membership is 0 fires no rule,
and a Takagi–Sugeno system then outputs 0/0 = NaN there; and of a learned rule grid by its rules.

Between two consecutive breakpoints (term parameters) a piecewise-linear membership is linear,
so testing the breakpoints and the midpoints between them finds every gap of triangles,
trapezoids and ramps exactly; smooth terms (Gaussian, bell, sigmoid) are positive everywhere.
"""

from __future__ import annotations

import itertools
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


MAX_SITUATIONS = 100_000  # combinations of input terms a rule grid is checked over


def uncovered_situation(system, free: tuple[dict, ...] = ()) -> dict | None:
    """The first combination of input terms (one term of each input, ``name -> label``) that no
    rule of positive weight covers, or None; a rule without a premise on an input covers every
    term of it. ``free`` lists partial combinations another behaviour handles (e.g. the avoider's
    "nothing near", which is goal seeking), left out."""
    premises, weights = system.compiled.premises, system.compiled.weights
    live = premises[weights > 0]
    for combination in itertools.product(*(range(len(v.terms)) for v in system.inputs)):
        labels = {v.name: v.labels[i] for v, i in zip(system.inputs, combination)}
        if any(all(labels[name] == label for name, label in part.items()) for part in free):
            continue
        if not ((live < 0) | (live == np.array(combination))).all(axis=1).any():
            return labels
    return None


def check_rules_cover(system, source=None, free: tuple[dict, ...] = ()) -> None:
    """Refuse a learned rule base with a combination of input terms that no rule covers
    (:func:`uncovered_situation`; the learned TS0 tables of §VI.4 fill their grid): there no rule
    would fire, and the output would be the empty sum, not anything learned."""
    size = math.prod(len(v.terms) for v in system.inputs)
    if size > MAX_SITUATIONS:
        raise InputError(f"a rule grid of {size:,} combinations of input terms, more than the {MAX_SITUATIONS:,} "
                         "a learned rule base may have", source=source, field="inputs")
    labels = uncovered_situation(system, free)
    if labels is not None:
        situation = " and ".join(f"{name} is {label}" for name, label in labels.items())
        raise InputError(f"no rule for the situation {situation}: a learned rule base has a rule for every "
                         "combination of its input terms (was a rule deleted?)", source=source, field="rules")
