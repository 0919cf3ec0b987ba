import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.robot.tricycle import DEFAULT_PARAMS, TricycleParams, step


def test_defaults_match_architecture():
    p = DEFAULT_PARAMS
    assert (p.dt, p.wheelbase, p.width, p.radius) == (0.1, 0.5, 0.5, 0.3)
    assert p.max_steering == pytest.approx(np.pi / 4) and (p.min_speed, p.max_speed) == (0.0, 4.0)


def test_euler_is_eq_IV_2():
    pose = np.array([1.0, 2.0, 0.3])
    new = step(pose, 0.2, 1.5)
    dt, l = DEFAULT_PARAMS.dt, DEFAULT_PARAMS.wheelbase
    expected = [1.0 + dt * 1.5 * np.cos(0.3), 2.0 + dt * 1.5 * np.sin(0.3), 0.3 + dt * 1.5 * np.tan(0.2) / l]
    np.testing.assert_allclose(new, expected)


@pytest.mark.parametrize("steering", [0.3, -0.5])
def test_arc_integration_stays_on_the_turning_circle(steering):
    params = TricycleParams(integrator="arc")
    speed = 2.0
    radius = params.wheelbase / np.tan(abs(steering))
    center = np.array([0.0, np.sign(steering) * radius])  # start at origin heading +x
    pose = np.zeros(3)
    for _ in range(200):
        pose = step(pose, steering, speed, params)
        assert np.hypot(*(pose[:2] - center)) == pytest.approx(radius, abs=1e-9)
    # the heading is tangent to the circle
    rel = pose[:2] - center
    tangent = np.arctan2(rel[1], rel[0]) + np.sign(steering) * np.pi / 2
    assert np.cos(pose[2] - tangent) == pytest.approx(1.0)


def test_arc_and_euler_agree_for_small_steps_and_straight_lines():
    fine = TricycleParams(dt=1e-3)
    a = e = np.array([0.0, 0.0, 0.0])
    for _ in range(1000):
        a = step(a, 0.4, 1.0, fine, integrator="arc")
        e = step(e, 0.4, 1.0, fine, integrator="euler")
    assert np.hypot(*(a[:2] - e[:2])) < 2e-3
    np.testing.assert_allclose(step([0, 0, 0.5], 0.0, 2.0, integrator="arc"), step([0, 0, 0.5], 0.0, 2.0))


def test_batch_equals_one_by_one():
    rng = np.random.default_rng(0)
    poses = rng.uniform(-1, 1, (16, 3))
    steering = rng.uniform(-0.7, 0.7, 16)
    speed = rng.uniform(0, 4, 16)
    batch = step(poses, steering, speed)
    assert batch.shape == (16, 3)
    for i in range(16):
        np.testing.assert_allclose(batch[i], step(poses[i], steering[i], speed[i]))
    assert np.all(np.abs(batch[:, 2]) <= np.pi)


def test_clip_limits():
    steering, speed = DEFAULT_PARAMS.clip(np.array([-2.0, 0.1, 2.0]), np.array([-1.0, 2.0, 9.0]))
    np.testing.assert_allclose(steering, [-np.pi / 4, 0.1, np.pi / 4])
    np.testing.assert_allclose(speed, [-0.5, 2.0, 4.0])  # the default robot reverses at up to 0.5 m/s
    no_reverse = TricycleParams(max_reverse_speed=0.0)
    np.testing.assert_allclose(no_reverse.clip(np.zeros(3), np.array([-1.0, 2.0, 9.0]))[1], [0.0, 2.0, 4.0])


@pytest.mark.parametrize("bad", [{"dt": 0.0}, {"wheelbase": -1.0}, {"radius": float("nan")},
                                 {"integrator": "rk4"}, {"min_speed": 5.0}])
def test_bad_params(bad):
    with pytest.raises(InputError):
        TricycleParams(**bad)
