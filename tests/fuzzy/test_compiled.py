"""The compiled engine kernels: norms at their boundaries, and the shortcuts that must not change a bit
(skipped samples and activations of a Mamdani output, chunks of rows)."""

import numpy as np
import pytest

from fuzzynav.fuzzy.engine import centroid_rows, norms, staged_kernels
from fuzzynav.fuzzy.engine.defuzzify import midpoints
from fuzzynav.fuzzy.engine.records import Affine, Groups, Sampled, Units
from fuzzynav.fuzzy.engine.sampled_defuzzify import REDUCTIONS
from fuzzynav.fuzzy.engine.staged_kernels import AND, OR
from fuzzynav.fuzzy.io.fll import from_fll_engine
from fuzzynav.fuzzy.operators import SNORMS, TNORMS
from tests.fuzzy.fll_fixtures import ENGINES

GRID = np.linspace(0.0, 1.0, 101)


@pytest.mark.parametrize("kind", range(len(TNORMS)), ids=TNORMS)
def test_tnorm_has_one_as_identity_and_zero_as_absorbing(kind):
    for a in GRID:
        assert norms.tnorm(kind, a, 1.0) == pytest.approx(a, abs=1e-15) == norms.tnorm(kind, 1.0, a)
        assert norms.tnorm(kind, a, 0.0) == 0.0 and norms.tnorm(kind, 0.0, a) == 0.0  # exactly: see integral


@pytest.mark.parametrize("kind", range(len(SNORMS)), ids=SNORMS)
def test_snorm_has_zero_as_identity(kind):
    for a in GRID:  # exactly: see integral
        assert norms.snorm(kind, a, 0.0) == a and norms.snorm(kind, 0.0, a) == a


def test_minimum_and_maximum_propagate_nan_as_numpy_does():
    for a, b in ((np.nan, 0.3), (0.3, np.nan)):
        assert np.isnan(norms.tnorm(TNORMS.index("Minimum"), a, b))
        assert np.isnan(norms.snorm(SNORMS.index("Maximum"), a, b))


def _shapes(rng, n_terms, size):
    """Triangles, some narrow (short support), plus one term nowhere zero."""
    x = midpoints(0.0, 1.0, size)
    centres, widths = rng.uniform(0, 1, n_terms), rng.uniform(0.02, 0.6, n_terms)
    shapes = np.clip(1.0 - np.abs(x[None, :] - centres[:, None]) / widths[:, None], 0.0, 1.0)
    shapes[0] = 0.5 + 0.5 * np.cos(3 * x)
    return np.ascontiguousarray(shapes), x


@pytest.mark.parametrize("reduction", range(len(REDUCTIONS)), ids=REDUCTIONS)
def test_integral_skips_only_what_cannot_change_the_result(reduction):
    """Skipping zero activations and samples outside a term's support gives the very bits of
    sampling every term everywhere, for every implication and aggregation."""
    rng = np.random.default_rng(reduction)
    shapes, x = _shapes(rng, 5, 97)
    degrees = rng.uniform(0, 1, (7, 300))
    degrees[rng.uniform(size=degrees.shape) < 0.4] = 0.0
    degrees[:, :3] = 0.0  # rows where nothing fires: NaN
    degrees[2, 3] = 1.5  # a row outside [0, 1] takes the full path
    rows = np.arange(7, dtype=np.int64)
    terms = np.array([0, 1, 2, 3, 4, 1, 3], dtype=np.int64)
    support = np.array([[np.flatnonzero(s)[0], np.flatnonzero(s)[-1] + 1] for s in shapes], dtype=np.int64)
    everywhere = np.tile(np.array([-1, x.size], dtype=np.int64), (5, 1))
    for aggregation in range(len(SNORMS)):
        for implication in range(len(TNORMS)):
            if SNORMS[aggregation] == "Maximum":  # units: one per (term, implication)
                units, unit_term = terms, np.arange(5, dtype=np.int64)
            else:
                units, unit_term = rows, terms
            imps = np.full(unit_term.size, implication, dtype=np.int64)
            fast, full = np.empty(300), np.empty(300)
            unit = Units(units, unit_term, imps, aggregation)
            staged_kernels.integral(degrees, rows, unit, Sampled(shapes, support, x, reduction), fast)
            staged_kernels.integral(degrees, rows, unit, Sampled(shapes, everywhere, x, reduction), full)
            np.testing.assert_array_equal(fast, full, err_msg=f"{SNORMS[aggregation]} / {TNORMS[implication]}")
            assert np.isnan(fast[:3]).all()
            if (SNORMS[aggregation], TNORMS[implication]) == ("Maximum", "Minimum"):
                assert (np.isfinite(fast) == (degrees > 0).any(axis=0)).all()


