"""JSON / YAML / FLL files: exact round trips and errors that name file, line or field."""

import json
import math

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import Bell, FuzzySystem, Gaussian, Linear, Ramp, Sigmoid, Triangular, Variable
from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.io import dumps, from_fll, load, loads, save, to_document
from fuzzynav.fuzzy.systems import SYSTEMS, get_system


def _odd_systems():
    x = Variable("x", (-2.0, 2.0), {"lo": Gaussian(0.7, -1.0), "mid": Bell(0.5, 2.0, 0.0), "hi": Sigmoid(3.0, 1.0)})
    z = Variable("z", (0.0, 1.0), {"a": Triangular(0.0, 1 / 3, 1.0)})
    yield FuzzySystem([x, z], [Variable("y", (-5.0, 5.0), {"f": Linear([1 / 3, -2.0], 0.1), "g": Linear([0, 1], 0)})],
                      ["IF x IS lo AND z IS a THEN y IS f", "IF x IS hi THEN y IS g WITH 0.25"], method="ts1")
    yield FuzzySystem([x], [Variable("y", (0.0, 1.0), {"u": Ramp(0.1, 0.9), "d": Sigmoid(-7.0, 0.4)})],
                      ["IF x IS lo THEN y IS u", "IF x IS mid THEN y IS d"], method="tsukamoto")
    yield FuzzySystem([x], [Variable("y", (0.0, 10.0), {"a": Triangular(0, 2, 4), "b": Gaussian(1.5, 7.0)})],
                      ["IF x IS lo THEN y IS a", "IF x IS hi THEN y IS b"], method="mamdani",
                      implication="product", aggregation="sum", resolution=333, tnorm="min")


@pytest.mark.parametrize("fmt", ["json", "yaml", "fll"])
def test_round_trip_exact(fmt, tmp_path):
    rng = np.random.default_rng(3)
    for system in [get_system(n) for n in SYSTEMS] + list(_odd_systems()):
        path = save(system, tmp_path / f"s.{fmt}")
        back = load(path)
        assert back == system
        lo = np.array([v.universe[0] for v in system.inputs])
        hi = np.array([v.universe[1] for v in system.inputs])
        X = rng.uniform(lo, hi, (200, len(lo)))
        np.testing.assert_array_equal(back.evaluate(X), system.evaluate(X))


def test_json_is_standard_and_keeps_infinite_shoulders():
    text = dumps(get_system("goal-seeking"), "json")
    doc = json.loads(text)  # standard JSON: no Infinity tokens
    assert "Infinity" not in text
    assert doc["inputs"][0]["terms"]["Z"]["params"] == ["-inf", 0.1, 3.5]
    assert doc["rules"][0] == "IF drg IS Z AND theta IS NG THEN alpha IS PM AND v IS Z"


def test_yaml_grid_rules_as_printed(tmp_path):
    doc = to_document(get_system("tracking"))
    doc["rules"] = {"grid": {"rows": "theta_er", "columns": "dtheta_er", "outputs": ["alpha"], "columns_first": False,
                             "cells": ["PG PG PG PM Z", "PG PG PM Z NM", "PG PM Z NM NG", "PM Z NM NG NG",
                                       "Z NM NG NG NG"]}}
    path = tmp_path / "t.json"
    path.write_text(json.dumps(doc))
    assert load(path) == get_system("tracking")
    doc["rules"]["grid"]["cells"][2] = "PG PM Z NM"
    path.write_text(json.dumps(doc))
    with pytest.raises(InputError, match=r"t\.json.*row Z has 4 cells"):
        load(path)
    doc["rules"]["grid"]["cells"][2] = "PG PM Z NM /"
    path.write_text(json.dumps(doc))
    with pytest.raises(InputError, match=r"cell \(theta_er=Z, dtheta_er=PG\)"):
        load(path)


