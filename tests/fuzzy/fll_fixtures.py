"""Small FLL engines written for these tests, each exercising fuzzylite features one at a time.

Shared by tests/fuzzy (properties, no pyfuzzylite) and tests/fll (the same engines evaluated by
pyfuzzylite 8). ``ENGINES[name]`` is FLL text; ``ROWWISE`` names those whose activation method
pyfuzzylite evaluates one row at a time.
"""

INPUT_TERMS = """  term: tri Triangle 0.0 2.0 4.0
  term: trap Trapezoid 1.0 2.0 3.0 5.0
  term: bell Bell 5.0 2.0 3.0
  term: gauss Gaussian 6.0 1.5
  term: gprod GaussianProduct 3.0 0.5 6.0 1.0
  term: sig Sigmoid 4.0 2.0
  term: sdiff SigmoidDifference 2.0 3.0 3.0 7.0
  term: sprod SigmoidProduct 2.0 3.0 -3.0 7.0
  term: s SShape 1.0 6.0
  term: z ZShape 2.0 8.0
  term: pi PiShape 1.0 3.0 6.0 9.0
  term: cos Cosine 5.0 4.0
  term: conc Concave 3.0 6.0
  term: conc2 Concave 8.0 5.0
  term: spike Spike 5.0 3.0
  term: arc Arc 2.0 7.0
  term: bin Binary 5.0 inf
  term: ell SemiEllipse 2.0 8.0
  term: rect Rectangle 3.0 6.0
  term: ramp Ramp 9.0 1.0
  term: disc Discrete 0.0 0.0 2.0 1.0 5.0 0.2 10.0 0.8
  term: half Triangle 2.0 5.0 8.0 0.5
  term: fun Function 0.5 + 0.4 * sin(x) * gt(x, 0) - 0.001 * x ^ 2 + 0.1 * max(lt(x, 1), ge(x, 9))
"""


def _mamdani(aggregation="Maximum", defuzzifier="Centroid 300", conjunction="Minimum", disjunction="Maximum",
             implication="Minimum", activation="General", rules=None, lock="false"):
    rules = rules or ["if x is tri and y is low then out is a", "if x is very gauss or y is not high then out is b",
                      "if x is somewhat s and (y is extremely low or x is seldom z) then out is c with 0.7",
                      "if x is pi then out is b with 0.4", "if y is high and x is any then out is c"]
    return f"""Engine: mamdani
InputVariable: x
  enabled: true
  range: 0.0 10.0
  lock-range: {lock}
{INPUT_TERMS}InputVariable: y
  enabled: true
  range: -1.0 1.0
  lock-range: false
  term: low Ramp 0.5 -1.0
  term: high Ramp -0.5 1.0
OutputVariable: out
  enabled: true
  range: 0.0 1.0
  lock-range: false
  aggregation: {aggregation}
  defuzzifier: {defuzzifier}
  default: nan
  lock-previous: false
  term: a Triangle 0.0 0.2 0.5
  term: b Cosine 0.5 0.6
  term: c SShape 0.5 0.95
RuleBlock: mamdani
  enabled: true
  conjunction: {conjunction}
  disjunction: {disjunction}
  implication: {implication}
  activation: {activation}
""" + "".join(f"  rule: {r}\n" for r in rules)


TAKAGI_SUGENO = """Engine: ts
InputVariable: a
  enabled: true
  range: 0.0 1.0
  lock-range: true
  term: lo Bell 0.0 0.4 2.0
  term: hi Bell 1.0 0.4 2.0
InputVariable: b
  enabled: true
  range: -2.0 2.0
  lock-range: false
  term: neg Sigmoid 0.0 -4.0
  term: pos Sigmoid 0.0 4.0
InputVariable: unused
  enabled: true
  range: 0.0 1.0
  lock-range: false
OutputVariable: y
  enabled: true
  range: -5.0 5.0
  lock-range: true
  aggregation: none
  defuzzifier: WeightedAverage TakagiSugeno
  default: 0.25
  lock-previous: false
  term: c Constant 1.5
  term: l Linear 2.0 -1.0 0.0 0.5
  term: l2 Linear -3.0 0.5 1.0
OutputVariable: z
  enabled: true
  range: -5.0 5.0
  lock-range: false
  aggregation: Maximum
  defuzzifier: WeightedSum
  default: nan
  lock-previous: true
  term: c Constant -1.0
  term: f Function 2 * a - b
RuleBlock: first
  enabled: true
  conjunction: AlgebraicProduct
  disjunction: AlgebraicSum
  implication: none
  activation: General
  rule: if a is lo and b is neg then y is c and z is c
  rule: if a is hi or b is pos then y is l
  rule: if a is very hi and b is somewhat neg then y is l2 and z is f with 0.5
  rule: if a is lo and b is pos then z is f
"""

