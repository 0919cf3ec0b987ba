"""A learned rule base must have a rule for every combination of its input terms
(:func:`fuzzynav.fuzzy.coverage.check_rules_cover`): where none fires, the robot stops or drifts."""

import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.coverage import check_rules_cover, uncovered_situation
from fuzzynav.fuzzy.membership import Singleton, Trapezoidal
from fuzzynav.fuzzy.rules import Rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable


def _system(rules):
    near_far = {"P": Trapezoidal(0, 0, 1, 2), "L": Trapezoidal(1, 2, 4, 4)}
    inputs = [Variable("front", (0, 4), near_far), Variable("left", (0, 4), near_far)]
    output = Variable("alpha", (-1, 1), {"N": Singleton(-1), "Z": Singleton(0)})
    return FuzzySystem(inputs, [output], [Rule(premises, (("alpha", "Z"),), weight) for premises, weight in rules],
                       method="ts0")


def test_every_cell_of_the_grid_needs_a_rule_of_positive_weight():
    full = [((("front", f), ("left", s)), 1.0) for f in "PL" for s in "PL"]
    assert uncovered_situation(_system(full)) is None
    assert uncovered_situation(_system(full[:3])) == {"front": "L", "left": "L"}
    assert uncovered_situation(_system(full[:3] + [(full[3][0], 0.0)])) == {"front": "L", "left": "L"}
    assert uncovered_situation(_system(full[:3]), free=({"front": "L", "left": "L"},)) is None
    assert uncovered_situation(_system(full[:1] + [((("front", "L"),), 1.0), ((("left", "L"),), 1.0)])) is None
    with pytest.raises(InputError, match="m.json: rules: no rule for the situation front is P and left is L"):
        check_rules_cover(_system([full[0], full[2], full[3]]), "m.json")
