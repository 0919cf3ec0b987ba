"""Shortest collision-free paths of a disc (world/planning.py)."""

import math

import numpy as np

from fuzzynav.world.planning import shortest_path
from fuzzynav.world.polylines import path_length
from fuzzynav.world.scenario import scenario_from_dict


def _world(obstacles, width=20.0, height=10.0):
    doc = {"world": {"width": width, "height": height}, "robot": {"x": 2, "y": 5}, "goal": {"x": 18, "y": 5},
           "obstacles": obstacles}
    return scenario_from_dict(doc).world


def test_open_world_gives_the_straight_line():
    path = shortest_path(_world([]), (2, 5), (18, 5), 0.3)
    assert path_length(path) == 16.0
    assert np.array_equal(path[0], [2, 5]) and np.array_equal(path[-1], [18, 5])


def test_round_a_disc_is_close_to_the_tangent_arc_tangent_length():
    """Around a circle of radius 1 at (10, 5) a disc of 0.3 goes tangent, arc, tangent on the circle
    of radius 1.3: 2 √(8² − 1.3²) + 1.3 (π − 2 acos(1.3 / 8))."""
    path = shortest_path(_world([{"circle": {"center": [10, 5], "radius": 1.0}}]), (2, 5), (18, 5), 0.3)
    r, d = 1.3, 8.0
    exact = 2 * math.sqrt(d * d - r * r) + r * (math.pi - 2 * math.acos(r / d))
    assert exact <= path_length(path) < exact * 1.02
    assert path_length(path) > 16.0


def test_no_path_through_a_closed_wall_or_a_gap_too_narrow():
    closed = _world([{"wall": {"start": [10, 0], "end": [10, 10], "thickness": 0.3}}])
    assert shortest_path(closed, (2, 5), (18, 5), 0.3) is None
    gap = _world([{"wall": {"start": [10, 0], "end": [10, 4.6], "thickness": 0.2}},
                  {"wall": {"start": [10, 5.4], "end": [10, 10], "thickness": 0.2}}])  # 0.8 m - 0.2 m walls
    assert shortest_path(gap, (2, 5), (18, 5), 0.2) is not None
    assert shortest_path(gap, (2, 5), (18, 5), 0.45) is None


def test_clearance_cost_keeps_the_path_away_from_obstacles():
    world = _world([{"circle": {"center": [10, 5], "radius": 1.0}}])
    plain = shortest_path(world, (2, 5), (18, 5), 0.3)
    careful = shortest_path(world, (2, 5), (18, 5), 0.3, weight=3.0, comfort=0.5)
    dense = lambda p: np.vstack([a + np.linspace(0, 1, 50)[:, None] * (b - a) for a, b in zip(p[:-1], p[1:])])
    assert world.clearance(dense(careful)).min() > world.clearance(dense(plain)).min() + 0.2


def test_a_huge_world_gets_a_coarser_grid_and_a_path_in_bounded_memory():
    """A 3 km world at 0.1 m cells would be 900 million cells (7 GB a grid): the cell grows so
    that the grid stays within MAX_GRID_CELLS, and the path is still found."""
    from fuzzynav.world.planning import MAX_GRID_CELLS, default_cell

    huge = scenario_from_dict({"world": {"width": 3000, "height": 3000}, "robot": {"x": 5, "y": 5},
                               "goal": {"x": 2990, "y": 2990}}, source="huge.yaml").world
    cell = default_cell(huge)
    assert (3000 / cell) ** 2 <= MAX_GRID_CELLS * 1.0001 and cell > 2.0
    path = shortest_path(huge, (5, 5), (2990, 2990), 0.3)
    assert path is not None and math.isclose(path_length(path), math.hypot(2985, 2985), rel_tol=0.01)
    small = scenario_from_dict({"robot": {"x": 1, "y": 1}, "goal": {"x": 15, "y": 15}}, source="s.yaml").world
    assert default_cell(small) == 0.1  # the worlds of the families and BARN keep their cells
