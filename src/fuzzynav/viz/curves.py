"""Learning-curve plots: mean reinforcement per episode, like Figs VI.1, VI.4, VI.8 and VI.22.

:func:`plot_learning_curve` draws the raw curve (light), its trailing moving average and, for
several seeds (a 2-D array, episodes × seeds), the mean over seeds with a min–max band; a dashed
vertical line marks the convergence episode — ``converged_at`` when the caller has it (a training
phase's own count, under its task's criterion), else :func:`fuzzynav.learn.curves.episodes_to_converge`
with its defaults on the seed mean; a count past the curve is written "not converged within N episodes". Uses the non-interactive Agg backend; returns the figure.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from fuzzynav import validation  # noqa: E402
from fuzzynav.errors import InputError  # noqa: E402
from fuzzynav.learn.curves import episodes_to_converge, moving_average  # noqa: E402
from fuzzynav.storage import savefig_atomic


def plot_learning_curve(curve, *, window: int = 50, tolerance: float = 0.05, label: str = "",
                        title: str = "Mean reinforcement per episode", ylabel: str = "mean reinforcement",
                        mark_convergence: bool = True, converged_at: int | None = None, ax=None, path=None):
    """Plot a learning curve (episodes,) or (episodes, seeds); save to ``path`` if given."""
    if path is not None:  # checked before drawing, as train --curve is
        from fuzzynav.viz.trajectories import figure_file

        path = figure_file(path)
    values = validation.finite_array(curve, field="curve")  # text, None or NaN: refused, not drawn
    if values.ndim == 1:
        values = values[:, None]
    if values.ndim != 2 or values.shape[0] == 0:
        raise InputError(f"a learning curve must be (episodes,) or (episodes, seeds), got {values.shape}",
                         field="curve")
    if np.abs(values).max() > validation.MAX_MAGNITUDE:  # matplotlib's axis of ±1e308 overflows
        raise InputError(f"a learning curve's values must lie within ±{validation.MAX_MAGNITUDE:g}, got "
                         f"{validation.shown(float(np.abs(values).max()))}", field="curve")
    figure = ax.figure if ax is not None else plt.figure(figsize=(6.4, 4.0))
    ax = ax if ax is not None else figure.add_subplot(111)
    episodes = np.arange(1, values.shape[0] + 1)
    mean = values.mean(axis=1)
    if values.shape[1] > 1:
        ax.fill_between(episodes, values.min(axis=1), values.max(axis=1), alpha=0.2, linewidth=0,
                        label=f"{label} min–max over {values.shape[1]} seeds".strip())
    else:
        ax.plot(episodes, mean, alpha=0.3, linewidth=0.6)
    smooth_label = f"{label} moving mean ({window} episodes)".strip()
    ax.plot(episodes, moving_average(mean, window), linewidth=1.5, label=smooth_label)
    if mark_convergence:
        converged = episodes_to_converge(mean, window=window, tolerance=tolerance) if converged_at is None else converged_at
        if converged <= values.shape[0]:
            ax.axvline(converged, linestyle="--", color="k", linewidth=0.8,
                       label=f"converged: episode {converged}")
        else:
            ax.plot([], [], " ", label=f"not converged within {values.shape[0]} episodes")
    ax.set_xlabel("episodes")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower right", fontsize="small")
    if path is not None:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        savefig_atomic(figure, path, dpi=120, bbox_inches="tight")
    return figure