def test_errors_name_file_and_field(tmp_path):
    doc = to_document(get_system("goal-seeking"))
    doc["rules"][3] = "IF drg IS Z AND theta IS XX THEN alpha IS PM AND v IS Z"
    path = tmp_path / "bad.yaml"
    path.write_text(dumps(get_system("goal-seeking"), "yaml").replace("theta IS PP THEN alpha IS Z AND v IS Z",
                                                                      "theta IS QQ THEN alpha IS Z AND v IS Z"))
    with pytest.raises(InputError, match=r"bad\.yaml: rules\[20\].*unknown term 'QQ' of 'theta'"):
        load(path)
    with pytest.raises(InputError, match=r"x\.json: rules\[3\].*unknown term 'XX'"):
        loads(json.dumps(doc), "json", source="x.json")
    doc = to_document(get_system("goal-seeking"))
    doc["inputs"][0]["terms"]["Z"]["params"] = [40.0, 41.0, 42.0]
    with pytest.raises(InputError, match=r"inputs\[0\].*drg\.Z.*outside the universe"):
        loads(json.dumps(doc), "json", source="x.json")
    doc["inputs"][0]["terms"]["Z"] = {"kind": "triangle", "params": [3, 2, 1]}
    with pytest.raises(InputError, match=r"inputs\[0\]\.terms\.Z: triangle needs|trapezoid needs"):
        loads(json.dumps(doc), "json", source="x.json")
    with pytest.raises(InputError, match=r"x\.json: line 2, column"):
        loads('{\n  "inputs": [,]\n}', "json", source="x.json")
    with pytest.raises(InputError, match=r"x\.yaml: line \d+, column \d+: invalid YAML"):
        loads("inputs:\n  - [\n", "yaml", source="x.yaml")
    with pytest.raises(InputError, match="unknown fuzzy-system file type"):
        load(tmp_path / "s.txt")


def test_fll_errors_name_the_line():
    text = dumps(get_system("tracking"), "fll")
    lines = text.splitlines()
    rule_line = next(i for i, line in enumerate(lines) if line.strip().startswith("rule:")) + 1
    bad = text.replace("then alpha is PG", "then alpha is HUGE", 1)
    with pytest.raises(InputError, match=rf"t\.fll: line {rule_line}: expected a term of 'alpha'.*got 'HUGE'"):
        from_fll(bad, source="t.fll")
    with pytest.raises(InputError, match=r"line \d+: term NG: unknown term type 'Blob'"):
        from_fll(text.replace("NG Constant", "NG Blob", 1), source="t.fll")
    with pytest.raises(InputError, match="rule uses 'or' but the block has no disjunction"):
        from_fll(text.replace(" and dtheta_er", " or dtheta_er", 1), source="t.fll")


def test_fll_import_fuzzylite_style():
    # written the way fuzzylite's own exporter writes (3 decimals, lock-range false, TS weighted average)
    text = """Engine: SimpleDimmer
InputVariable: Ambient
  enabled: true
  range: 0.000 1.000
  lock-range: false
  term: DARK Triangle 0.000 0.250 0.500
  term: MEDIUM Triangle 0.250 0.500 0.750
  term: BRIGHT Triangle 0.500 0.750 1.000
OutputVariable: Power
  enabled: true
  range: 0.000 1.000
  lock-range: false
  aggregation: none
  defuzzifier: WeightedAverage TakagiSugeno
  default: nan
  lock-previous: false
  term: LOW Constant 0.250
  term: MEDIUM Constant 0.500
  term: HIGH Constant 0.750
RuleBlock:
  enabled: true
  conjunction: none
  disjunction: none
  implication: none
  activation: General
  rule: if Ambient is DARK then Power is HIGH
  rule: if Ambient is MEDIUM then Power is MEDIUM
  rule: if Ambient is BRIGHT then Power is LOW
"""
    fs = from_fll(text, source="dimmer.fll")
    assert isinstance(fs, Engine)  # lock-range false: fuzzylite's meaning, not a clamping FuzzySystem
    # 0.3: DARK 0.8, MEDIUM 0.2 -> (0.8·0.75 + 0.2·0.5) / 1.0
    assert fs.evaluate_one(0.3) == pytest.approx((0.7,))
    assert math.isnan(fs.evaluate_one(0.1)[0]) is False
    # outside the range nothing fires (no clamping): NaN, as in fuzzylite; locked, the border's value
    assert math.isnan(fs.evaluate_one(1.5)[0])
    locked = from_fll(text.replace("lock-range: false", "lock-range: true", 1), source="dimmer.fll")
    assert locked.method == "ts0" and locked.evaluate_one(1.5) == locked.evaluate_one(1.0)
