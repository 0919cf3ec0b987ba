"""The parts of a fuzzylite-style engine: input and output variables, rule blocks, rules.

Plain records, checked when an :class:`~fuzzynav.fuzzy.engine.Engine` is built. Names follow the
fuzzylite language (FLL), which is the reference for their meaning:

- an input's ``lock_range`` clips its value to ``[minimum, maximum]`` before fuzzification;
  without it a value outside the range is fuzzified as it is;
- an output's ``defuzzifier`` (:class:`Defuzzifier`) and ``aggregation`` (an S-norm name or
  ``None``) are its own; a non-finite result is replaced by the previous row's value
  (``lock_previous``), then by ``default`` (if not NaN), then clipped if ``lock_range``;
- a rule block has its ``conjunction`` (T-norm for ``and``), ``disjunction`` (S-norm for
  ``or``), ``implication`` (T-norm shaping a Mamdani conclusion) and ``activation`` method.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from fuzzynav.fuzzy.membership import MembershipFunction

INTEGRAL = ("Centroid", "Bisector", "MeanOfMaximum", "SmallestOfMaximum", "LargestOfMaximum")
WEIGHTED = ("WeightedAverage", "WeightedSum")
WEIGHTED_TYPES = ("Automatic", "TakagiSugeno", "Tsukamoto")
DEFAULT_RESOLUTION = 1000  # fuzzylite's IntegralDefuzzifier.default_resolution
GRIDS = ("midpoints", "linspace")  # an integral defuzzifier's samples: fuzzylite's, MATLAB's


@dataclass(frozen=True)
class Defuzzifier:
    """``kind`` in INTEGRAL or WEIGHTED (with its ``type``).

    An integral defuzzifier samples the output range at ``resolution`` points: the midpoints of
    as many equal cells (``grid="midpoints"``, fuzzylite) or evenly from end to end
    (``grid="linspace"``, MATLAB's evalfis, 101 points by default).
    """

    kind: str
    resolution: int = DEFAULT_RESOLUTION
    type: str = "Automatic"
    grid: str = "midpoints"

    @property
    def integral(self) -> bool:
        return self.kind in INTEGRAL

    def text(self) -> str:
        """As written after ``defuzzifier:`` in FLL."""
        if self.integral:
            return f"{self.kind} {self.resolution}"
        return self.kind if self.type == "Automatic" else f"{self.kind} {self.type}"


@dataclass
class InputVariable:
    """An input: its range, terms (possibly none), ``lock_range`` and ``enabled``."""

    name: str
    minimum: float
    maximum: float
    terms: dict[str, MembershipFunction] = field(default_factory=dict)
    lock_range: bool = False
    enabled: bool = True
    description: str = ""

    @property
    def universe(self) -> tuple[float, float]:
        return (self.minimum, self.maximum)

    @property
    def labels(self) -> list[str]:
        return list(self.terms)


@dataclass
class OutputVariable(InputVariable):
    """An output: the input's fields plus how it is aggregated and defuzzified."""

    aggregation: str | None = None
    defuzzifier: Defuzzifier | None = None
    default: float = math.nan
    lock_previous: bool = False


@dataclass(frozen=True)
class Proposition:
    """``variable is [hedges] term`` (``term`` is None after the hedge ``any``)."""

    variable: str
    hedges: tuple[str, ...]
    term: str | None

    def text(self) -> str:
        return " ".join([self.variable, "is", *self.hedges, *([self.term] if self.term else [])])


@dataclass(frozen=True)
class Operator:
    """``left and right`` / ``left or right``."""

    name: str  # "and" | "or"
    left: Proposition | Operator
    right: Proposition | Operator

    def text(self) -> str:
        def side(node):
            return f"({node.text()})" if isinstance(node, Operator) and node.name != self.name else node.text()
        return f"{side(self.left)} {self.name} {side(self.right)}"


@dataclass(frozen=True)
class EngineRule:
    """``if antecedent then conclusions [with weight]``."""

    antecedent: Proposition | Operator
    conclusions: tuple[Proposition, ...]
    weight: float = 1.0

    def text(self) -> str:
        then = " and ".join(c.text() for c in self.conclusions)
        weight = "" if self.weight == 1.0 else f" with {self.weight!r}"
        return f"if {self.antecedent.text()} then {then}{weight}"


@dataclass
class RuleBlock:
    """Rules evaluated together, with the operators of the module docstring."""

    rules: list[EngineRule]
    conjunction: str | None = None
    disjunction: str | None = None
    implication: str | None = None
    activation: str = "General"
    activation_params: tuple = ()
    name: str = ""
    enabled: bool = True
    description: str = ""
