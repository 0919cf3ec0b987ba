"""Cross-checks against pyfuzzylite (GPL, numpy < 2: run in their own venv, ``pytest -m fll tests/fll``).

1. FLL export: our systems written as FLL, loaded by pyfuzzylite, evaluated by its vectorised
   engine on >= 1000 random inputs (some outside the ranges: lock-range clamps them as we do),
   max |diff| <= 1e-9.
2. FLL import: files in fuzzylite's own style (its exporter, its bundled examples) read by us and
   evaluated by both engines, on their ``.fld`` rows and on random inputs of which 20 % lie outside
   the ranges (lock-range as written).
3. The engines of ``tests/fuzzy/fll_fixtures.py`` (written for these tests: every term, hedge,
   norm, activation and defuzzifier, per-output settings, several blocks, chained variables).
"""

from pathlib import Path

import numpy as np
import pytest

from fuzzynav.fuzzy import FuzzySystem, Gaussian, Ramp, Triangular, Variable, strong_partition
from fuzzynav.fuzzy.io import from_fll, to_fll
from fuzzynav.fuzzy.systems import SYSTEMS, get_system
from tests.fuzzy.fll_fixtures import ENGINES, ROWWISE
from tests.fuzzy.numpy_path import assert_fused_matches_numpy_path

pytestmark = pytest.mark.fll
fl = pytest.importorskip("fuzzylite")

EXAMPLES = Path(fl.__file__).parent / "examples"
# a representative subset of the examples pyfuzzylite ships (read from the installed package, never copied)
SUPPORTED_EXAMPLES = [
    "mamdani/simple_dimmer.fll", "mamdani/simple_dimmer_chained.fll", "mamdani/laundry.fll", "mamdani/all_terms.fll",
    "mamdani/matlab/tank.fll", "mamdani/matlab/mam21.fll", "mamdani/octave/investment_portfolio.fll",
    "takagi_sugeno/simple_dimmer.fll", "takagi_sugeno/approximation.fll", "takagi_sugeno/matlab/fpeaks.fll",
    "takagi_sugeno/matlab/membrn1.fll", "takagi_sugeno/matlab/juggler.fll", "takagi_sugeno/octave/linear_tip_calculator.fll",
    "hybrid/tipper.fll", "hybrid/obstacle_avoidance.fll", "tsukamoto/tsukamoto.fll",
    "terms/bell.fll", "terms/concave.fll", "terms/cosine.fll", "terms/discrete.fll", "terms/function.fll",
    "terms/pi_shape.fll", "terms/spike.fll", "terms/zs_shape.fll", "terms/arc.fll", "terms/binary.fll",
    "terms/semi_ellipse.fll", "terms/sigmoid_difference.fll", "terms/linear.fll",
]


def _process(engine, X: np.ndarray) -> np.ndarray:
    """pyfuzzylite's outputs; activations other than General run one row at a time there."""
    if all(type(b.activation).__name__ == "General" for b in engine.rule_blocks):
        engine.input_values = X
        engine.process()
        return np.atleast_2d(engine.output_values).reshape(len(X), -1)
    rows = []
    for row in X:
        for variable, value in zip(engine.input_variables, row):
            variable.value = float(value)
        engine.process()
        rows.append([float(np.asarray(v.value).ravel()[-1]) for v in engine.output_variables])
    return np.array(rows)


def _compare(system, engine, X: np.ndarray, atol: float) -> float:
    theirs = _process(engine, X)
    ours = system.evaluate(X)
    both_nan = (np.isnan(ours) & np.isnan(theirs)) | (ours == theirs)  # also the same infinity
    diff = np.where(both_nan, 0.0, np.abs(ours - theirs))
    assert not np.isnan(diff).any(), "NaN in one engine only"
    assert diff.max() <= atol, diff.max()
    return float(diff.max())


def _inputs(system, n, margin, seed, outside=None):
    """Uniform over the ranges widened by ``margin``; or, with ``outside``, that share of the rows
    beyond either end (up to 50 % of the range)."""
    rng = np.random.default_rng(seed)
    lo = np.array([v.universe[0] for v in system.inputs])
    hi = np.array([v.universe[1] for v in system.inputs])
    width = hi - lo
    X = rng.uniform(lo - margin * width, hi + margin * width, (n, len(lo)))
    if outside:
        beyond = rng.random((n, len(lo))) < outside
        below = rng.random((n, len(lo))) < 0.5
        step = rng.uniform(0.0, 0.5 * width, (n, len(lo)))
        X = np.where(beyond, np.where(below, lo - step, hi + step), X)
    return X


def _tolerance(system) -> float:
    spans = [v.universe[1] - v.universe[0] for v in system.outputs]
    return 1e-9 * max([s for s in spans if np.isfinite(s) and s > 0] + [1.0])


@pytest.mark.parametrize("name", list(SYSTEMS))
def test_export_thesis_systems(name):
    system = get_system(name)
    engine = fl.FllImporter().from_string(to_fll(system))
    _compare(system, engine, _inputs(system, 2000, 0.1, 1), 1e-9)