@pytest.mark.parametrize("reduction", range(len(REDUCTIONS)), ids=REDUCTIONS)
def test_maximum_units_four_at_a_time_give_the_bits_of_one_by_one(reduction):
    """Units of Maximum aggregation whose supports overlap are max-combined four in one pass
    (staged_kernels._max_units): the very bits of one pass each, the minimum and the product mixed, with
    zero degrees, a unit of narrow support among them and rows outside [0, 1] or NaN."""
    rng = np.random.default_rng(10 + reduction)
    x = np.linspace(0.0, 1.0, 201)
    centres = np.array([0.0, 0.25, 0.5, 0.75, 1.0, 0.3])
    shapes = 1.0 / (1.0 + np.abs((x[None, :] - centres[:, None]) / 0.2) ** 3.0)
    shapes[5] = np.clip(1.0 - np.abs(x - 0.3) / 0.05, 0.0, 1.0)  # a narrow triangle
    support = np.array([[np.flatnonzero(s)[0], np.flatnonzero(s)[-1] + 1] for s in shapes], dtype=np.int64)
    unit_term = np.array([0, 1, 5, 2, 3, 4, 1, 2, 0], dtype=np.int64)
    implication = np.array([norms.MINIMUM, norms.PRODUCT] * 4 + [norms.MINIMUM], dtype=np.int64)
    degrees = rng.uniform(0, 1, (unit_term.size, 400))
    degrees[rng.uniform(size=degrees.shape) < 0.3] = 0.0
    degrees[:, :2] = 0.0  # nothing fires
    degrees[3, 2], degrees[1, 3] = 1.5, np.nan  # rows that take the full path
    rows = units = np.arange(unit_term.size, dtype=np.int64)
    maximum = SNORMS.index("Maximum")
    assert staged_kernels._spans_overlap(support, unit_term, units, 0)[2]
    four, one_by_one = np.empty(400), np.empty(400)
    for use_four, out in ((True, four), (False, one_by_one)):
        staged_kernels._integral(use_four, degrees, rows, Units(units, unit_term, implication, maximum),
                                 Sampled(np.ascontiguousarray(shapes), support, x, reduction), out, 0, 400)
    np.testing.assert_array_equal(four, one_by_one)
    assert np.isfinite(four[4:]).mean() > 0.9


def test_a_sparse_centroid_computed_across_rows_gives_the_bits_of_row_by_row():
    """A centroid of Maximum aggregation over short supports (a partition of triangles, one term
    twice with either implication) is computed across rows (centroid_rows.max_centroid): the very
    bits of the row-by-row pass, rows of degrees outside [0, 1] or NaN (left to it) included."""
    rng = np.random.default_rng(3)
    x = np.linspace(0.0, 30.0, 200)
    shapes = np.ascontiguousarray(np.clip(1.0 - np.abs(x[None, :] - np.array([5.0, 15.0, 25.0, 12.0])[:, None]) / 3.0,
                                          0.0, 1.0))
    support = np.array([[np.flatnonzero(s)[0], np.flatnonzero(s)[-1] + 1] for s in shapes], dtype=np.int64)
    unit_term = np.array([0, 1, 2, 3, 1], dtype=np.int64)
    implication = np.array([norms.MINIMUM, norms.MINIMUM, norms.PRODUCT, norms.MINIMUM, norms.PRODUCT], dtype=np.int64)
    rows = np.arange(6, dtype=np.int64)
    units = np.array([0, 1, 2, 3, 4, 0], dtype=np.int64)  # unit 0: two activations, max-combined
    degrees = rng.uniform(0, 1, (6, 1000))
    degrees[rng.uniform(size=degrees.shape) < 0.4] = 0.0
    degrees[:, :2] = 0.0
    degrees[0, 2], degrees[5, 3], degrees[2, 4] = np.nan, 1.5, -0.25
    maximum = SNORMS.index("Maximum")
    assert centroid_rows.applies(unit_term, implication, support, x.size)
    across_rows, row_by_row = np.empty(1000), np.empty(1000)
    unit, sampled = Units(units, unit_term, implication, maximum), Sampled(shapes, support, x, 0)
    staged_kernels.integral(degrees, rows, unit, sampled, across_rows)
    staged_kernels._integral(False, degrees, rows, unit, sampled, row_by_row, 0, 1000)
    np.testing.assert_array_equal(across_rows, row_by_row)
    assert np.isnan(across_rows[:3]).all() and np.isfinite(across_rows[3:5]).all()
    assert np.isfinite(across_rows[5:]).mean() > 0.9


@pytest.mark.parametrize("name", ["takagi-sugeno", "mamdani", "chained", "activation-Highest", "snorm-EinsteinSum"])
def test_a_batch_equals_its_rows_evaluated_apart(name):
    """Chunks of rows (rule degrees, weighted outputs) change nothing."""
    engine = from_fll_engine(ENGINES[name])
    rng = np.random.default_rng(1)
    X = np.column_stack([rng.uniform(v.minimum - 2, v.maximum + 2, 1300) for v in engine.inputs])
    whole = engine.evaluate(X)
    apart = np.vstack([engine.evaluate(X[k:k + 1]) for k in range(0, 1300, 97)])
    np.testing.assert_array_equal(whole[::97], apart)


