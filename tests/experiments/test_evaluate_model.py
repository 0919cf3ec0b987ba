"""``fuzzynav evaluate --model FILE``: a trained model over generated worlds (bench/evaluate.py)."""

import json

import pytest

from fuzzynav.bench.evaluate import evaluate
from fuzzynav.catalog.tasks import load_controller
from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.generate import generate_worlds


@pytest.fixture(scope="module")
def q_model(tmp_path_factory):
    path = tmp_path_factory.mktemp("model") / "q.json"
    assert main(["train", "q-goal", "--episodes", "50", "--seed", "0", "--out", str(path), "--quiet"]) == 0
    return path


def test_evaluate_model_json_matches_the_episodes_of_the_loaded_controller(q_model, capsys):
    capsys.readouterr()
    assert main(["evaluate", "--model", str(q_model), "--worlds", "circles", "--n", "4", "--seed", "3", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["controller"] == "q-goal" and result["model"] == str(q_model) and result["n"] == 4
    expected = [metrics(run_episode(s, load_controller(q_model), seed=3), s)
                for s in generate_worlds("circles", 4, 3)]
    keys = ("scenario", "outcome", "time_s", "path_length_m", "min_clearance_m")
    assert [{key: r[key] for key in keys} for r in result["episodes"]] == [{key: e[key] for key in keys}
                                                                           for e in expected]
    assert result["success_rate"] == sum(e["outcome"] == "reached" for e in expected) / 4
    assert result["success_rate"] + result["collision_rate"] + result["timeout_rate"] == pytest.approx(1.0)


def test_evaluate_model_table(q_model, capsys):
    assert main(["evaluate", "--model", str(q_model), "--worlds", "circles", "--n", "2"]) == 0
    out = capsys.readouterr().out
    assert f"controller q-goal (model {q_model})" in out and "success_rate" in out


def test_evaluate_model_and_controller_are_mutually_exclusive(q_model):
    with pytest.raises(SystemExit) as exit_info:
        main(["evaluate", "--model", str(q_model), "--controller", "fuzzy-2b", "--worlds", "circles", "--n", "1"])
    assert exit_info.value.code == 2


def test_evaluate_without_a_controller_runs_the_default_navigator(capsys):
    assert main(["evaluate", "--worlds", "circles", "--n", "1"]) == 0
    assert "controller fuzzy-5b on 1 circles world (seed 0" in capsys.readouterr().out


def test_evaluate_missing_model_file_is_an_input_error(tmp_path, capsys):
    assert main(["evaluate", "--model", str(tmp_path / "missing.json"), "--worlds", "circles", "--n", "1"]) == 2
    assert "missing.json" in capsys.readouterr().err


def test_evaluate_needs_exactly_one_source(q_model):
    for controller, model in (("fuzzy-2b", q_model), (None, None)):  # both, or neither
        with pytest.raises(InputError, match="give exactly one of a controller name and a model file") as error:
            evaluate(controller, "circles", 1, model=model)
        assert error.value.field == "controller"
