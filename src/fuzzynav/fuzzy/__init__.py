"""Fuzzy-logic library (thesis chapter II, §IV.3): membership functions, linguistic variables,
rule bases and TS0 / TS1 / Mamdani / Tsukamoto inference, vectorised with NumPy; fuzzylite-style
engines (:class:`Engine`: every fuzzylite term, hedge, norm, activation and defuzzifier), read and
written as FLL or MATLAB .fis (:mod:`fuzzynav.fuzzy.io`), exported to C (:mod:`.export_c`).

Knows nothing of robots. The thesis' own systems are in :mod:`fuzzynav.fuzzy.systems`.
"""

from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.membership import (
    Bell,
    Gaussian,
    Linear,
    MembershipFunction,
    Ramp,
    Sigmoid,
    Singleton,
    Trapezoidal,
    Triangular,
)
from fuzzynav.fuzzy.partition import PartitionReport, check_strong_partition, strong_partition
from fuzzynav.fuzzy.rules import Rule, parse_rule, rules_from_grid
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable

__all__ = [
    "Bell", "Engine", "FuzzySystem", "Gaussian", "Linear", "MembershipFunction", "PartitionReport", "Ramp", "Rule",
    "Sigmoid", "Singleton", "Trapezoidal", "Triangular", "Variable", "check_strong_partition", "parse_rule",
    "rules_from_grid", "strong_partition",
]
