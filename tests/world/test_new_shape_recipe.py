"""CONTRIBUTING.md's recipe for an obstacle type holds: one registered class (tests/world/rectangle_shape.py,
written outside the package) is all that scenario parsing, the world's collisions and rays, the
simulator, the generator's shape draws and the plots need."""

import importlib
import json
import sys

import numpy as np
import pytest
import yaml
from matplotlib.figure import Figure

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.viz.trajectories import draw_world
from fuzzynav.world.scenario import scenario_from_dict
from fuzzynav.world.shapes import SHAPES

MODULE = "tests.world.rectangle_shape"
SCENARIO = {"robot": {"x": 2.0, "y": 5.0, "theta": 0.0}, "goal": {"x": 18.0, "y": 5.0},
            "obstacles": [{"circle": {"center": [10, 15], "radius": 1.0}},
                          {"rectangle": {"center": [6.0, 5.0], "size": [2.0, 4.0]}}]}
CORNERS = [[5, 3], [7, 3], [7, 7], [5, 7]]


@pytest.fixture
def rectangle():
    """The recipe's module imported afresh (its ``@register`` runs); the registry restored after."""
    sys.modules.pop(MODULE, None)
    yield importlib.import_module(MODULE).Rectangle
    del SHAPES["rectangle"]
    sys.modules.pop(MODULE, None)


def test_a_scenario_with_the_new_type_parses_and_round_trips(rectangle):
    scenario = scenario_from_dict(SCENARIO)
    shape = scenario.world.obstacles[1]
    assert isinstance(shape, rectangle) and shape.kind == "rectangle" and shape.angle == 0.0  # default filled in
    np.testing.assert_allclose(shape.packed(), CORNERS)
    np.testing.assert_allclose(np.concatenate(shape.bounds()), [5, 3, 7, 7])
    # round trip of a turned one: every parameter, the angle too, comes back (not only what to_dict writes)
    turned = {**SCENARIO, "obstacles": [{"rectangle": {"center": [6.0, 5.0], "size": [2.0, 4.0], "angle": 0.5}}]}
    again = scenario_from_dict(scenario_from_dict(turned).to_dict()).world.obstacles[0]
    assert isinstance(again, rectangle) and again.angle == 0.5 and again.size.tolist() == [2.0, 4.0]
    assert again.center.tolist() == [6.0, 5.0]
    half = np.array([[-1, -2], [1, -2], [1, 2], [-1, 2]])  # the corners turned by 0.5 rad about the centre
    np.testing.assert_allclose(again.packed(), [6, 5] + half @ [[np.cos(0.5), np.sin(0.5)], [-np.sin(0.5), np.cos(0.5)]])


def test_bad_parameters_of_the_new_type_name_the_file_and_field(rectangle):
    bad = {**SCENARIO, "obstacles": [{"rectangle": {"center": [6.0, 5.0], "size": [-2.0, 4.0]}}]}
    with pytest.raises(InputError) as error:
        scenario_from_dict(bad, source="mine.yaml")
    assert (error.value.source, error.value.field) == ("mine.yaml", "obstacles[0].rectangle.size[0]")
    typo = {**SCENARIO, "obstacles": [{"rectangle": {"centre": [6.0, 5.0], "size": [2.0, 4.0]}}]}
    with pytest.raises(InputError, match="did you mean 'center'"):
        scenario_from_dict(typo, source="mine.yaml")
    with pytest.raises(InputError, match="obstacles\\[0\\].rectangle.size: missing"):
        scenario_from_dict({**SCENARIO, "obstacles": [{"rectangle": {"center": [6.0, 5.0]}}]}, source="mine.yaml")


def test_the_new_type_is_sensed_by_the_rays_and_collides(rectangle):
    world = scenario_from_dict(SCENARIO).world
    ahead = world.ranges(np.array([[2.0, 5.0, 0.0]]), np.array([0.0, np.pi / 2]), 4.0)
    np.testing.assert_allclose(ahead, [[3.0, 4.0]])  # the face at x = 5; nothing above within range
    turned = scenario_from_dict({**SCENARIO, "obstacles": [
        {"rectangle": {"center": [6.0, 5.0], "size": [2.0, 4.0], "angle": float(np.pi / 2)}}]}).world
    np.testing.assert_allclose(turned.ranges(np.array([[2.0, 5.0, 0.0]]), np.array([0.0]), 4.0), [[2.0]])
    distance, point, index = world.nearest_obstacle(np.array([[4.5, 5.0], [6.0, 5.5]]))
    np.testing.assert_allclose(distance, [0.5, -1.0])  # signed: inside the rectangle, 1 m from its sides
    assert index.tolist() == [1, 1]
    assert world.collides(np.array([[4.8, 5.0], [4.6, 5.0]]), radius=0.3).tolist() == [True, False]


def test_the_simulator_runs_the_new_type(rectangle, tmp_path, capsys):
    file = tmp_path / "rectangle.yaml"
    file.write_text(yaml.safe_dump({**SCENARIO, "max_time": 60}))
    assert main(["run", str(file), "--controller", "fuzzy-2b", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["outcome"] == "reached" and result["min_clearance_m"] > 0.0  # it went round the rectangle


def test_the_new_type_draws_and_generates(rectangle):
    ax = Figure().add_subplot()
    draw_world(ax, scenario_from_dict(SCENARIO))
    boundary, circle, drawn_rectangle = ax.patches[:3]  # then the goal
    np.testing.assert_allclose(drawn_rectangle.get_xy()[:4], CORNERS)
    rng = np.random.default_rng(0)
    drawn = [rectangle.random(rng) for _ in range(5)]
    world = scenario_from_dict({**SCENARIO, "robot": {"x": 0.5, "y": 0.5}, "goal": {"x": 19.5, "y": 19.5},
                                "obstacles": drawn}).world
    assert [shape.kind for shape in world.obstacles] == ["rectangle"] * 5
