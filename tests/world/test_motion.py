import numpy as np
import pytest

from fuzzynav.world.motion import TargetMotion

MOTIONS = [
    TargetMotion("static", [4, 12]),
    TargetMotion("line", [4, 12], velocity=np.array([0.5, -0.2])),
    TargetMotion("circle", [4, 12], center=np.array([8, 12]), speed=0.7),
    TargetMotion("sinusoid", [4, 12], velocity=np.array([0.4, 0.0]), amplitude=1.5, period=8.0),
]


@pytest.mark.parametrize("motion", MOTIONS, ids=lambda m: m.type)
def test_starts_at_p0_and_velocity_is_the_derivative(motion):
    t = np.linspace(0.0, 20.0, 201)
    positions = motion.position(t)
    np.testing.assert_allclose(positions[0], [4, 12])
    assert positions.shape == (201, 2) and motion.position(3.0).shape == (2,)
    h = 1e-6
    numeric = (motion.position(t + h) - motion.position(t - h)) / (2 * h)
    np.testing.assert_allclose(motion.velocity_at(t), numeric, atol=1e-6)


def test_shapes_of_the_courses():
    np.testing.assert_allclose(MOTIONS[1].position(np.array([0.0, 10.0])), [[4, 12], [9, 10]])  # p0 + v t
    # counter-clockwise round (8, 12) from p0 = (4, 12): a quarter turn (π/2 · 4 m / 0.7 m/s) later at (8, 8)
    np.testing.assert_allclose(MOTIONS[2].position(np.pi / 2 * 4.0 / 0.7), [8, 8], atol=1e-12)
    np.testing.assert_allclose(MOTIONS[2].velocity_at(0.0), [0, -0.7], atol=1e-12)
    circle = MOTIONS[2].position(np.linspace(0, 30, 50))
    np.testing.assert_allclose(np.hypot(*(circle - [8, 12]).T), 4.0)
    assert np.allclose(np.hypot(*MOTIONS[2].velocity_at(np.array([1.0, 7.0])).T), 0.7)
    sinus = MOTIONS[3].position(np.array([2.0, 6.0, 8.0]))
    np.testing.assert_allclose(sinus, [[4.8, 13.5], [6.4, 10.5], [7.2, 12.0]], atol=1e-12)
