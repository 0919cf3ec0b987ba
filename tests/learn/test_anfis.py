"""ANFIS (thesis §V.3.4, Table V.2): recovery of known TS systems, accuracy, stability, round trips."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from sklearn.base import clone

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import Bell, FuzzySystem, Linear, Rule, Variable
from fuzzynav.fuzzy.io import files
from fuzzynav.learn import anfis_mf
from fuzzynav.learn.anfis import ANFIS
from fuzzynav.learn.anfis_hybrid import Grid, StepRule


def tracker_target(theta):
    """The benchmark target of benchmarks/anfis_bench.py: α = (π/4)·tanh(1.5·θ_er)."""
    return math.pi / 4 * np.tanh(1.5 * theta)


@pytest.fixture(scope="module")
def known_ts1():
    """A first-order TS system (2 inputs × (2, 3) bell MFs, off the grid partition), built and
    evaluated by the fuzzy library — an implementation independent of the ANFIS code."""
    rng = np.random.default_rng(0)
    p1 = anfis_mf.grid_premises("bell", -1.0, 1.0, 2) * [1.15, 1.1, 1.0] + [0.0, 0.0, 0.08]
    p2 = anfis_mf.grid_premises("bell", 0.0, 2.0, 3) * [0.9, 1.0, 1.0] + [0.0, 0.0, -0.05]
    theta = rng.normal(size=(6, 3))
    inputs = [Variable("x1", (-1, 1), {f"m{j}": Bell(*r) for j, r in enumerate(p1)}),
              Variable("x2", (0, 2), {f"m{j}": Bell(*r) for j, r in enumerate(p2)})]
    output = Variable("y", (-10, 10), {f"r{k}": Linear(t[:2], t[2]) for k, t in enumerate(theta)})
    rules = [Rule((("x1", f"m{i}"), ("x2", f"m{j}")), (("y", f"r{3 * i + j}"),)) for i in range(2) for j in range(3)]
    system = FuzzySystem(inputs, [output], rules, method="ts1", defuzzifier="weighted_average")
    X = np.column_stack([rng.uniform(-1, 1, 400), rng.uniform(0, 2, 400)])
    X[:2] = [[-1.0, 0.0], [1.0, 2.0]]  # the corners fix the training range = the true universes
    return system, [p1, p2], theta, X, system.evaluate(X)[:, 0]


def test_recovers_consequents_exactly_when_premises_are_given(known_ts1):
    system, premises, theta, X, y = known_ts1
    model = ANFIS(premises=premises, learn_premises=False).fit(X, y)
    assert model.n_epochs_ == 1  # one forward pass: least squares only
    np.testing.assert_allclose(model.consequents_, theta, atol=1e-10)
    fresh = np.column_stack([np.linspace(-1, 1, 50), np.linspace(2, 0, 50)])
    np.testing.assert_allclose(model.predict(fresh), system.evaluate(fresh)[:, 0], atol=1e-10)


def test_hybrid_learning_recovers_outputs_from_the_grid_partition(known_ts1):
    system, _, _, X, y = known_ts1
    model = ANFIS(n_mfs=[2, 3], epochs=200).fit(X, y)
    history = model.history_["train_rmse"]
    best = history[model.best_epoch_]
    assert best <= 1e-3 * y.std()
    assert best <= history[0] / 20  # the premise (backward) pass is what gets it there
    fresh = np.random.default_rng(5).uniform([-1, 0], [1, 2], (500, 2))
    error = model.predict(fresh) - system.evaluate(fresh)[:, 0]
    assert np.sqrt(np.mean(error**2)) <= 2e-3 * y.std()


def test_order_zero_recovers_singleton_consequents():
    premises = [anfis_mf.grid_premises("gaussian", 0.0, 1.0, 4)]
    values = np.array([0.5, -1.0, 2.0, 0.25])
    truth = ANFIS.from_dict({**_document(premises, values[:, None], order=0, mf="gaussian")})
    X = np.linspace(0, 1, 60)[:, None]
    model = ANFIS(mf="gaussian", order=0, premises=premises, learn_premises=False).fit(X, truth.predict(X))
    np.testing.assert_allclose(model.consequents_[:, 0], values, atol=1e-10)


def test_fits_the_tracker_target_to_1e_4_rad():
    X = np.linspace(-math.pi, math.pi, 100)[:, None]
    model = ANFIS(n_mfs=5, mf="bell", epochs=200).fit(X, tracker_target(X[:, 0]))
    test = np.random.default_rng(1).uniform(-math.pi, math.pi, (1000, 1))
    rmse = np.sqrt(np.mean((model.predict(test) - tracker_target(test[:, 0])) ** 2))
    assert rmse <= 1e-4
    assert model.score(test, tracker_target(test[:, 0])) > 0.999999


@pytest.mark.parametrize("mf, step_size, clean_rmse", [
    ("bell", 0.05, 0.03), ("gaussian", 0.05, 0.03), ("bell", 1.0, 0.1), ("gaussian", 1.0, 0.1)])
def test_noisy_data_does_not_diverge(mf, step_size, clean_rmse):
    """Noise σ = 0.05 rad; a step 20× the default still ends finite, with the best validation epoch kept."""
    rng = np.random.default_rng(3)
    X = rng.uniform(-math.pi, math.pi, (300, 1))
    y = tracker_target(X[:, 0]) + rng.normal(0.0, 0.05, 300)
    model = ANFIS(n_mfs=7, mf=mf, epochs=150, step_size=step_size, validation_fraction=0.25,
                  n_iter_no_change=20, random_state=0).fit(X, y)
    history = model.history_
    assert len(history["validation_rmse"]) == len(history["train_rmse"]) == model.n_epochs_
    assert np.isfinite(history["train_rmse"]).all() and np.isfinite(history["validation_rmse"]).all()
    assert all(np.isfinite(p).all() for p in model.premises_)
    best_val = history["validation_rmse"][model.best_epoch_]
    assert best_val == min(history["validation_rmse"])  # best-epoch checkpoint on the validation split
    assert model.n_epochs_ - 1 - model.best_epoch_ <= 20  # early stopping, or the epoch budget
    clean = np.linspace(-math.pi, math.pi, 500)[:, None]
    assert np.sqrt(np.mean((model.predict(clean) - tracker_target(clean[:, 0])) ** 2)) < clean_rmse


def test_validation_split_is_seeded():
    rng = np.random.default_rng(4)
    X = rng.uniform(-1, 1, (80, 1))
    y = np.sin(3 * X[:, 0]) + rng.normal(0, 0.1, 80)
    runs = [ANFIS(n_mfs=4, epochs=30, validation_fraction=0.3, random_state=seed).fit(X, y) for seed in (7, 7, 8)]
    assert runs[0].history_ == runs[1].history_
    assert runs[0].history_["validation_rmse"] != runs[2].history_["validation_rmse"]


@pytest.mark.parametrize("mf", ["bell", "gaussian"])
def test_premise_gradient_matches_finite_differences(mf):
    """Backward pass of Table V.2 against central differences of E = ½ Σ e² (consequents fixed)."""
    rng = np.random.default_rng(2)
    X = rng.uniform(-1, 1, (40, 2))
    y = rng.normal(size=40)
    rules = np.array([[i, j] for i in range(2) for j in range(3)])
    grid = Grid(mf, [2, 3], rules, order=1)
    params = np.concatenate([anfis_mf.grid_premises(mf, -1, 1, 2), anfis_mf.grid_premises(mf, -1, 1, 3)])
    params = params * (1 + 0.1 * rng.uniform(-1, 1, params.shape))
    theta = rng.normal(size=(6, 3))

    def energy(p):
        e = grid.predict(X, p, theta) - y
        return 0.5 * float(e @ e)

    fwd = grid.forward(X, params, True)
    f, out = grid.outputs(fwd, theta)
    analytic = grid.premise_gradient(fwd, f, out, out - y)
    numeric = np.zeros_like(params)
    for index in np.ndindex(params.shape):
        h = 1e-6 * max(1.0, abs(params[index]))
        up, down = params.copy(), params.copy()
        up[index] += h
        down[index] -= h
        numeric[index] = (energy(up) - energy(down)) / (2 * h)
    np.testing.assert_allclose(analytic, numeric, rtol=1e-5, atol=1e-7)


def test_step_size_rules_of_jang():
    rule = StepRule(1.1, 0.9)
    k = 1.0
    for error in [5, 4, 3, 2]:  # first error has no predecessor: 3 decreases so far
        k = rule.update(error, k)
    assert k == 1.0
    k = rule.update(1, k)  # 4th consecutive decrease
    assert k == pytest.approx(1.1)
    for error in [2, 1, 2, 1]:  # up, down, up, down: two oscillations
        k = rule.update(error, k)
    assert k == pytest.approx(1.1 * 0.9)


def test_predict_one_matches_predict_for_every_layout():
    rng = np.random.default_rng(6)
    X = rng.uniform(-2, 2, (120, 2))
    y = np.sin(X[:, 0]) * X[:, 1]
    cases = [ANFIS(n_mfs=5, epochs=20).fit(X[:, :1], y), ANFIS(n_mfs=4, mf="gaussian", order=0, epochs=20).fit(X[:, :1], y),
             ANFIS(n_mfs=[3, 2], epochs=20).fit(X, y), ANFIS(n_mfs=[2, 3], mf="gaussian", epochs=20).fit(X, y)]
    probe = rng.uniform(-3, 3, (25, 2))
    for model in cases:
        n = model.n_features_in_
        batch = model.predict(probe[:, :n])
        one = [model.predict_one(row[0] if n == 1 else row) for row in probe[:, :n]]
        np.testing.assert_allclose(one, batch, rtol=1e-12, atol=1e-12)
    far = cases[0].predict_one(1e200)  # a bell power overflows a float: falls back to the batch path
    assert far == pytest.approx(cases[0].predict([[1e200]])[0])


def test_json_round_trip_is_exact_and_keeps_hyper_parameters():
    X = np.linspace(-math.pi, math.pi, 60)[:, None]
    model = ANFIS(n_mfs=5, epochs=40, validation_fraction=0.2, random_state=1).fit(X, tracker_target(X[:, 0]))
    text = json.dumps(model.to_dict())
    again = ANFIS.from_dict(json.loads(text))
    probe = np.linspace(-4, 4, 33)[:, None]
    assert np.array_equal(again.predict(probe), model.predict(probe))
    assert again.predict_one(0.3) == model.predict_one(0.3)
    assert again.get_params() == model.get_params()
    assert again.history_ == model.history_ and again.best_epoch_ == model.best_epoch_
    assert json.dumps(again.to_dict()) == text


def test_export_to_the_fuzzy_library(tmp_path):
    X = np.linspace(-math.pi, math.pi, 100)[:, None]
    model = ANFIS(n_mfs=5, epochs=30).fit(X, tracker_target(X[:, 0]))
    system = model.to_fuzzy_system(["theta_er"], "alpha", name="anfis-tracker")
    assert system.method == "ts1" and system.input_names == ["theta_er"] and len(system.rules) == 5
    probe = np.random.default_rng(0).uniform(-math.pi, math.pi, (200, 1))
    np.testing.assert_allclose(system.evaluate(probe)[:, 0], model.predict(probe), atol=1e-12)
    path = files.save(system, tmp_path / "anfis.json")
    np.testing.assert_allclose(files.load(path).evaluate(probe)[:, 0], model.predict(probe), atol=1e-12)
    # order 0 exports as TS0 with singleton conclusions; two inputs, Gaussian premises
    X2 = np.random.default_rng(1).uniform(-1, 1, (150, 2))
    zero = ANFIS(n_mfs=[2, 3], mf="gaussian", order=0, epochs=20).fit(X2, X2[:, 0] * X2[:, 1])
    exported = zero.to_fuzzy_system()
    assert exported.method == "ts0" and len(exported.rules) == 6
    np.testing.assert_allclose(exported.evaluate(X2)[:, 0], zero.predict(X2), atol=1e-12)


def test_is_a_scikit_learn_estimator():
    model = ANFIS(n_mfs=[2, 2], mf="gaussian", epochs=5)
    assert not hasattr(model, "premises_")  # no work in the constructor
    twin = clone(model)
    assert twin.get_params() == model.get_params()
    with pytest.raises(Exception, match="not fitted"):
        model.predict([[0.0, 0.0]])


@pytest.mark.parametrize("params, field", [
    ({"mf": "triangle"}, "mf"), ({"order": 2}, "order"), ({"n_mfs": 0}, "n_mfs"), ({"n_mfs": [2, 2, 2]}, "n_mfs"),
    ({"epochs": 0}, "epochs"), ({"step_decrease": 1.5}, "step_decrease"), ({"validation_fraction": 1.0},
                                                                           "validation_fraction"),
    ({"premises": [[[1.0, 2.0]]]}, "premises[0]"),
])
def test_bad_hyper_parameters_name_the_field(params, field):
    X = np.zeros((10, 1)) + np.arange(10)[:, None]
    with pytest.raises(InputError) as info:
        ANFIS(**params).fit(X, np.arange(10.0))
    assert info.value.field == field


def test_bad_data_and_documents_name_the_field():
    with pytest.raises(InputError, match="NaN") as info:
        ANFIS().fit([[0.0], [np.nan], [1.0]], [0.0, 1.0, 2.0])
    assert info.value.field == "X"
    with pytest.raises(InputError) as info:
        ANFIS().fit([[0.0], [1.0]], [0.0, 1.0, 2.0])
    assert info.value.field == "y"
    model = ANFIS(n_mfs=3, epochs=3).fit(np.linspace(0, 1, 20)[:, None], np.linspace(0, 1, 20))
    with pytest.raises(InputError) as info:
        model.predict(np.zeros((3, 2)))
    assert info.value.field == "X"
    document = model.to_dict()
    document["consequents"] = document["consequents"][:-1]
    with pytest.raises(InputError) as info:
        ANFIS.from_dict(document, source="model.json")
    assert info.value.field == "consequents" and "model.json" in str(info.value)
    with pytest.raises(InputError) as info:
        ANFIS.from_dict({**model.to_dict(), "params": {**model.to_dict()["params"], "mf": "cone"}})
    assert info.value.field == "params.mf"


@pytest.mark.parametrize("key, value, field, problem", [
    ("best_epoch", "abc", "best_epoch", "must be an integer"), ("best_epoch", [1], "best_epoch", "must be an integer"),
    ("n_features_in", 2.5, "n_features_in", "must be an integer"),  # was cut to 2
    ("n_features_in", 0, "n_features_in", "must be an integer in [1, "),
])
def test_a_model_files_counts_are_integers(key, value, field, problem):
    document = ANFIS(n_mfs=2, epochs=2).fit(np.linspace(0, 1, 20)[:, None], np.linspace(0, 1, 20)).to_dict()
    with pytest.raises(InputError) as info:
        ANFIS.from_dict({**document, key: value}, source="m.json")
    assert info.value.field == field and problem in str(info.value)


def test_a_grid_of_too_many_rules_is_refused_before_it_is_built():
    """16 inputs of 5 MFs each, a 4 KB file: 5^16 rules, refused by count (it took gigabytes)."""
    document = ANFIS(n_mfs=2, epochs=2).fit(np.linspace(0, 1, 20)[:, None], np.linspace(0, 1, 20)).to_dict()
    document = {**document, "n_features_in": 16, "premises": [[[0.1, 0.1 * j - 0.2] for j in range(5)]] * 16}
    document["params"] = {**document["params"], "mf": "gaussian", "n_mfs": 5}
    with pytest.raises(InputError, match=r"make 152,587,890,625 rules, more than the 100,000"):
        ANFIS.from_dict(document, source="m.json")
    with pytest.raises(InputError, match="rules, more than") as info:
        ANFIS(n_mfs=5).fit(np.zeros((4, 8)), np.zeros(4))
    assert info.value.field == "n_mfs"


def _document(premises, consequents, *, order, mf):
    """A fitted-model document written by hand: a known system without training."""
    n = len(premises)
    lows = [float(np.min(p[:, -1])) for p in premises]
    highs = [float(np.max(p[:, -1])) for p in premises]
    return {
        "format": "fuzzynav-anfis", "version": 1,
        "params": {**ANFIS(mf=mf, order=order).get_params(), "n_mfs": [len(p) for p in premises]},
        "n_features_in": n, "premises": [p.tolist() for p in premises], "consequents": consequents.tolist(),
        "input_range": [[lo, hi] for lo, hi in zip(lows, highs)], "output_range": [-1.0, 1.0],
    }
