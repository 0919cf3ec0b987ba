"""The fused kernel (one compiled call from the inputs to the outputs) gives the very bits of the
engine's NumPy path (within a few ulp where it fuzzifies Gaussian, Bell and Sigmoid terms: see
``numpy_path.py``), on every fixture engine it takes, and says why it does not take the others."""

import numpy as np
import pytest

from fuzzynav.fuzzy.engine.pack import NUMPY, TERM
from fuzzynav.fuzzy.io.fll import from_fll_engine
from tests.fuzzy.fll_fixtures import ENGINES, INPUT_TERMS
from tests.fuzzy.numpy_path import assert_fused_matches_numpy_path

FALLBACKS = {"activation-First", "activation-Last", "activation-Highest", "activation-Lowest",
             "activation-Proportional", "activation-Threshold", "takagi-sugeno", "tsukamoto"}


def _inputs(engine, n=3000):
    rng = np.random.default_rng(7)
    X = np.column_stack([rng.uniform(v.minimum - 3, v.maximum + 3, n) for v in engine.inputs])
    X[0], X[1], X[2] = np.nan, np.inf, -np.inf  # NaN and infinities propagate as in NumPy
    X[3, 0] = np.nan
    return X


@pytest.mark.parametrize("name", sorted(set(ENGINES) - FALLBACKS))
def test_fused_kernel_gives_the_bits_of_the_numpy_path(name):
    engine = from_fll_engine(ENGINES[name])
    X = _inputs(engine)
    fused = assert_fused_matches_numpy_path(engine, X)
    np.testing.assert_array_equal(fused[::101], np.vstack([engine.evaluate(X[k:k + 1]) for k in range(0, len(X), 101)]))


def _every_term_engine() -> str:
    """One input with every term type, one rule per term (hedged, every other one) on two outputs."""
    labels = [line.split()[1] for line in INPUT_TERMS.splitlines()]
    hedges = ["", "very ", "somewhat ", "extremely ", "seldom ", "not "]
    rules = "".join(f"  rule: if x is {hedges[k % 6]}{label} then y is {'lo' if k % 2 else 'hi'} and w is c{k % 2}\n"
                    for k, label in enumerate(labels))
    return (f"Engine: every\nInputVariable: x\n  enabled: true\n  range: 0.0 10.0\n  lock-range: false\n{INPUT_TERMS}"
            "OutputVariable: y\n  enabled: true\n  range: 0.0 1.0\n  lock-range: false\n  aggregation: Maximum\n"
            "  defuzzifier: Centroid 200\n  default: nan\n  lock-previous: false\n"
            "  term: lo Triangle 0.0 0.25 0.5\n  term: hi Gaussian 0.7 0.1\n"
            "OutputVariable: w\n  enabled: true\n  range: -1.0 1.0\n  lock-range: true\n  aggregation: none\n"
            "  defuzzifier: WeightedAverage\n  default: 0.0\n  lock-previous: true\n"
            "  term: c0 Constant -0.5\n  term: c1 Linear 2.0 0.1\n"
            "RuleBlock: rules\n  enabled: true\n  conjunction: Minimum\n  disjunction: Maximum\n"
            f"  implication: AlgebraicProduct\n  activation: General\n{rules}")


def test_every_term_type_and_hedge_in_the_kernel_or_numpy():
    """Terms are fuzzified in the kernel, but for Function and the rarer ones built on exp (by
    NumPy); either way the NumPy path's outputs."""
    engine = from_fll_engine(_every_term_engine())
    assert engine.fallback is None
    literals, packed = engine._packed[:2]
    how = {p.term: int(packed.literal[k, 0]) for k, p in enumerate(literals)}
    assert {t for t, h in how.items() if h == NUMPY} == {"gprod", "sdiff", "sprod", "spike", "fun"}
    assert {t for t, h in how.items() if h == TERM} == {"tri", "trap", "bell", "gauss", "sig", "s", "z", "pi", "cos",
                                                         "conc", "conc2", "arc", "bin", "ell", "rect", "ramp", "disc",
                                                         "half"}
    fused = assert_fused_matches_numpy_path(engine, _inputs(engine, 5000))
    assert np.isfinite(fused).mean() > 0.9


@pytest.mark.parametrize("name, reason", [("activation-Highest", "an activation method other than General"),
                                          ("tsukamoto", "a weighted conclusion that is not constant or linear"),
                                          ("takagi-sugeno", "output z: a weighted conclusion")])
def test_what_the_kernel_does_not_take_keeps_the_numpy_path_and_says_why(name, reason):
    engine = from_fll_engine(ENGINES[name])
    assert reason in engine.fallback
    assert np.isfinite(engine.evaluate(_inputs(engine)[4:])).any()


def test_blocks_of_rows_carry_lock_previous_across_their_boundaries():
    """The kernel runs big batches by blocks of rows (fused_kernel.ROWS at least); lock-previous still
    carries the last value of one block into the next, as the NumPy path over the whole batch."""
    from fuzzynav.fuzzy.engine import fused_kernel

    engine = from_fll_engine(_every_term_engine())
    X = _inputs(engine, 3 * fused_kernel.ROWS + 10)
    gaps = [fused_kernel.ROWS - 1, fused_kernel.ROWS, 2 * fused_kernel.ROWS, 2 * fused_kernel.ROWS + 1]
    X[gaps] = np.nan  # no rule fires: w keeps the value of the row before (lock-previous)
    out = assert_fused_matches_numpy_path(engine, X)
    w = engine.output_names.index("w")
    assert np.all(out[gaps, w] == out[[fused_kernel.ROWS - 2, fused_kernel.ROWS - 2, 2 * fused_kernel.ROWS - 1, 2 * fused_kernel.ROWS - 1], w])
    assert np.isfinite(out[gaps, w]).all()


@pytest.mark.parametrize("name", ["mamdani", "chained", "snorm-EinsteinSum"])
def test_the_flat_buffers_give_back_every_packed_array(name):
    """pack.flatten's three buffers, unpacked as the kernel does (fused_kernel._unpack), are the Packed
    arrays themselves: same order, dtypes, shapes and values."""
    from fuzzynav.fuzzy.engine.fused_kernel import _unpack
    from fuzzynav.fuzzy.engine.pack import flatten

    engine = from_fll_engine(ENGINES[name])
    assert engine.fallback is None
    packed = engine._packed[1]
    for field, original, unpacked in zip(packed._fields, packed, _unpack(*flatten(packed)), strict=True):
        assert unpacked.dtype == original.dtype and unpacked.shape == original.shape, field
        np.testing.assert_array_equal(unpacked, original, err_msg=field)


def test_rules_of_two_propositions_alone_in_their_term_group_are_left_to_the_output():
    """On the grid fixture, the rules p and q of weight 1 whose output term has no other activation
    are not computed by the rule pass (their output multiplies p q where it reads it); the weighted
    rule, the two rules on one term and the rule of three propositions are, and the rule of one
    proposition reads it in place. The outputs are the NumPy path's bits
    (test_fused_kernel_gives_the_bits_of_the_numpy_path["grid"]); here, that the kernel did defer."""
    engine = from_fll_engine(ENGINES["grid"])
    assert engine.fallback is None
    packed = engine._packed[1]
    deferred = {r for r in range(len(packed.rule_weight)) if packed.rule_skipped[r]}
    assert deferred == {0, 1, 2, 3, 5, 8, 9, 10}  # 10: one proposition, aliased
    assert int((packed.act_partner >= 0).sum()) == 7
    assert_fused_matches_numpy_path(engine, _inputs(engine))
