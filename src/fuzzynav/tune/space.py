"""The search space of a role's fuzzy system: genes in [0, 1] ↔ membership breakpoints and rule conclusions.

Two parts, chosen by ``what`` (``"mf"``, ``"rules"`` or ``"both"``):

- **breakpoints** (``mf``): every distinct finite breakpoint of a variable's piecewise-linear input
  terms (triangles, trapezoids, shoulders) and every output singleton is a *knot*; knots at the ends
  of the universe stay where they are, every other knot moves inside its own box, from 45 % of the
  way to its left neighbour to 45 % of the way to its right one (the lateral tuning of Alcalá,
  Alcalá-Fdez & Herrera, *IEEE TFS* 15(4), 2007, with the boxes of this package). Boxes never
  overlap, so the knots keep their order, and every term keeps its knots by index — a strong
  partition (the thesis' inputs, §IV.3) stays a strong partition. Gene 0.5 is the knot as it was.
- **rule conclusions** (``rules``): each (rule, output) picks one of the output's terms, ordered by
  their singleton value (NG … PG for α, Z … TG for V); gene g picks term ⌊g K⌋ of K. The
  discrete view (:attr:`SearchSpace.choices`) is what the ant colony (:mod:`fuzzynav.tune.aco`) walks.

:meth:`SearchSpace.decode` builds the :class:`~fuzzynav.fuzzy.FuzzySystem` of a gene vector;
:attr:`SearchSpace.start` decodes to the system it was made from.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.membership import Singleton, Trapezoidal, Triangular
from fuzzynav.fuzzy.rules import Rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable

WHAT = ("mf", "rules", "both")
BOX = 0.45  # share of the way to a neighbouring knot a knot may move
SPREAD = 0.1  # standard deviation of a breakpoint gene around the start in a first population
REPICK = 0.15  # chance that a rule conclusion of a first-population member moves one term up or down


class Knots:
    """The knots of one variable: their values, which are free, and each free knot's box."""

    def __init__(self, variable: Variable, values: list[float]):
        lo, hi = variable.universe
        self.values = sorted(set(values))
        free, boxes = [], []
        for j, value in enumerate(self.values):
            if value in (lo, hi):
                continue
            left = self.values[j - 1] if j > 0 else (lo if lo < value else None)
            right = self.values[j + 1] if j + 1 < len(self.values) else (hi if hi > value else None)
            left = value - (right - value) if left is None else left
            right = value + (value - left) if right is None else right
            free.append(j)
            boxes.append((value - BOX * (value - left), value + BOX * (right - value)))
        self.free, self.boxes = free, boxes

    def moved(self, genes: np.ndarray) -> dict[float, float]:
        """{old knot value: new value} for genes in [0, 1] (0.5: unmoved), one per free knot."""
        out = {value: value for value in self.values}
        for j, (lo, hi), g in zip(self.free, self.boxes, genes):
            value = self.values[j]
            out[value] = value + (2 * g - 1) * ((value - lo) if g < 0.5 else (hi - value))
        return out


def _input_values(variable: Variable) -> list[float]:
    values = []
    for label, mf in variable.terms.items():
        if type(mf) not in (Trapezoidal, Triangular):
            raise InputError(f"tuning moves triangles and trapezoids only, got {type(mf).__name__}",
                             field=f"inputs.{variable.name}.{label}")
        values += [p for p in mf.params() if math.isfinite(p)]
    return values


def _output_values(variable: Variable) -> list[float]:
    for label, mf in variable.terms.items():
        if not isinstance(mf, Singleton):
            raise InputError(f"tuning needs singleton conclusions (TS0), got {type(mf).__name__}",
                             field=f"outputs.{variable.name}.{label}")
    return [mf.value for mf in variable.terms.values()]


def _moved_term(mf, moved: dict[float, float]):
    if isinstance(mf, Singleton):
        return Singleton(moved[mf.value])
    params = [moved.get(p, p) for p in mf.params()]
    return Triangular(*params) if type(mf) is Triangular else Trapezoidal(*params)


