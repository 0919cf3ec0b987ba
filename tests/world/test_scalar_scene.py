"""The one-point scalar path (ScalarScene) against the vectorised kernels, on random worlds of
every shape kind: nearest obstacle (distance, point, index) and range readings agree within 1e-9."""

import numpy as np
import pytest

from fuzzynav.world import Circle, Ellipse, Polygon, Wall, World


def random_world(seed: int) -> World:
    rng = np.random.default_rng(seed)
    shapes = []
    for _ in range(rng.integers(1, 14)):
        x, y = rng.uniform(2, 18, 2)
        kind = rng.integers(4)
        if kind == 0:
            shapes.append(Circle((x, y), rng.uniform(0.2, 2.0)))
        elif kind == 1:  # star-shaped, so simple
            n = rng.integers(3, 8)
            angle, radius = np.sort(rng.uniform(0, 2 * np.pi, n)), rng.uniform(0.3, 2.0, n)
            shapes.append(Polygon(np.column_stack([x + radius * np.cos(angle), y + radius * np.sin(angle)])))
        elif kind == 2:
            shapes.append(Wall((x, y), (x + rng.uniform(-4, 4), y + rng.uniform(-4, 4)), rng.uniform(0.05, 0.5)))
        else:
            shapes.append(Ellipse((x, y), rng.uniform(0.2, 2.5, 2), rng.uniform(-3, 3)))
    return World(obstacles=tuple(shapes))


@pytest.mark.parametrize("seed", range(12))
def test_scalar_nearest_obstacle_matches_vectorised(seed):
    world = random_world(seed)
    points = np.random.default_rng(100 + seed).uniform(-0.5, 20.5, (150, 2))
    distance, nearest, index = world.nearest_obstacle(points)  # vectorised
    single = [world.nearest_obstacle(p[None]) for p in points]  # scalar, one point each
    np.testing.assert_allclose([d[0] for d, _, _ in single], distance, rtol=0, atol=1e-9)
    np.testing.assert_allclose([q[0] for _, q, _ in single], nearest, rtol=0, atol=1e-9)
    np.testing.assert_array_equal([k[0] for _, _, k in single], index)
    assert np.any(distance < 0)  # some points inside obstacles


@pytest.mark.parametrize("seed", range(12))
def test_scalar_ranges_match_vectorised(seed):
    world = random_world(seed)
    rng = np.random.default_rng(200 + seed)
    poses = np.column_stack([rng.uniform(-0.5, 20.5, (150, 2)), rng.uniform(-np.pi, np.pi, 150)])
    angles = np.concatenate([np.deg2rad([0, -30, 30, -60, 60, -90, 90]), rng.uniform(-np.pi, np.pi, 5)])
    for max_range in (1.5, 4.0, 30.0):
        batch = world.ranges(poses, angles, max_range)  # vectorised
        single = np.concatenate([world.ranges(p, angles, max_range) for p in poses])
        np.testing.assert_allclose(single, batch, rtol=0, atol=1e-9)
        assert np.any(batch < max_range)
        assert max_range > 20 or np.any(batch == max_range)


def test_scalar_paths_of_an_empty_world():
    world = World()
    distance, nearest, index = world.nearest_obstacle([[3.0, 4.0]])
    assert distance[0] == np.inf and np.isnan(nearest).all() and index[0] == -1
    np.testing.assert_allclose(world.ranges([3.0, 4.0, 0.0], [0.0, np.pi / 2, np.pi], 30.0), [[17.0, 16.0, 3.0]])
