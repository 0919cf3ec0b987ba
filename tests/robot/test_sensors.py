import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.world import Circle, World


def test_thesis_layout():
    ring = SensorRing()
    np.testing.assert_allclose(np.rad2deg(ring.angles), [0, -30, 30, -60, 60, -90, 90])
    assert ring.count == 7 and ring.max_range == 4.0


def test_readings_see_left_and_right():
    world = World(obstacles=(Circle([10, 12], 1.0), Circle([10, 7], 1.0)))
    d = SensorRing().read(world, np.array([[10.0, 10.0, 0.0]]))[0]
    assert d[0] == 4.0  # nothing ahead within range
    assert d[6] == pytest.approx(1.0)  # +90°: left obstacle surface at y = 11
    assert d[5] == pytest.approx(2.0)  # −90°: right obstacle surface at y = 8


def test_noise_is_seeded_and_bounded():
    world = World(obstacles=(Circle([11, 10], 0.5),))
    ring = SensorRing(noise_std=0.2)
    poses = np.array([[10.0, 10.0, 0.0]] * 50)
    a = ring.read(world, poses, np.random.default_rng(1))
    b = ring.read(world, poses, np.random.default_rng(1))
    c = ring.read(world, poses, np.random.default_rng(2))
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)
    assert a.min() >= 0.0 and a.max() <= 4.0
    assert abs(a[:, 0].mean() - 0.5) < 0.1 and a[:, 0].std() > 0.1


@pytest.mark.parametrize("bad", [{"angles": []}, {"max_range": 0.0}, {"noise_std": -1.0}])
def test_bad_ring(bad):
    with pytest.raises(InputError):
        SensorRing(**bad)


def test_noise_needs_an_explicit_generator():
    with pytest.raises(ValueError, match="Generator"):
        SensorRing(noise_std=0.1).read(World(), np.array([[10.0, 10.0, 0.0]]))
