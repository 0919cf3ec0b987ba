"""Deep nesting in the engine readers (FLL rules, .fis and FLL formulas) is refused with the
file and line named, never a RecursionError; ordinary nesting still loads."""

import re

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.formula import Function
from fuzzynav.fuzzy.io import dumps, loads
from fuzzynav.fuzzy.systems import get_system

FLL = dumps(get_system("goal-seeking"), "fll")
RULE = re.findall(r"rule: .*", FLL)[0]


@pytest.mark.parametrize("premise, problem", [
    (" and ".join(["drg is P"] * 3000), "a premise nested deeper than 64 levels"),
    ("(" * 3000 + "drg is P" + ")" * 3000, "brackets nested deeper than 64 levels"),
])
def test_deep_fll_rule_is_refused_naming_the_line(premise, problem):
    with pytest.raises(InputError, match=rf"x.fll: line \d+: {re.escape(problem)}"):
        loads(FLL.replace(RULE, f"rule: if {premise} then alpha is Z and v is Z"), "fll", "x.fll")


def test_ordinary_nesting_still_loads():
    premise = "(" * 10 + " and ".join(["drg is P"] * 10) + ")" * 10
    engine = loads(FLL.replace(RULE, f"rule: if {premise} then alpha is PG and v is F"), "fll", "x.fll")
    plain = loads(FLL.replace(RULE, "rule: if drg is P then alpha is PG and v is F"), "fll", "y.fll")
    without = loads(FLL.replace(RULE + "\n", ""), "fll", "z.fll")
    inputs = np.array([[3.5, 0.2], [3.5, -1.0]])  # the peak of P: P^10 = P whatever the conjunction
    assert np.array_equal(engine.evaluate(inputs), plain.evaluate(inputs))
    assert not np.array_equal(engine.evaluate(inputs), without.evaluate(inputs))  # the rule counts


@pytest.mark.parametrize("formula", ["(" * 5000 + "x" + ")" * 5000, "+".join(["1"] * 5000), "-" * 5000 + "1",
                                     "^".join(["1"] * 5000)])
def test_deep_formula_is_refused(formula):
    with pytest.raises(ValueError, match="formula nested deeper than 64 levels"):
        Function(formula)


def test_deep_range_formula_in_fis_names_the_line():
    fis = dumps(get_system("goal-seeking"), "fis").replace("Range=[0.0 28.284271247461902]",
                                                           "Range=[" + "(" * 5000 + "0" + ")" * 5000 + " 28]")
    with pytest.raises(InputError, match=r"x.fis: line \d+ \(Range\)"):
        loads(fis, "fis", "x.fis")