class SearchSpace:
    """Genes of ``system`` for ``what`` (module docstring): :attr:`size` genes in [0, 1]."""

    def __init__(self, system: FuzzySystem, what: str):
        if what not in WHAT:
            raise InputError(f"must be one of {', '.join(WHAT)}, got {what!r}", field="--what")
        if system.method != "ts0":
            raise InputError(f"tuning needs a TS0 system, got {system.method}", field="method")
        self.system, self.what = system, what
        variables = system.inputs + system.outputs
        self.knots = [Knots(v, _input_values(v) if k < len(system.inputs) else _output_values(v))
                      for k, v in enumerate(variables)] if what != "rules" else []
        self.n_mf = sum(len(k.free) for k in self.knots)
        self.order = {v.name: sorted(v.terms, key=lambda label: v.terms[label].value) for v in system.outputs}
        self.slots = [(r, name) for r, rule in enumerate(system.rules) for name, _ in rule.conclusions] \
            if what != "mf" else []
        self.choices = [len(self.order[name]) for _, name in self.slots]
        self.size = self.n_mf + len(self.slots)
        if self.size == 0:
            raise InputError(f"{system.name or 'the system'} has nothing to tune with --what {what}", field="--what")

    @property
    def start(self) -> np.ndarray:
        """The genes of the system as it was."""
        picks = [self.order[name].index(dict(self.system.rules[r].conclusions)[name]) for r, name in self.slots]
        return np.concatenate([np.full(self.n_mf, 0.5), self.genes_of(picks)])

    def around_start(self, n: int, rng: np.random.Generator) -> np.ndarray:
        """``(n, size)``: the start, then ``n - 1`` neighbours of it — breakpoint genes moved by
        N(0, :data:`SPREAD`), each rule conclusion moved one term up or down with chance
        :data:`REPICK` (a tuning refines the thesis' system rather than starting from nothing)."""
        population = np.tile(self.start, (n, 1))
        population[1:, :self.n_mf] += rng.normal(0.0, SPREAD, (n - 1, self.n_mf))
        steps = rng.choice((-1, 1), (n - 1, len(self.slots))) * (rng.random((n - 1, len(self.slots))) < REPICK)
        picks = np.clip(self.picks(self.start) + steps, 0, np.asarray(self.choices) - 1)
        population[1:, self.n_mf:] = np.stack([self.genes_of(p) for p in picks]) if len(self.slots) else 0.0
        return np.clip(population, 0.0, 1.0)

    def genes_of(self, picks) -> np.ndarray:
        """The rule genes (middle of each term's cell) of term indices ``picks``, one per slot."""
        return (np.asarray(picks, dtype=float) + 0.5) / np.asarray(self.choices, dtype=float)

    def picks(self, genes: np.ndarray) -> np.ndarray:
        """The term index of each (rule, output) slot of gene vector ``genes``."""
        rule_genes = np.clip(np.asarray(genes, dtype=float)[self.n_mf:], 0.0, 1.0)
        return np.minimum((rule_genes * self.choices).astype(int), np.asarray(self.choices) - 1)

    def decode(self, genes, description: str = "") -> FuzzySystem:
        """The system of gene vector ``genes`` (clipped to [0, 1])."""
        genes = np.clip(np.asarray(genes, dtype=float), 0.0, 1.0)
        if genes.shape != (self.size,):
            raise ValueError(f"expected {self.size} genes, got shape {genes.shape}")
        system = self.system
        variables = system.inputs + system.outputs
        if self.knots:
            at, new = 0, []
            for variable, knots in zip(variables, self.knots):
                moved = knots.moved(genes[at:at + len(knots.free)])
                at += len(knots.free)
                new.append(Variable(variable.name, variable.universe,
                                    {label: _moved_term(mf, moved) for label, mf in variable.terms.items()}))
            variables = new
        rules = list(system.rules)
        for (r, name), pick in zip(self.slots, self.picks(genes)):
            conclusions = tuple((n, self.order[name][pick] if n == name else t) for n, t in rules[r].conclusions)
            rules[r] = Rule(rules[r].premises, conclusions, rules[r].weight)
        n_in = len(system.inputs)
        return FuzzySystem(variables[:n_in], variables[n_in:], rules, method=system.method, tnorm=system.tnorm,
                           defuzzifier=system.defuzzifier, name=system.name,
                           description=description or system.description)
