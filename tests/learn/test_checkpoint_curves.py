"""Learning curves: smoothing, the episodes-to-converge criterion and the Fig VI.1-style plot."""

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.learn.curves import episodes_to_converge, moving_average, plateau, records
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
    assert episodes_to_converge(-2 + 3 * curve, window=10) == 110  # scale- and sign-free
    assert plateau(curve, tail=0.1, window=10) == 1.0


def test_exponential_curve_with_and_without_noise():
    k = np.arange(3000)
    clean = 2.0 - 3.0 * np.exp(-k / 300.0)
    # the raw curve enters the 5 % band at τ ln 20 ≈ 899; the trailing window lags by ~window/2
    # and the start level (first window's mean, −0.57 instead of −1) narrows the band a little
    assert 300 * np.log(20) + 50 < episodes_to_converge(clean, window=100) < 300 * np.log(20) + 120
    # noise can only delay the last exit from the band ("stays within" is conservative)
    noisy = clean + np.random.default_rng(0).normal(0, 0.3, k.size)
    assert 940 < episodes_to_converge(noisy, window=100) < 1300


def test_unsettled_and_flat_curves():
    # still rising at the end: the last window is above the plateau (mean of the last half)
    assert episodes_to_converge(np.linspace(0, 1, 500), window=10, tail=0.5) == 501
    assert episodes_to_converge(np.full(80, 0.7), window=20) == 20
    with pytest.raises(InputError, match="empty"):
        episodes_to_converge([])
    with pytest.raises(InputError, match="tolerance"):
        episodes_to_converge([1, 2], tolerance=5)


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
    with pytest.raises(InputError, match="curve"):
        plot_learning_curve(np.zeros((2, 2, 2)))


def test_records_from_a_train_loop_curve():
    curve = {"mean_reward": [[[1.0, 3.0], [2.0, 4.0]], [[0.0, 2.0], [1.0, 1.0]]], "steps": [[5, 6], [7, 8]]}
    assert records(curve).tolist() == [[2.0, 3.0], [1.0, 1.0]]
    assert records(curve, head=1).tolist() == [[3.0, 4.0], [2.0, 1.0]]
    assert records(curve, "steps").ravel().tolist() == [5, 6, 7, 8]
    with pytest.raises(InputError, match="success"):
        records(curve, "success")
