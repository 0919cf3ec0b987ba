"""Neural and ANFIS trackers: generalized learning data, training, model files, CLI."""

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from fuzzynav.catalog.tasks import load_controller
from fuzzynav.errors import InputError
from fuzzynav.learn.tasks import trackers as tt
from fuzzynav.learn.tasks.common import TrainRequest
from fuzzynav.storage import read_document as read_model


def test_generalized_learning_pairs_invert_the_tricycle():
    data = tt.tracker_data(seed=3, n_train=50, n_val=20)
    # one Euler step: Δθ = V tan(α) Δt / l, θ_er = −Δθ  ->  α = −atan(l θ_er / (V Δt))
    np.testing.assert_allclose(data.y_train, -np.arctan(0.5 * data.x_train[:, 0] / 0.1), atol=1e-12)
    lo, hi = data.input_range
    assert -0.2 <= lo < -0.15 and 0.15 < hi <= 0.2


@pytest.mark.parametrize("kind", ["neural-tracker", "anfis-tracker"])
def test_default_models_fit_unseen_pairs(kind):
    document = tt.default_document(kind)
    assert document["training"]["validation_rmse_rad"] < (2e-3 if kind == "neural-tracker" else 2e-4)


@pytest.mark.parametrize("kind", ["neural-tracker", "anfis-tracker"])
def test_train_writes_a_model_that_loads_and_clamps(kind, tmp_path):
    out = tmp_path / f"{kind}.json"
    train = tt.train_neural_tracker if kind == "neural-tracker" else tt.train_anfis_tracker
    result = train(TrainRequest(out=out, seed=1, episodes=40, progress=False, curve=tmp_path / "curve.png"))
    assert result["model"] == str(out) and (tmp_path / "curve.png").stat().st_size > 0
    assert read_model(out)["kind"] == kind
    tracker = load_controller(out)
    assert tracker.name == kind
    lo, hi = tracker.input_range
    big = tracker.steering(np.array([2.0, -2.0, hi, lo]), np.zeros(4))
    np.testing.assert_allclose(big[:2], big[2:])  # clamped to the training range: saturates
    assert big[0] < -0.7 and big[1] > 0.7 and np.abs(big).max() <= math.pi / 4


def test_bad_model_document_raises_input_error(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"kind": "anfis-tracker", "model": {}, "input_range": [1, 0]}))
    with pytest.raises(InputError, match="input_range"):
        load_controller(bad)


@pytest.mark.slow
def test_cli_train_then_run_with_the_model(tmp_path):
    out = tmp_path / "m.json"
    cli = [sys.executable, "-m", "fuzzynav"]
    subprocess.run([*cli, "train", "anfis-tracker", "--out", str(out), "--quiet"], check=True, capture_output=True)
    run = subprocess.run([*cli, "run", "path-trapezoid", "--model", str(out), "--json"], check=True,
                         capture_output=True, text=True)
    numbers = json.loads(run.stdout)
    assert numbers["completed"] and numbers["max_cross_track_m"] < 0.5
    assert {"mean_cross_track_m", "max_cross_track_m"} <= numbers.keys()
    run = subprocess.run([*cli, "run", "fig-V-30", "--controller", "neural-tracker", "--json"], check=True,
                         capture_output=True, text=True)
    numbers = json.loads(run.stdout)
    assert numbers["captured"] and numbers["capture_time_s"] is not None


def _run_json(capsys, *argv) -> dict:
    from fuzzynav.cli import main

    assert main(["run", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_cli_run_prints_the_path_metrics_of_the_n_path(capsys):
    numbers = _run_json(capsys, "path-n", "--controller", "anfis-tracker")
    assert numbers["completed"] is True
    assert 0 < numbers["mean_cross_track_m"] < numbers["max_cross_track_m"] < 0.2


@pytest.mark.slow
@pytest.mark.parametrize("scenario", ["fig-V-29", "fig-V-30", "fig-V-31", "fig-V-32", "fig-V-33a", "fig-V-33b",
                                      "fig-V-34a", "fig-V-34b"])
def test_cli_run_prints_capture_for_every_tracker_on_the_target_scenarios(capsys, scenario):
    for name in ("fuzzy-tracker", "neural-tracker", "anfis-tracker", "pure-pursuit", "stanley"):
        numbers = _run_json(capsys, scenario, "--controller", name)
        assert numbers["captured"] is True, name
        assert 0 < numbers["capture_time_s"] <= numbers["time_s"] + 1e-9, name
