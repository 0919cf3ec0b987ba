"""One pose goes through tricycle.step's float path, many through its array path: same poses."""

import numpy as np
import pytest

from fuzzynav.robot.tricycle import TricycleParams, step


@pytest.mark.parametrize("integrator", ["euler", "arc"])
def test_float_path_matches_array_path(integrator):
    rng = np.random.default_rng(7)
    params = TricycleParams(integrator=integrator)
    poses = np.column_stack([rng.uniform(0, 20, (400, 2)), rng.uniform(-np.pi, np.pi, 400)])
    steering = np.where(rng.random(400) < 0.2, 0.0, rng.uniform(-0.8, 0.8, 400))  # straight lines too
    speed = rng.uniform(0, 4, 400)
    batch = step(poses, steering, speed, params)
    single = np.concatenate([step(poses[i:i + 1], steering[i:i + 1], speed[i:i + 1], params) for i in range(400)])
    np.testing.assert_allclose(single, batch, rtol=0, atol=1e-12)
    turned = np.abs(np.diff(np.unwrap([poses[:, 2], batch[:, 2]], axis=0), axis=0))
    assert turned.max() > 0.1  # the headings did change (and wrap)


def test_float_path_keeps_numpy_semantics_for_inf_and_nan():
    inf = step(np.array([[np.inf, 1.0, 0.0]]), np.array([0.1]), np.array([1.0]))
    assert inf[0, 0] == np.inf and np.isfinite(inf[0, 1:]).all()
    nan = step(np.array([[1.0, 1.0, 0.0]]), np.array([np.nan]), np.array([1.0]))
    assert np.isnan(nan[0, 2]) and nan[0, 0] == 1.1
    with np.errstate(invalid="ignore"):  # math.cos(inf) raises; the array path gives nan
        heading = step(np.array([[1.0, 1.0, np.inf]]), np.array([0.1]), np.array([1.0]))
    assert np.isnan(heading).all()


def test_clip_of_one_robot_matches_the_array_clip():
    params = TricycleParams()
    values = [np.nan, -np.inf, -2.0, -0.5, 0.0, 0.3, 1.0, 5.0, np.inf]
    for steering in values:
        for speed in values:
            one = params.clip(np.array([steering]), np.array([speed]))
            many = params.clip(np.array([steering, 0.0]), np.array([speed, 0.0]))
            np.testing.assert_array_equal(one[0], many[0][:1])
            np.testing.assert_array_equal(one[1], many[1][:1])
    assert params.clip(np.array([1]), np.array([3]))[1].dtype == float
