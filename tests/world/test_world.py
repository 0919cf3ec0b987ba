import numpy as np
import pytest

from fuzzynav.world import Circle, Ellipse, Polygon, Wall, World
from fuzzynav.world.polygons import polygon_self_intersects

MIXED = World(obstacles=(
    Circle([5, 5], 1.0),
    Polygon([[8, 8], [10, 8], [10, 10]]),
    Wall([2, 12], [10, 12], 0.2),
    Ellipse([14, 6], [2.0, 1.0], 0.3),
))


def test_circle_distance_collision_nearest():
    world = World(obstacles=(Circle([5, 5], 1.0),))
    points = np.array([[5.0, 7.0], [5.0, 5.5], [8.0, 5.0]])
    distance, nearest, index = world.nearest_obstacle(points)
    np.testing.assert_allclose(distance, [1.0, -0.5, 2.0])
    np.testing.assert_allclose(nearest, [[5, 6], [5, 6], [6, 5]])
    np.testing.assert_array_equal(index, [0, 0, 0])
    np.testing.assert_array_equal(world.collides(points, 0.3), [False, True, False])
    assert world.collides(np.array([[5.0, 6.25]]), 0.3)[0]


def test_polygon_and_wall_signed_distance():
    distance, nearest, index = MIXED.nearest_obstacle(np.array([[9.5, 8.5], [9.0, 7.0], [6.0, 12.5], [6.0, 12.0]]))
    np.testing.assert_allclose(distance, [-0.5, 1.0, 0.4, -0.1])
    np.testing.assert_allclose(nearest[:3], [[9.5, 8.0], [9.0, 8.0], [6.0, 12.1]])
    np.testing.assert_array_equal(index, [1, 1, 2, 2])


def test_ellipse_distance_matches_dense_sampling():
    rng = np.random.default_rng(3)
    ellipse = Ellipse([14, 6], [2.0, 0.7], 0.3)
    world = World(obstacles=(ellipse,))
    points = rng.uniform([10, 3], [18, 9], (200, 2))
    s = np.linspace(0, 2 * np.pi, 20001)
    c, si = np.cos(0.3), np.sin(0.3)
    local = np.stack([2.0 * np.cos(s), 0.7 * np.sin(s)], 1)
    boundary = ellipse.center + local @ np.array([[c, si], [-si, c]])
    brute = np.hypot(*(points[:, None] - boundary[None]).transpose(2, 0, 1)).min(1)
    distance, nearest, _ = world.nearest_obstacle(points)
    np.testing.assert_allclose(np.abs(distance), brute, atol=2e-3)
    np.testing.assert_allclose(np.hypot(*(points - nearest).T), np.abs(distance), atol=1e-9)
    inside = (((points - ellipse.center) @ np.array([[c, -si], [si, c]])) / [2.0, 0.7]) ** 2
    np.testing.assert_array_equal(distance < 0, inside.sum(1) < 1)


def test_boundary_is_separate_from_obstacles():
    world = World(obstacles=(Circle([10, 10], 1.0),))
    point = np.array([[0.2, 10.0]])
    assert world.nearest_obstacle(point)[0][0] == pytest.approx(8.8)
    assert world.clearance(point)[0] == pytest.approx(0.2)
    assert world.collides(point, 0.3)[0]
    assert not world.contains(np.array([[-0.1, 3.0]]))[0]


def test_empty_world():
    world = World()
    distance, nearest, index = world.nearest_obstacle(np.array([[3.0, 4.0]]))
    assert np.isinf(distance[0]) and np.isnan(nearest[0]).all() and index[0] == -1
    assert world.clearance(np.array([[3.0, 4.0]]))[0] == pytest.approx(3.0)


def test_ranges_match_ray_marching():
    """Every ray reading equals the first point along the ray that is inside something."""
    rng = np.random.default_rng(7)
    poses = []
    while len(poses) < 20:
        x, y = rng.uniform(0.5, 19.5, 2)
        if MIXED.clearance(np.array([[x, y]]))[0] > 0.05:
            poses.append([x, y, rng.uniform(-np.pi, np.pi)])
    poses = np.array(poses)
    angles = np.deg2rad([0.0, -30, 30, -60, 60, -90, 90])
    readings = MIXED.ranges(poses, angles, 4.0)
    assert readings.shape == (20, 7)
    t = np.linspace(0.0, 4.0, 4001)
    for pose, row in zip(poses, readings):
        for angle, value in zip(angles, row):
            heading = pose[2] + angle
            points = pose[:2] + t[:, None] * [np.cos(heading), np.sin(heading)]
            blocked = np.flatnonzero(MIXED.clearance(points) < 0)
            expected = t[blocked[0]] if len(blocked) else 4.0
            assert value == pytest.approx(expected, abs=1e-3)


def test_wall_is_a_thick_rectangle():
    wall = Wall([2, 12], [10, 12], 0.2)
    np.testing.assert_allclose(wall.vertices, [[2, 11.9], [10, 11.9], [10, 12.1], [2, 12.1]])
    assert MIXED.ranges(np.array([[6.0, 10.0, np.pi / 2]]), [0.0], 4.0)[0, 0] == pytest.approx(1.9)


@pytest.mark.parametrize("points, bad", [
    ([[0, 0], [1, 0], [1, 1], [0, 1]], False),
    ([[0, 0], [1, 1], [1, 0], [0, 1]], True),  # bow tie
    ([[0, 0], [2, 0], [1, 0], [1, 1]], True),  # folds back along an edge
    ([[0, 0], [1, 0], [1, 0], [0, 1]], True),  # repeated vertex
    ([[0, 0], [1, 1], [2, 2]], True),  # zero area
    ([[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]], False),  # concave
])
def test_polygon_self_intersection(points, bad):
    assert polygon_self_intersects(points) is bad


def test_shapes_round_trip_to_dict():
    # every parameter written, defaults too (the wall's thickness): a dropped one would come back as its default
    assert [shape.to_dict() for shape in MIXED.obstacles] == [
        {"circle": {"center": [5.0, 5.0], "radius": 1.0}},
        {"polygon": {"points": [[8.0, 8.0], [10.0, 8.0], [10.0, 10.0]]}},
        {"wall": {"start": [2.0, 12.0], "end": [10.0, 12.0], "thickness": 0.2}},
        {"ellipse": {"center": [14.0, 6.0], "radii": [2.0, 1.0], "angle": 0.3}},
    ]
    for shape in MIXED.obstacles:
        (kind, params), = shape.to_dict().items()
        assert kind == shape.kind
        rebuilt = type(shape)(**params)
        assert rebuilt.to_dict() == shape.to_dict()
        np.testing.assert_array_equal(rebuilt.packed(), shape.packed())


def test_nearest_obstacle_is_the_exact_row_minimum():
    """The broad phase that skips far polygons and ellipses never changes the nearest obstacle."""
    rng = np.random.default_rng(11)
    points = rng.uniform(0, 20, (500, 2))
    exact = np.column_stack([World(obstacles=(shape,)).nearest_obstacle(points)[0] for shape in MIXED.obstacles])
    distance, nearest, index = MIXED.nearest_obstacle(points)
    np.testing.assert_allclose(distance, exact.min(axis=1))
    np.testing.assert_array_equal(index, exact.argmin(axis=1))
    np.testing.assert_allclose(np.hypot(*(points - nearest).T), np.abs(distance), atol=1e-9)
