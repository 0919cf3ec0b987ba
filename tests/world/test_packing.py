"""Packing a world's shapes for the kernels (fuzzynav.kernels.layout.pack) and the walls' cached corners."""

import numpy as np
import pytest

from fuzzynav.kernels import layout
from fuzzynav.world import Wall


def polygon_block(scene):
    """The polygon rows (P, 5) and edge rows (E, 7) of a packed scene."""
    n_polygons, n_edges = int(scene[layout.N_POLYGONS]), int(scene[layout.N_EDGES])
    at_polygons, at_edges = int(scene[layout.AT_POLYGONS]), int(scene[layout.AT_EDGES])
    return (scene[at_polygons:at_polygons + 5 * n_polygons].reshape(-1, 5),
            scene[at_edges:at_edges + 7 * n_edges].reshape(-1, 7))


def test_a_square_packs_its_edges_centre_and_bounding_radius():
    rows, edges = polygon_block(layout.pack(20.0, 20.0, [], [[[0, 0], [2, 0], [2, 2], [0, 2]]], []))
    np.testing.assert_array_equal(rows, [[0, 4, 1, 1, np.sqrt(2)]])
    np.testing.assert_array_equal(edges[:, :4], [[0, 0, 2, 0], [2, 0, 2, 2], [2, 2, 0, 2], [0, 2, 0, 0]])
    np.testing.assert_array_equal(edges[:, 4:], [[2, 0, 4], [0, 2, 4], [-2, 0, 4], [0, -2, 4]])


def test_each_polygon_packs_as_alone_whatever_its_neighbours():
    """Polygons of mixed vertex counts are packed together; each one's rows are bit for bit those
    it has packed alone (its centre summed in the same order), its edges shifted by those before."""
    rng = np.random.default_rng(3)
    polygons = [rng.normal(0.0, 10.0 ** rng.uniform(-2, 3), (int(n), 2)) + rng.uniform(-1e3, 1e3, 2)
                for n in rng.integers(3, 40, 30)]
    rows, edges = polygon_block(layout.pack(20.0, 20.0, [(1.0, 2.0, 0.5)], polygons, [(5.0, 5.0, 2.0, 1.0, 0.3)]))
    start = 0
    for polygon, row in zip(polygons, rows):
        alone_rows, alone_edges = polygon_block(layout.pack(20.0, 20.0, [], [polygon], []))
        assert row.tobytes() == (alone_rows[0] + [start, start, 0, 0, 0]).tobytes()
        assert edges[start:start + len(polygon)].tobytes() == alone_edges.tobytes()
        start += len(polygon)
    assert start == len(edges)


def test_a_wall_computes_its_corners_once_read_only():
    start = np.array([2.0, 12.0])
    wall = Wall(start, [10.0, 12.0], 0.2)
    start[0] = 5.0  # the wall keeps its own copy of its ends, so its corners cannot go stale
    assert wall.vertices is wall.packed()
    np.testing.assert_allclose(wall.vertices, [[2, 11.9], [10, 11.9], [10, 12.1], [2, 12.1]])
    for array in (wall.vertices, wall.start, wall.end):
        with pytest.raises(ValueError):
            array[0] = 0.0
    assert "vertices" not in Wall.schema() and "vertices" not in wall.to_dict()["wall"]


def corners_one_wall_at_a_time(start, end, thickness):
    """A wall's rectangle as walls first computed it (numpy scalars, one wall at a time)."""
    direction = end - start
    normal = np.array([-direction[1], direction[0]]) / np.hypot(*direction) * (0.5 * thickness)
    return np.array([start - normal, end - normal, end + normal, start + normal])


def test_a_chain_of_walls_is_the_walls_built_one_by_one_bit_for_bit():
    rng = np.random.default_rng(8)
    for _ in range(200):
        points = rng.uniform(-50.0, 50.0, (int(rng.integers(2, 8)), 2))
        thickness = float(rng.uniform(0.01, 2.0))
        chain = Wall.chain(points, thickness)
        assert len(chain) == len(points) - 1
        for i, wall in enumerate(chain):
            alone = Wall(points[i], points[i + 1], thickness)
            assert type(wall) is Wall and wall.thickness == alone.thickness
            assert wall.start.tobytes() == alone.start.tobytes() and wall.end.tobytes() == alone.end.tobytes()
            assert wall.vertices.tobytes() == alone.vertices.tobytes()
            assert wall.vertices.tobytes() == corners_one_wall_at_a_time(points[i], points[i + 1], thickness).tobytes()
            for array in (wall.vertices, wall.start, wall.end):
                with pytest.raises(ValueError):
                    array[0] = 0.0
    points[0, 0] = 99.0  # the chain holds its own copy of the points
    assert chain[0].start[0] != 99.0


@pytest.mark.parametrize("points, thickness, field", [
    ([[0.0, 0.0]], 0.3, "points"),
    ([[0.0, 0.0], [1.0, 1.0], [1.0, 1.0]], 0.3, "points[2]"),
    ([[0.0, 0.0], [np.nan, 1.0]], 0.3, "points"),
    ([[0.0, 0.0], [1e9, 1.0]], 0.3, "points"),
    ([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]], 0.3, "points"),
    ([[0.0, 0.0], [1.0, 1.0]], 0.0, "thickness"),
    ([[0.0, 0.0], [1.0, 1.0]], "thick", "thickness"),
])
def test_a_chain_of_walls_checks_its_points_and_thickness(points, thickness, field):
    from fuzzynav.errors import InputError

    with pytest.raises(InputError) as caught:
        Wall.chain(points, thickness)
    assert caught.value.field == field


def test_walls_packed_in_compiled_code_are_the_packed_world_bit_for_bit():
    from fuzzynav.kernels.courses import pack_walls

    rng = np.random.default_rng(9)
    for _ in range(300):
        points = rng.uniform(-10 ** rng.uniform(-1, 4), 10 ** rng.uniform(-1, 4), (int(rng.integers(2, 8)), 2))
        walls = Wall.chain(points, float(rng.uniform(0.01, 3.0)))
        vertices = np.array([wall.vertices for wall in walls])
        assert pack_walls(20.0, 15.0, vertices).tobytes() == layout.pack(20.0, 15.0, [], vertices, []).tobytes()


def test_a_prepacked_world_is_the_world_its_constructor_builds():
    from fuzzynav.kernels.courses import pack_walls
    from fuzzynav.world import Circle, World

    walls = Wall.chain([[2.0, 2.0], [8.0, 3.0], [6.0, 9.0]], 0.3)
    scene = pack_walls(20.0, 20.0, np.array([wall.vertices for wall in walls]))
    world, built = World.prepacked(20, 20.0, walls, scene), World(20.0, 20.0, walls)
    assert world == built and world.scene.tobytes() == built.scene.tobytes()
    assert world.order.tobytes() == built.order.tobytes() and isinstance(world.width, float)
    points = np.random.default_rng(1).uniform(0.0, 20.0, (50, 2))
    np.testing.assert_array_equal(world.clearance(points), built.clearance(points))
    with pytest.raises(ValueError, match="does not hold"):
        World.prepacked(20.0, 20.0, walls + (Circle([5.0, 5.0], 1.0),), scene)