TSUKAMOTO = """Engine: tsukamoto
InputVariable: x
  enabled: true
  range: -10.0 10.0
  lock-range: false
  term: small Bell -10.0 5.0 3.0
  term: medium Bell 0.0 5.0 3.0
  term: large Bell 10.0 5.0 3.0
OutputVariable: y
  enabled: true
  range: 0.0 1.0
  lock-range: false
  aggregation: Maximum
  defuzzifier: WeightedAverage Tsukamoto
  default: nan
  lock-previous: false
  term: r Ramp 0.0 0.25
  term: s SShape 0.3 0.7
  term: zz ZShape 0.4 0.9
  term: c Concave 0.6 0.8
"""

def _block(name, implication, rules, enabled="true"):
    """A rule block without conjunction or disjunction (one premise per rule)."""
    head = [f"RuleBlock: {name}", f"  enabled: {enabled}", "  conjunction: none", "  disjunction: none",
            f"  implication: {implication}", "  activation: General"]
    return "\n".join(head + [f"  rule: {r}" for r in rules]) + "\n"


_THIRDS = "  term: {} Triangle 0.0 0.25 0.5\n  term: {} Triangle 0.25 0.5 0.75\n  term: {} Triangle 0.5 0.75 1.0\n"
# a dimmer whose second block reads the first block's output ("power") as a premise; a third block is off
CHAINED = ("Engine: chained\nInputVariable: ambient\n  enabled: true\n  range: 0.0 1.0\n  lock-range: false\n"
           + _THIRDS.format("dark", "medium", "bright")
           + "OutputVariable: power\n  enabled: true\n  range: 0.0 1.0\n  lock-range: false\n  aggregation: Maximum\n"
             "  defuzzifier: Bisector 400\n  default: nan\n  lock-previous: false\n"
           + _THIRDS.format("low", "medium", "high")
           + "OutputVariable: inverse\n  enabled: true\n  range: 0.0 1.0\n  lock-range: true\n"
             "  aggregation: AlgebraicSum\n  defuzzifier: MeanOfMaximum 500\n  default: 0.5\n  lock-previous: false\n"
             "  term: low Cosine 0.2 0.5\n  term: medium Cosine 0.5 0.5\n  term: high Cosine 0.8 0.5\n"
           + _block("direct", "AlgebraicProduct", ["if ambient is dark then power is high",
                                                   "if ambient is medium then power is medium",
                                                   "if ambient is bright then power is low"])
           + _block("inverse", "EinsteinProduct", ["if power is low then inverse is high",
                                                   "if power is medium then inverse is medium",
                                                   "if power is high then inverse is low"])
           + _block("off", "Minimum", ["if ambient is dark then inverse is low"], enabled="false"))

TNORMS = ("AlgebraicProduct", "BoundedDifference", "DrasticProduct", "EinsteinProduct", "HamacherProduct", "Minimum",
          "NilpotentMinimum")
SNORMS = ("AlgebraicSum", "BoundedSum", "DrasticSum", "EinsteinSum", "HamacherSum", "Maximum", "NilpotentMaximum",
          "NormalizedSum", "UnboundedSum")
DEFUZZIFIERS = ("Centroid 300", "Bisector 300", "MeanOfMaximum 300", "SmallestOfMaximum 300",
                "LargestOfMaximum 300")
ACTIVATIONS = ("First 2 0.1", "Last 2 0.0", "Highest 2", "Lowest 2", "Proportional", "Threshold >= 0.3")

TSUKAMOTO += _block("r", "none", ["if x is small then y is r", "if x is medium then y is s",
                                  "if x is large then y is zz", "if x is medium then y is c with 0.5"])

