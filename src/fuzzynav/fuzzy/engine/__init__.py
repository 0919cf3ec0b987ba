"""fuzzylite-compatible engines: every term, hedge, norm, activation and defuzzifier fuzzylite 8
names, several rule blocks, chained variables, per-output settings (see :mod:`.engine`)."""

from fuzzynav.fuzzy.engine.engine import Engine
from fuzzynav.fuzzy.engine.model import (
                                         Defuzzifier,
                                         EngineRule,
                                         InputVariable,
                                         Operator,
                                         OutputVariable,
                                         Proposition,
                                         RuleBlock,
)
from fuzzynav.fuzzy.engine.rule_text import parse_engine_rule

__all__ = ["Defuzzifier", "Engine", "EngineRule", "InputVariable", "Operator", "OutputVariable", "Proposition",
           "RuleBlock", "parse_engine_rule"]
