"""Neural inverse model by generalized learning (thesis §V.3.2, Figs V.13–V.15), on a toy plant."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.learn.neural import (
    NeuralInverseModel,
    fit_inverse_model,
    generalized_learning_dataset,
    validate_inverse_model,
)

LIMIT = math.pi / 4


def plant(alpha):
    """A monotone steering plant: the heading change of a bicycle model over one step
    (V Δt / l) tan α with V = 1 m/s, Δt = 0.1 s, l = 0.5 m, seen as the error it leaves."""
    return -0.2 * np.tan(alpha)


@pytest.fixture(scope="module")
def model():
    errors, commands = generalized_learning_dataset(plant, n_samples=200, random_state=0)
    return fit_inverse_model(errors, commands)


def test_dataset_applies_the_commands_to_the_plant():
    errors, commands = generalized_learning_dataset(plant, n_samples=50, random_state=3)
    assert errors.shape == (50, 1) and commands.shape == (50,)
    assert np.all(np.abs(commands) <= LIMIT)
    np.testing.assert_array_equal(errors[:, 0], plant(commands))
    again, _ = generalized_learning_dataset(plant, n_samples=50, random_state=3)
    np.testing.assert_array_equal(again, errors)
    given = np.array([-0.5, 0.0, 0.5])
    observed, used = generalized_learning_dataset(lambda a: np.column_stack([a, 2 * a]), given)
    assert observed.shape == (3, 2) and np.array_equal(used, given)


def test_inverse_model_on_unseen_pairs(model):
    """Fig V.15: ~100 pairs not used in training; the network returns the command that was applied."""
    check = validate_inverse_model(model, plant, n_samples=100, random_state=1)
    assert check.errors.shape == (100, 1)
    assert check.rmse < 2e-3 and check.max_abs_error < 1e-2
    # two tanh hidden layers and one linear output neuron (Fig V.13)
    assert [W.shape for W in model.weights] == [(1, 10), (10, 10), (10, 1)]
    hidden = np.tanh(np.tanh(check.errors @ model.weights[0] + model.biases[0]) @ model.weights[1] + model.biases[1])
    np.testing.assert_allclose(check.predicted, hidden @ model.weights[2][:, 0] + model.biases[2][0], atol=1e-12)


def test_gradient_descent_solver_records_a_decreasing_loss_curve():
    errors, commands = generalized_learning_dataset(plant, n_samples=100, random_state=0)
    sgd = fit_inverse_model(errors, commands, (6, 6), solver="sgd", max_iter=300, random_state=1)
    assert len(sgd.loss_curve) == 300
    assert sgd.loss_curve[-1] < 0.1 * sgd.loss_curve[0]
    check = validate_inverse_model(sgd, plant, random_state=2)
    assert check.rmse < 0.2 * check.desired.std()  # plain back-propagation: learning, if slowly


def test_scalar_forward_pass_matches_the_batch(model):
    probe = np.linspace(-0.3, 0.3, 41)
    np.testing.assert_allclose([model.predict_one(v) for v in probe], model.predict(probe), rtol=1e-12, atol=1e-14)
    two = fit_inverse_model(np.column_stack([probe, probe**2]), np.sin(probe), (4, 3), max_iter=50)
    np.testing.assert_allclose(two.predict_one([0.1, 0.01]), two.predict([[0.1, 0.01]])[0], rtol=1e-12)
    with pytest.raises(InputError):
        two.predict_one(0.1)


def test_json_round_trip_is_exact(model):
    again = NeuralInverseModel.from_dict(json.loads(json.dumps(model.to_dict())))
    probe = np.linspace(-0.4, 0.4, 17)
    assert np.array_equal(again.predict(probe), model.predict(probe))
    assert again.predict_one(0.05) == model.predict_one(0.05)
    assert again.loss_curve == model.loss_curve


def test_bad_inputs_name_the_field(model):
    with pytest.raises(InputError) as info:
        generalized_learning_dataset(lambda a: a[:-1], n_samples=10)
    assert info.value.field == "plant"
    with pytest.raises(InputError) as info:
        generalized_learning_dataset(lambda a: np.full_like(a, np.nan), n_samples=10)
    assert info.value.field == "plant"
    with pytest.raises(InputError) as info:
        fit_inverse_model([0.0, 1.0, 2.0], [0.0, 1.0], (3, 3))
    assert info.value.field == "commands"
    with pytest.raises(InputError) as info:
        fit_inverse_model([0.0, 1.0], [0.0, 1.0], solver="trainlm")
    assert info.value.field == "solver"
    document = model.to_dict()
    document["weights"][1] = document["weights"][1][:-1]
    with pytest.raises(InputError) as info:
        NeuralInverseModel.from_dict(document, source="mlp.json")
    assert info.value.field == "weights[1]" and "mlp.json" in str(info.value)
