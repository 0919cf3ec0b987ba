"""fuzzylite-compatible engines: every term, hedge, norm, activation and defuzzifier fuzzylite 8
names, several rule blocks, chained variables, per-output settings (see :mod:`.engine`).

The pipeline, stage by stage, and the module of each:

- **model and text** — :mod:`.model` (variables, terms' owners, rule blocks, rules, as FLL names
  them), :mod:`.rule_text` (``if A is very X or ... then O is W with 0.5``), :mod:`.convert`
  (between a thesis :class:`~fuzzynav.fuzzy.system.FuzzySystem` and an engine);
- **the engine** — :mod:`.engine`: :class:`Engine` evaluates an ``(N, n_inputs)`` batch as
  fuzzylite 8 processes an engine, through one of two paths that give the same bits:
- **packing** (once per engine) — :mod:`.pack`: the engine as flat arrays for the fused kernel;
  what it cannot take is the engine's ``fallback`` (why the staged path runs instead);
- **the fused kernel** — :mod:`.fused_kernel`: one compiled call from the input batch to the
  outputs, by blocks of rows that fit in cache: input clipping,
  - *fuzzification* — :mod:`.fuzzify_terms` (one loop per term type, hedges), with
    :mod:`.vmath` (``exp`` / ``log`` the compiler vectorises) and :mod:`.quotient` (divisions by
    one denominator as multiplications, the same bits);
  - *antecedents* — postfix programs over the propositions' degrees, inside the kernel;
  - *implication and aggregation* of a Mamdani output — :mod:`.implication` (one pass over a
    term's support for the usual pairs of norms) and :mod:`.norms` (every T-norm and S-norm);
  - *defuzzification* — :mod:`.sampled_defuzzify` (centroid, bisector, the maxima of the
    sampled set), :mod:`.centroid_lanes` (the centroid's eight running sums as vector
    instructions), :mod:`.centroid_rows` (a Maximum-aggregated centroid computed across rows);
    :mod:`.sugeno_outputs` (a Takagi–Sugeno output's Σ g z / Σ g over its constant and linear
    terms);
  - *the outputs' settings* — lock-previous, default, lock-range over the whole batch;
- **the staged path** (engines the kernel does not take) — terms and hedges fuzzified in NumPy
  over the batch (:mod:`.engine`), then rules, aggregation and defuzzification compiled over the
  rows, stage by stage (:mod:`.staged_kernels`, driven output by output by :mod:`.defuzzify`).

Measured speeds, and the commands that reproduce them, are in the project's documentation.
"""

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