def test_export_other_methods():
    x = Variable("x", (-1.0, 1.0), strong_partition([-1.0, 0.0, 1.0], ["N", "Z", "P"]))
    g = Variable("g", (0.0, 2.0), {"lo": Gaussian(0.4, 0.5), "hi": Gaussian(0.6, 1.5)})
    # Tsukamoto: one rule per conclusion term (fuzzylite 8 sums the strengths of rules sharing a
    # term before inverting; we invert per rule, as the textbook method does)
    tsu = FuzzySystem([x], [Variable("y", (0.0, 1.0), {"u": Ramp(0.1, 0.9), "d": Ramp(0.8, 0.2), "s": Ramp(0.0, 1.0)})],
                      ["IF x IS N THEN y IS u", "IF x IS P THEN y IS d", "IF x IS Z THEN y IS s WITH 0.5"],
                      method="tsukamoto")
    mam = FuzzySystem([x, g], [Variable("y", (0.0, 10.0), {"a": Triangular(0, 2, 5), "b": Triangular(4, 7, 10)})],
                      ["IF x IS N AND g IS lo THEN y IS a", "IF x IS P THEN y IS b", "IF g IS hi THEN y IS b WITH 0.7"],
                      method="mamdani", tnorm="min", implication="min", aggregation="max", resolution=500)
    mam_ps = FuzzySystem(mam.inputs, mam.outputs, mam.rules, method="mamdani", implication="product",
                         aggregation="sum", resolution=500)
    for system in (tsu, mam, mam_ps):
        engine = fl.FllImporter().from_string(to_fll(system))
        _compare(system, engine, _inputs(system, 1000, 0.05, 2), 1e-9)


def test_fuzzylite_default_precision_shifts_alpha():
    # why export writes full precision: fuzzylite's 3-decimal exporter moves α by ~3e-4 rad
    system = get_system("goal-seeking")
    engine = fl.FllImporter().from_string(to_fll(system))
    rounded = fl.FllImporter().from_string(fl.FllExporter().to_string(engine))
    X = _inputs(system, 1000, 0.0, 3)
    rounded.input_values = X
    rounded.process()
    assert np.abs(rounded.output_values[:, 0] - system.evaluate(X)[:, 0]).max() > 1e-4
    _compare(system, engine, X, 1e-9)


def test_import_fuzzylite_exporter_style():
    # an engine built in pyfuzzylite and written by its own exporter (3 decimals)
    engine = fl.FllImporter().from_string(to_fll(get_system("tracking")))
    text = fl.FllExporter().to_string(engine)
    ours = from_fll(text, source="exported.fll")
    _compare(ours, fl.FllImporter().from_string(text), _inputs(ours, 1000, 0.1, 4), 1e-9)


@pytest.mark.parametrize("example", SUPPORTED_EXAMPLES)
def test_import_fuzzylite_examples(example):
    path = EXAMPLES / example
    text = path.read_text()
    ours = from_fll(text, source=example)
    fld = path.with_suffix(".fld")
    if fld.exists():  # the dataset's input columns, as fuzzylite's own tests replay them
        lines = fld.read_text().splitlines()
        columns = [lines[0].split().index(name) for name in ours.input_names]
        rows = np.array([[float(v) for v in line.split()] for line in lines[1:] if line.strip()])[:, columns]
        _compare(ours, fl.FllImporter().from_string(text), rows, _tolerance(ours))
    # lock-range as written: 20 % of the inputs outside the ranges
    _compare(ours, fl.FllImporter().from_string(text), _inputs(ours, 1000, 0.0, 5, outside=0.2), _tolerance(ours))


@pytest.mark.parametrize("name", list(ENGINES))
def test_feature_engines(name):
    text = ENGINES[name]
    ours = from_fll(text, source=name)
    X = _inputs(ours, 300 if name in ROWWISE else 2000, 0.0, 6, outside=0.2)
    _compare(ours, fl.FllImporter().from_string(text), X, _tolerance(ours))
    again = from_fll(to_fll(ours), source="again")  # FLL round trip: the same numbers, bit for bit
    np.testing.assert_array_equal(again.evaluate(X), ours.evaluate(X))


@pytest.mark.parametrize("example", SUPPORTED_EXAMPLES)
def test_fused_kernel_gives_the_bits_of_the_numpy_path_on_the_examples(example):
    """The fused kernel (every example it takes) against the engine's NumPy path: bit for bit, or
    within 1e-12 × the output range where Gaussian, Bell or Sigmoid terms are fuzzified in it."""
    from fuzzynav.fuzzy.engine import Engine

    ours = from_fll((EXAMPLES / example).read_text(), source=example)
    assert isinstance(ours, Engine)
    if example in ("takagi_sugeno/approximation.fll", "tsukamoto/tsukamoto.fll"):  # function / inverse conclusions
        assert "a weighted conclusion that is not constant or linear" in ours.fallback
        return
    X = _inputs(ours, 2000, 0.0, 8, outside=0.2)
    X[0] = np.nan
    assert_fused_matches_numpy_path(ours, X)
