"""The project's YAML reader: YAML 1.2 exponent floats and duplicate keys, in scenarios and
fuzzy-system files alike (a user writes ``radius: 1e-1`` and expects a number)."""

import numpy as np
import pytest
import yaml

from fuzzynav.cli import main
from fuzzynav.fuzzy.io import dumps, load
from fuzzynav.fuzzy.systems import get_system
from fuzzynav.world.scenario import load_scenario
from fuzzynav.yaml_loader import load_yaml


@pytest.mark.parametrize("text, value", [
    ("1e3", 1000.0), ("-2E-1", -0.2), ("+1.5e2", 150.0), ("3.e1", 30.0), ("1e400", float("inf")),
])
def test_exponent_notation_is_a_float(text, value):
    assert load_yaml(f"v: {text}") == {"v": value}


@pytest.mark.parametrize("text, value", [("12", 12), ("0.5", 0.5), ("e3", "e3"), ("1e", "1e"), ("'1e3'", "1e3")])
def test_other_scalars_unchanged(text, value):
    assert load_yaml(f"v: {text}") == {"v": value}


def test_duplicate_key_is_a_yaml_error():
    with pytest.raises(yaml.YAMLError, match="duplicate key 'a'"):
        load_yaml("a: 1\na: 2\n")


def test_scenario_accepts_exponent_numbers(tmp_path):
    path = tmp_path / "s.yaml"
    path.write_text("robot: {x: 1, y: 1, theta: 0}\ngoal: {x: 18, y: 18, tolerance: 3e-1}\n"
                    "obstacles:\n  - circle: {center: [5, 5], radius: 1e0}\nmax_time: 1e2\n")
    scenario = load_scenario(path)
    assert scenario.max_time == 100.0
    assert scenario.world.obstacles[0].radius == 1.0


def test_scenario_huge_exponent_is_not_finite(tmp_path, capsys):
    path = tmp_path / "s.yaml"
    path.write_text("robot: {x: 1, y: 1, theta: 1e400}\ngoal: {x: 18, y: 18}\n")
    assert main(["run", str(path), "--controller", "goal-seeking"]) == 2
    assert "robot.theta: must be finite, got inf" in capsys.readouterr().err


def test_fis_yaml_exponent_parameter_and_duplicate_key(tmp_path):
    text = dumps(get_system("goal-seeking"), "yaml")
    path = tmp_path / "gs.yaml"
    path.write_text(text.replace("      - 0.1\n", "      - 1e-1\n", 1))
    X = np.array([[5.0, 0.3], [0.05, -1.0]])
    np.testing.assert_array_equal(load(path).evaluate(X), get_system("goal-seeking").evaluate(X))
    path.write_text(text + "tnorm: min\n")
    with pytest.raises(Exception, match="duplicate key 'tnorm'"):
        load(path)
