"""Cross-check against simpful (an independent engine) on >= 1000 random inputs, |diff| <= 1e-9.

simpful's Sugeno inference with AND_PRODUCT is a product-T-norm TS0 with weighted average; on
the thesis' complete grids over strong partitions it equals the weighted sum of eq IV.4.
"""

import math

import numpy as np
import pytest

from fuzzynav.fuzzy import Triangular
from fuzzynav.fuzzy.systems import get_system

sf = pytest.importorskip("simpful")


def to_simpful(system):
    """The same system in simpful: triangles / shoulders as point lists over the universe."""
    fs = sf.FuzzySystem(show_banner=False, operators=["AND_PRODUCT"], verbose=False)
    for var in system.inputs:
        lo, hi = var.universe
        sets = []
        for label, mf in var.terms.items():
            assert isinstance(mf, Triangular) or mf.kind == "trapezoid"
            a, b, c, d = mf._edges()
            points = [[lo, 1.0] if a == -math.inf else [a, 0.0]]
            points += [[b, 1.0]] if math.isfinite(b) and b > lo else []
            points += [[c, 1.0]] if math.isfinite(c) and c != b and c < hi else []
            points += [[hi, 1.0]] if d == math.inf else [[d, 0.0]]
            sets.append(sf.FuzzySet(points=points, term=label))
        fs.add_linguistic_variable(var.name, sf.LinguisticVariable(sets, universe_of_discourse=[lo, hi]))
    for var in system.outputs:
        for label, mf in var.terms.items():
            fs.set_crisp_output_value(f"{var.name}_{label}", mf.value)
    rules = []
    for rule in system.rules:
        premise = " AND ".join(f"({v} IS {t})" for v, t in rule.premises)
        for v, t in rule.conclusions:
            rules.append(f"IF {premise} THEN ({v} IS {v}_{t})")
    fs.add_rules(rules)
    return fs


@pytest.mark.parametrize("name", ["goal-seeking", "tracking"])
def test_matches_simpful(name):
    system = get_system(name)
    peer = to_simpful(system)
    rng = np.random.default_rng(7)
    lo = np.array([v.universe[0] for v in system.inputs])
    hi = np.array([v.universe[1] for v in system.inputs])
    X = rng.uniform(lo, hi, (1000, 2))
    ours = system.evaluate(X)
    theirs = np.empty_like(ours)
    for n, x in enumerate(X):
        for var, value in zip(system.input_names, x):
            peer.set_variable(var, float(value))
        result = peer.Sugeno_inference(system.output_names)
        theirs[n] = [result[o] for o in system.output_names]
    assert np.abs(ours - theirs).max() <= 1e-9