def _weighted_reference(degrees, rows, groups, aggregation, coefficients, constants, inputs, weighted_sum):
    """Σ g z / Σ g group by group in NumPy, each operation as the kernel orders it: a group's
    activations folded with the S-norm, z = ((c₀ + c₁ x₁) + c₂ x₂) + …, num += g z, den += g."""
    n = inputs.shape[1]
    num, den = np.zeros(n), np.zeros(n)
    for g in range(coefficients.shape[0]):
        members = [degrees[r] for r, h in zip(rows, groups) if h == g]
        d = members[0].copy()
        for other in members[1:]:
            norms.snorm_into(aggregation, d, other, d)
        z = np.full(n, constants[g])
        for i in range(coefficients.shape[1]):
            z = z + coefficients[g, i] * inputs[i]
        num, den = num + d * z, den + d
    y = num / den
    return y * den if weighted_sum else y


@pytest.mark.parametrize("n_inputs", [0, 1, 2, 3, 4, 5])
def test_weighted_outputs_four_groups_at_a_time_give_the_bits_of_one_group_at_a_time(n_inputs):
    """Takagi–Sugeno outputs of one to four inputs take their groups four by four (sugeno_outputs.py): the
    same bits as the groups one by one, over several chunks of rows, with folded groups, NaN and
    infinite inputs, and every count of groups around the tile."""
    rng = np.random.default_rng(3)
    n = 2 * 1024 + 300
    inputs = rng.uniform(-3.0, 3.0, (n_inputs, n))
    if n_inputs:
        inputs[0, :3] = [np.nan, np.inf, -np.inf]
    for n_groups in (1, 3, 4, 5, 9):
        groups = np.concatenate([np.arange(n_groups), rng.integers(0, n_groups, 3)]).astype(np.int64)
        rows = rng.permutation(groups.size).astype(np.int64)
        degrees = rng.random((groups.size, n))
        degrees[:, 5] = 0.0  # a row where no group has a degree: 0 / 0
        coefficients, constants = rng.normal(0.0, 2.0, (n_groups, n_inputs)), rng.normal(0.0, 2.0, n_groups)
        for aggregation in (SNORMS.index("Maximum"), SNORMS.index("AlgebraicSum")):
            for weighted_sum in (False, True):
                out = np.empty(n)
                grouping = Groups(rows, groups, np.zeros(groups.size, dtype=np.bool_), np.ones((0, 0), dtype=np.bool_),
                                  False, aggregation)
                staged_kernels.weighted_affine(degrees, grouping, Affine(coefficients, constants), inputs, weighted_sum,
                                               out)
                with np.errstate(invalid="ignore"):  # inf − inf and 0 / 0, as in the kernel
                    expected = _weighted_reference(degrees, rows, groups, aggregation, coefficients, constants,
                                                   inputs, weighted_sum)
                np.testing.assert_array_equal(out, expected, err_msg=f"{n_groups} groups, {SNORMS[aggregation]}")


@pytest.mark.parametrize("conjunction", range(len(TNORMS)), ids=TNORMS)
def test_rule_degrees_give_the_bits_of_the_norms_applied_pair_by_pair(conjunction):
    """Left-deep antecedents of one to six propositions, ANDs in runs of up to five among ORs (up to
    three conjunctions a loop for the product and the minimum: norms.conjoin_into), weights, NaN and
    bounds among the degrees, over several chunks of rows: the bits of each operator applied in
    turn with tnorm_into / snorm_into."""
    rng = np.random.default_rng(6)
    n = 2 * staged_kernels.CHUNK + 77
    table = rng.random((6, n))
    table[:, :40] = rng.choice([np.nan, 0.0, 1.0, 0.5], (6, 40))
    operators = [[], [AND], [AND, AND], [AND, AND, AND], [AND, AND, AND, AND, AND], [AND, OR, AND, AND],
                 [OR, AND, AND, AND, OR], [AND, AND, OR, AND, AND]]
    program, starts, expected = [], [0], []
    for ops in operators:
        props = rng.permutation(6)[:len(ops) + 1]
        program += [int(props[0])] + [x for p, op in zip(props[1:], ops) for x in (int(p), op)]
        starts.append(len(program))
        value = table[props[0]].copy()
        for p, op in zip(props[1:], ops):
            (norms.tnorm_into if op == AND else norms.snorm_into)(conjunction if op == AND else SNORMS.index("Maximum"),
                                                                  value, table[p], value)
        expected.append(value)
    weights = np.array([1.0, 0.5, 1.0, 0.25, 1.0, 1.0, 0.75, 1.0])
    out = np.empty((len(operators), n))
    staged_kernels.rule_degrees(table, np.array(program), np.array(starts), weights, conjunction, SNORMS.index("Maximum"), out)
    for r, value in enumerate(expected):
        reference = value if weights[r] == 1.0 else weights[r] * value
        np.testing.assert_array_equal(out[r], reference, err_msg=f"rule {r}: {operators[r]}")
