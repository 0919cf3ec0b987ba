"""Learning curves: smoothing, the episodes-to-converge criterion and the Fig VI.1-style plot."""

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.learn.curves import episodes_to_converge, moving_average, records
from fuzzynav.viz.curves import plot_learning_curve


def test_moving_average_is_trailing():
    assert moving_average([1, 2, 3, 4, 5], 2).tolist() == [1.0, 1.5, 2.5, 3.5, 4.5]
    assert moving_average([3.0], 10).tolist() == [3.0]
    with pytest.raises(InputError, match="window"):
        moving_average([1, 2], 0)


def test_step_curve_converges_one_window_after_the_step():
    curve = np.r_[np.zeros(100), np.ones(200)]
    # m_k = (k − 99) / 10 just after the step: within 5 % of the plateau 1 once m ≥ 0.95
    assert episodes_to_converge(curve, window=10) == 110
    assert episodes_to_converge(-2 + 3 * curve, window=10) == 110  # the band follows the travel, 3
    # judged at batch ends only: the first end of a batch of 25 at or after episode 110
    assert episodes_to_converge(curve, window=25, batch=25, hold=100) == 125


def test_exponential_curve_with_and_without_noise():
    k = np.arange(3000)
    clean = 2.0 - 3.0 * np.exp(-k / 300.0)
    # the raw curve is within 5 % of its travel (≈ 0.13) of the plateau 2 from τ ln(3 / 0.13)
    # ≈ 940; the hold's mean sits a little below 2 and the trailing window lags (hold 1000)
    assert 300 * np.log(20) < episodes_to_converge(clean, window=100) < 300 * np.log(20) + 60
    # noise of σ = 0.3 widens the band to 3 σ / √W and delays the settling of the smoothed curve
    noisy = clean + np.random.default_rng(0).normal(0, 0.3, k.size)
    assert 940 < episodes_to_converge(noisy, window=100) < 1300


def test_the_answer_does_not_depend_on_the_budget():
    rng = np.random.default_rng(3)
    k = np.arange(8000)
    curve = 1.0 - np.exp(-k / 400.0) + rng.normal(0, 0.2, k.size)
    first = episodes_to_converge(curve[:4000], window=50, batch=50)
    assert first < 4000 - 500  # settled within the shorter budget
    assert episodes_to_converge(curve, window=50, batch=50) == first  # twice the budget: the same
    # it reads the first k + H episodes only: what comes after cannot change it
    assert episodes_to_converge(np.r_[curve[:first + 500], -curve[first + 500:]], window=50, batch=50) == first
    # too short a budget says so (len + 1) instead of answering near its end
    assert episodes_to_converge(curve[:first + 400], window=50, batch=50) == first + 401


def test_noise_floor_and_success_gate():
    rng = np.random.default_rng(1)
    flat = 0.7 + rng.normal(0, 0.3, 1000)  # settled from the start, noisy: the band is 3 σ / √W
    assert episodes_to_converge(flat, window=50) == 50
    half = np.tile([1.0, 0.0], 500)  # a plateau of half failures is not convergence
    assert episodes_to_converge(flat, window=50, success=half) == 1001
    solved = (rng.random(1000) < 0.97).astype(float)
    assert episodes_to_converge(flat, window=50, success=solved) == 50
    with pytest.raises(InputError, match="success"):
        episodes_to_converge(flat, window=50, success=solved[:10])


def test_unsettled_and_bad_input():
    # still rising by 20 % of its travel over every hold: never within 5 % of the plateau that follows
    assert episodes_to_converge(np.linspace(0, 1, 5000), window=100) == 5001
    assert episodes_to_converge(np.full(80, 0.7), window=20) == 81  # shorter than window + hold
    assert episodes_to_converge(np.full(80, 0.7), window=20, hold=60) == 20
    with pytest.raises(InputError, match="empty"):
        episodes_to_converge([])
    with pytest.raises(InputError, match="tolerance"):
        episodes_to_converge([1, 2], tolerance=5)
    with pytest.raises(InputError, match="multiples"):
        episodes_to_converge(np.ones(100), window=30, batch=20)


def test_plot_learning_curve(tmp_path):
    rng = np.random.default_rng(1)
    seeds = np.r_[np.zeros(100), np.ones(200)][:, None] + rng.normal(0, 0.01, (300, 3))
    figure = plot_learning_curve(seeds, window=10, path=tmp_path / "curve.png", label="FQL")
    ax = figure.axes[0]
    assert (tmp_path / "curve.png").stat().st_size > 5000
    assert ax.get_xlabel() == "episodes" and len(ax.collections) == 1  # the min–max band
    converged = [line for line in ax.get_lines() if line.get_label().startswith("converged")]
    assert len(converged) == 1 and 108 <= converged[0].get_xdata()[0] <= 112
    single = plot_learning_curve(seeds[:, 0], window=10, mark_convergence=False)
    assert len(single.axes[0].get_lines()) == 2
    given = plot_learning_curve(seeds[:, 0], window=10, converged_at=250)  # a training's own count
    assert [line.get_xdata()[0] for line in given.axes[0].get_lines() if line.get_label().startswith("converged")] == [250]
    with pytest.raises(InputError, match="curve"):
        plot_learning_curve(np.zeros((2, 2, 2)))


def test_records_from_a_train_loop_curve():
    curve = {"mean_reward": [[[1.0, 3.0], [2.0, 4.0]], [[0.0, 2.0], [1.0, 1.0]]], "steps": [[5, 6], [7, 8]]}
    assert records(curve).tolist() == [[2.0, 3.0], [1.0, 1.0]]
    assert records(curve, head=1).tolist() == [[3.0, 4.0], [2.0, 1.0]]
    assert records(curve, "steps").ravel().tolist() == [5, 6, 7, 8]
    with pytest.raises(InputError, match="success"):
        records(curve, "success")


def world_curve(seed, batches=40, step_batch=12, batch=50):
    """An avoider-like curve: one random world per batch of 50 episodes sets their common level
    (σ 0.15), episodes vary around it (σ 0.25); the mean steps from −0.6 to −0.2 at batch 12."""
    rng = np.random.default_rng(seed)
    level = np.where(np.arange(batches) < step_batch, -0.6, -0.2) + rng.normal(0, 0.15, batches)
    return (level[:, None] + rng.normal(0, 0.25, (batches, batch))).ravel()


def test_clustered_batches_settle_after_the_step_whatever_the_budget():
    options = {"window": 500, "hold": 750, "batch": 50}
    independent = []
    for seed in range(10):
        curve = world_curve(seed)
        independent.append(episodes_to_converge(curve, **options))
        k = episodes_to_converge(curve, clustered=True, **options)
        assert 600 < k <= 1150  # after the step at episode 600, at most one window (500) later
        assert episodes_to_converge(curve[:k + 750], clustered=True, **options) == k
        longer = np.r_[curve, world_curve(seed + 10, step_batch=0)]
        assert episodes_to_converge(longer, clustered=True, **options) == k
    # as if the episodes were independent, the band is √50 too narrow for the worlds' noise
    assert independent.count(2001) >= 7


def test_clustered_flat_curve_and_bad_hold():
    flat = world_curve(0, step_batch=0)
    assert episodes_to_converge(flat, window=500, hold=750, batch=50, clustered=True) == 500  # the first window
    with pytest.raises(InputError, match="2 batches"):
        episodes_to_converge(flat, window=50, hold=50, batch=50, clustered=True)
