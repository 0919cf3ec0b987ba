"""BARN worlds as scenarios: world/barn.py and ``fuzzynav import barn`` (data: tests/data/barn, MIT)."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.world.barn import barn_scenario, optimal_path_length, read_posts
from fuzzynav.world.scenario import load_scenario, scenario_from_dict

DATA = Path(__file__).resolve().parents[1] / "data" / "barn"


def test_posts_of_world_0():
    posts = read_posts(DATA / "world_0.world")
    assert len(posts) == 209  # 210 models, one of them the ground plane
    assert np.all(posts[:, 2] == 0.075)
    assert posts[:, 0].min() == pytest.approx(-4.425) and posts[:, 1].max() == pytest.approx(9.525)
    on_grid = (posts[:, :2] - 0.075) / 0.15
    assert np.allclose(on_grid, np.round(on_grid))


def test_optimal_path_of_world_0_follows_run_py():
    """run.py: cells (r, c) -> (0.15 r - 4.575, 0.15 c + 5.075), start and goal added at the ends."""
    cells = np.load(DATA / "path_0.npy")
    points = np.vstack([[-2.25, 3.0], np.column_stack([cells[:, 0] * 0.15 - 4.575, cells[:, 1] * 0.15 + 5.075]),
                        [-2.25, 13.0]])
    expected = sum(math.dist(a, b) for a, b in zip(points[:-1], points[1:]))
    assert optimal_path_length(DATA / "path_0.npy") == pytest.approx(expected)
    assert expected > 10.0


@pytest.mark.parametrize("scale", (1.0, 2.0))
def test_scenario_keeps_the_challenge_rules_at_any_scale(scale):
    document = barn_scenario(read_posts(DATA / "world_0.world"), "world_0", scale)
    scenario = scenario_from_dict(document)
    assert scenario.max_time == 100.0
    assert scenario.goal.tolerance == pytest.approx(scale)
    assert math.dist(scenario.goal.position, scenario.start[:2]) == pytest.approx(10 * scale)
    assert scenario.start[2] == pytest.approx(1.57)
    assert len(scenario.world.obstacles) == 209
    assert scenario.world.obstacles[0].radius == pytest.approx(0.075 * scale)


def test_import_cli_writes_scenarios_and_references(tmp_path):
    out = tmp_path / "barn"
    assert main(["import", "barn", str(DATA / "world_0.world"), "--out", str(out), "--scale", "1.5"]) == 0
    scenario = load_scenario(out / "world_0.yaml")
    assert len(scenario.world.obstacles) == 209
    references = json.loads((out / "benchmark.json").read_text())["scenarios"]
    assert references["world_0"]["barn_optimal_path_m"] == pytest.approx(
        1.5 * optimal_path_length(DATA / "path_0.npy"), abs=1e-6)


def test_bad_world_file_is_an_input_error(tmp_path, capsys):
    bad = tmp_path / "world_5.world"
    bad.write_text("<sdf><world><model name='box'><pose>0 0 0 0 0 0</pose><link><collision><geometry>"
                   "<box><size>1 1 1</size></box></geometry></collision></link></model></world></sdf>")
    with pytest.raises(InputError, match=r"box"):
        read_posts(bad)
    assert main(["import", "barn", str(bad), "--out", str(tmp_path / "o")]) == 2
    assert "world_5.world" in capsys.readouterr().err
    (tmp_path / "broken.world").write_text("<sdf><world>")
    assert main(["import", "barn", str(tmp_path / "broken.world"), "--out", str(tmp_path / "o")]) == 2
