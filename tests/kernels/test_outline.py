"""The compiled outline distance (kernels/outline.py) against the brute force over every segment:
the same distances and nearest points, ties to the first segment, for echoes on the outline, off
it and far from it."""

import numpy as np
import pytest

from fuzzynav.kernels.outline import BRIDGE, off_outline


def brute_force(points, before, valid, bridge):
    """Every point against every segment of the outline (neighbouring valid beams < bridge apart)."""
    a, b = before[:-1], before[1:]
    joined = valid[:-1] & valid[1:] & (np.hypot(*(b - a).T) < bridge)
    a, e = a[joined], (b - a)[joined]
    if not len(a):
        return np.full(len(points), np.inf), points.copy()
    u = np.clip(np.einsum("pk,sk->ps", points, e) - np.einsum("sk,sk->s", a, e)[None], 0.0, None)
    u = np.minimum(u / np.maximum(np.einsum("sk,sk->s", e, e), 1e-12)[None], 1.0)
    foot = a[None] + u[..., None] * e[None]
    dist = np.hypot(*(points[:, None] - foot).transpose(2, 0, 1))
    s = np.argmin(dist, axis=1)
    return dist[np.arange(len(points)), s], foot[np.arange(len(points)), s]


@pytest.mark.parametrize("seed", range(20))
def test_the_grid_search_finds_the_nearest_segment_exactly(seed):
    rng = np.random.default_rng(seed)
    angles = np.linspace(-2.3, 2.3, 271)
    r = np.convolve(rng.uniform(0.3, 4.0, 271), np.ones(9) / 9, mode="same")
    before = np.column_stack([r * np.cos(angles), r * np.sin(angles)]) + rng.normal(0, 0.01, (271, 2))
    valid = rng.uniform(size=271) < 0.9
    n = int(rng.integers(1, 271))
    points = before[rng.integers(0, 271, n)].copy()  # on the outline's vertices: ties between segments
    nudged = rng.uniform(size=n) < 0.6
    points[nudged] += rng.normal(0, 0.1, (int(nudged.sum()), 2))
    far = rng.uniform(size=n) < 0.1
    points[far] += rng.normal(0, 3.0, (int(far.sum()), 2))
    dist, foot = off_outline(points, before, valid, BRIDGE)
    expected_dist, expected_foot = brute_force(points, before, valid, BRIDGE)
    np.testing.assert_array_equal(dist, expected_dist)
    np.testing.assert_array_equal(foot, expected_foot)


def test_no_outline_leaves_every_point_at_infinity():
    before = np.column_stack([np.arange(5.0), np.zeros(5)])  # 1 m apart: wider than the bridge
    points = np.array([[0.5, 0.1], [3.0, 2.0]])
    dist, foot = off_outline(points, before, np.ones(5, dtype=bool), BRIDGE)
    assert np.isinf(dist).all()
    np.testing.assert_array_equal(foot, points)