_GRID_TERMS = ("  term: lo Triangle -0.5 0.0 0.5\n  term: mid Trapezoid 0.0 0.4 0.6 1.0\n"
               "  term: hi Ramp 0.5 1.0\n")
_GRID_RULES = ["if x is lo and y is lo then f is t0", "if x is lo and y is mid then f is t1",
               "if x is lo and y is hi then f is t2", "if x is mid and y is lo then f is t3",
               "if x is mid and y is mid then f is t4 with 0.5", "if x is mid and y is hi then f is t5",
               "if x is hi and y is lo then f is t6", "if x is hi and y is mid then f is t6",
               "if x is hi and y is hi then f is t7", "if x is very hi and y is not lo then f is t8",
               "if x is lo then f is t9", "if x is lo and y is lo and x is not hi then f is t10"]
GRID = ("Engine: grid\n" + "".join(f"InputVariable: {v}\n  enabled: true\n  range: 0.0 1.0\n  lock-range: false\n"
                                  + (_GRID_TERMS if v != "u" else "") for v in "xyu")
        + "OutputVariable: f\n  enabled: true\n  range: -10.0 10.0\n  lock-range: false\n  aggregation: none\n"
        "  defuzzifier: WeightedAverage TakagiSugeno\n  default: nan\n  lock-previous: false\n"
        + "".join(f"  term: t{k} Linear {0.5 * k - 2.0} {1.0 - 0.3 * k} {0.25 * k} {k % 3 - 1.0}\n" for k in range(11))
        + "RuleBlock: rules\n  enabled: true\n  conjunction: AlgebraicProduct\n  disjunction: AlgebraicSum\n"
        "  implication: none\n  activation: General\n" + "".join(f"  rule: {r}\n" for r in _GRID_RULES))
"""An ANFIS-like grid (MATLAB's genfis): rules "x is A and y is B" with the product, each alone in
its output term group (the fused kernel leaves their degree to the output, ``pack.rule_skipped``),
and among them a weighted rule, two rules on one term, hedges, a rule of one proposition and one
of three (computed by the rule pass)."""

# MATLAB-like Mamdani output: six terms, five of them Bells (non-zero everywhere), concluded by two
# blocks of Maximum aggregation, one implying by the minimum and one by the product: the kernel
# max-combines its units four at a time (staged_kernels._max_units)
_BELL_OUTPUT = "".join(f"  term: b{k} Bell {0.2 * k:.1f} 0.15 {1.5 + k}\n" for k in range(5)) + \
    "  term: tri Triangle 0.7 0.8 0.9\n"
OVERLAPPING = ("Engine: overlapping\nInputVariable: x\n  enabled: true\n  range: 0.0 10.0\n  lock-range: false\n"
               + INPUT_TERMS + "OutputVariable: out\n  enabled: true\n  range: 0.0 1.0\n  lock-range: false\n"
               "  aggregation: Maximum\n  defuzzifier: Centroid 200\n  default: nan\n  lock-previous: false\n"
               + _BELL_OUTPUT
               + _block("min", "Minimum", ["if x is tri then out is b0", "if x is gauss then out is b1",
                                           "if x is s then out is b2 with 0.6", "if x is bell then out is tri",
                                           "if x is trap then out is b0"])
               + _block("product", "AlgebraicProduct", ["if x is z then out is b3", "if x is pi then out is b4",
                                                        "if x is cos then out is b1"]))

ENGINES = {"mamdani": _mamdani(), "mamdani-locked": _mamdani(lock="true"), "takagi-sugeno": TAKAGI_SUGENO,
           "tsukamoto": TSUKAMOTO, "chained": CHAINED, "grid": GRID, "overlapping": OVERLAPPING}
ENGINES.update({f"tnorm-{t}": _mamdani(conjunction=t, implication=t) for t in TNORMS})
ENGINES.update({f"snorm-{s}": _mamdani(disjunction=s, aggregation=s) for s in SNORMS})
ENGINES.update({f"defuzzifier-{d.split()[0]}": _mamdani(defuzzifier=d) for d in DEFUZZIFIERS})
ENGINES.update({f"activation-{a.split()[0]}": _mamdani(activation=a) for a in ACTIVATIONS})
ROWWISE = {f"activation-{a.split()[0]}" for a in ACTIVATIONS}
