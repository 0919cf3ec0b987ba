"""The office, maze and forest families of world/generate.py: seeded, solvable, valid scenario
files, each family what its module says, and the default navigator reaching a goal in each."""

import numpy as np
import pytest

from fuzzynav.bench.suites import parse_suite
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import main
from fuzzynav.sim import run_episode
from fuzzynav.world import forest, maze, office
from fuzzynav.world.generate import POINT_CLEARANCE, TURNING_MARGIN, connected, generate_world, generate_worlds
from fuzzynav.world.scenario import load_scenario, scenario_from_dict
from fuzzynav.world.shapes import Circle, Wall
from tests.world.same_world import assert_same_goal_scenario

FAMILIES = ("office", "maze", "forest")
MARGINS = {"office": office.MARGIN, "maze": TURNING_MARGIN, "forest": forest.MARGIN}
ROBOT = 0.3  # m, the default footprint's radius


@pytest.mark.parametrize("kind", FAMILIES)
def test_worlds_are_reproducible_per_seed_and_differ_between_seeds(kind):
    worlds = generate_worlds(kind, 4, 5)
    for i, scenario in enumerate(worlds):
        assert generate_world(kind, 5, i).to_dict() == scenario.to_dict()
        assert scenario.name == f"{kind}-5-{i:03d}"
    other = generate_worlds(kind, 4, 6)
    assert all(a.to_dict()["obstacles"] != b.to_dict()["obstacles"] for a, b in zip(worlds, other))


@pytest.mark.parametrize("kind", FAMILIES)
def test_worlds_are_solvable_for_the_footprint_and_start_far_from_the_goal(kind):
    for scenario in generate_worlds(kind, 6, 2):
        start, goal = scenario.start[:2], scenario.goal.position
        assert connected(scenario.world, start, goal, ROBOT + MARGINS[kind]), scenario.name
        assert np.hypot(*(goal - start)) >= 10.0
        assert (scenario.world.clearance(np.array([start, goal])) > ROBOT + 0.5).all()


@pytest.mark.parametrize("kind", FAMILIES)
def test_worlds_are_valid_scenario_files(kind, tmp_path, capsys):
    for scenario in generate_worlds(kind, 3, 0):
        assert_same_goal_scenario(scenario_from_dict(scenario.to_dict(), source="again"), scenario)
    assert main(["worlds", "generate", kind, "--n", "2", "--seed", "4", "--out", str(tmp_path)]) == 0
    for original in generate_worlds(kind, 2, 4):
        assert_same_goal_scenario(load_scenario(tmp_path / f"{original.name}.yaml"), original)
    suite = parse_suite(f"{kind}:3:9")
    assert_same_goal_scenario(suite.scenario(2, 1), generate_world(kind, 10, 2))


def test_office_doors_are_as_wide_as_drawn_and_pieces_leave_them_open():
    pieces = office.with_doors((0.0, 5.0), (10.0, 5.0), [(7.0, 1.2), (2.0, 0.9)])
    spans = [(w["wall"]["start"][0], w["wall"]["end"][0]) for w in pieces]
    assert spans == [(0.0, 1.55), (2.45, 6.4), (7.6, 10.0)]
    rng = np.random.default_rng(1)
    for _ in range(200):
        centre, width = office._door(rng, 3.0)
        assert office.DOORS[0] <= width <= office.DOORS[1]
        assert centre - width / 2 >= office.JAMB - 1e-9 and centre + width / 2 <= 3.0 - office.JAMB + 1e-9


def test_office_rooms_open_onto_a_corridor_through_doors_narrower_than_its_width():
    for scenario in generate_worlds("office", 5, 0):
        walls = [o for o in scenario.world.obstacles if isinstance(o, Wall)]
        assert len(walls) >= 10 and len(walls) == len(scenario.world.obstacles)
        # the rooms are closed but for doors: a disc wider than the widest door fits in them but cannot leave
        wide = office.DOORS[1] / 2 + 0.2
        assert (scenario.world.clearance(np.array([scenario.start[:2], scenario.goal.position])) >= wide).all()
        assert not connected(scenario.world, scenario.start[:2], scenario.goal.position, wide)


def test_maze_corridors_let_the_car_turn_round_and_the_maze_has_loops():
    rng = np.random.default_rng(0)
    east, north = maze.carve(rng, 8)
    cells, openings = 64, (~east).sum() + (~north).sum()
    assert openings > cells - 1  # a spanning tree has cells - 1 openings; braiding adds loops
    for scenario in generate_worlds("maze", 5, 1):
        side = 20.0 / int(scenario.description.split(" x ")[1].split()[0])
        assert side - maze.THICKNESS >= 2 * (ROBOT + TURNING_MARGIN)
        assert all(isinstance(o, Wall) for o in scenario.world.obstacles)


def test_forest_posts_are_thin_spaced_and_clear_of_start_and_goal():
    for scenario in generate_worlds("forest", 5, 3):
        posts = scenario.world.obstacles
        assert len(posts) >= 50 and all(isinstance(p, Circle) for p in posts)
        radii = np.array([p.radius for p in posts])
        centres = np.array([p.center for p in posts])
        assert radii.min() >= forest.RADII[0] - 1e-3 and radii.max() <= forest.RADII[1] + 1e-3
        gaps = np.hypot(*(centres[:, None] - centres[None]).transpose(2, 0, 1)) + np.eye(len(posts)) * 99
        assert gaps.min() >= forest.SPACING[0] - 1e-2
        ends = np.array([scenario.start[:2], scenario.goal.position])
        assert (scenario.world.clearance(ends) >= POINT_CLEARANCE - 1e-9).all()


def test_poisson_disc_sample_is_spaced_and_maximal():
    points = forest.poisson_disc(np.random.default_rng(0), 10.0, 6.0, 1.0)
    distance = np.hypot(*(points[:, None] - points[None]).transpose(2, 0, 1)) + np.eye(len(points)) * 99
    assert distance.min() >= 1.0
    grid = np.stack(np.meshgrid(np.linspace(0.5, 9.5, 19), np.linspace(0.5, 5.5, 11)), -1).reshape(-1, 2)
    nearest = np.hypot(*(grid[:, None] - points[None]).transpose(2, 0, 1)).min(axis=1)
    assert nearest.max() < 2.0  # no hole a further point would fit in (Bridson: within 2 spacings)


@pytest.mark.parametrize("kind", FAMILIES)
def test_the_default_navigator_reaches_the_goal_without_touching(kind):
    scenario = generate_world(kind, 0, 1)
    trace = run_episode(scenario, make_controller("fuzzy-5b"), seed=0)
    assert trace.outcome == "reached", scenario.name
    assert (scenario.world.clearance(trace.pose[:, :2]) >= trace.robot_radius).all()
