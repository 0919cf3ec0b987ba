"""The main job: runs the built-in scenarios' controllers and writes plots and metrics."""

import json

import pytest

from fuzzynav.cli import main
from fuzzynav.cli.demo import demo_runs
from fuzzynav.errors import InputError
from fuzzynav.world.scenario import scenario_from_dict


def test_demo_runs_a_scenario_and_writes_plot_and_tables(tmp_path, capsys, monkeypatch):
    runs = demo_runs()
    assert runs, "the built-in scenarios name no controllers"
    name, controller = runs[0]
    assert main(["demo", "--out", str(tmp_path), "--scenario", name]) == 0
    rows = json.loads((tmp_path / "metrics.json").read_text())
    assert {row["scenario"] for row in rows} == {name}
    assert controller in {row["controller"] for row in rows}
    assert (tmp_path / f"{name}--{controller}.png").stat().st_size > 1000
    table = (tmp_path / "metrics.md").read_text()
    assert table.startswith("| scenario | controller |") and name in table
    assert f"{name} / {controller}" in capsys.readouterr().out


def test_scenario_controllers_key_is_validated():
    doc = {"robot": {"x": 1, "y": 1}, "goal": {"x": 5, "y": 5}, "controllers": "goal-seeking"}
    with pytest.raises(InputError, match="controllers"):
        scenario_from_dict(doc, source="s.yaml")
    doc["controllers"] = ["goal-seeking"]
    assert scenario_from_dict(doc, source="s.yaml").controllers == ("goal-seeking",)
