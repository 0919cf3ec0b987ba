"""The learning curve of a tuning run: the best cost found against the episodes spent."""

from __future__ import annotations

import numpy as np


def plot_curve(curve, path, title: str = "", start: float | None = None) -> None:
    """Plot ``curve`` ([(episodes, best cost so far)]) to ``path`` (written atomically), with the
    start's cost as a dashed line when given (log scale: a failure costs 10 to 20, an arrival < 1)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from fuzzynav.storage import savefig_atomic

    points = np.asarray(curve, dtype=float).reshape(-1, 2)
    figure, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.step(points[:, 0], points[:, 1], where="post", label="best candidate so far")
    if start is not None:
        ax.axhline(start, linestyle="--", color="k", linewidth=0.8, label="start (the system tuned)")
    ax.set_yscale("log")
    ax.legend(loc="center right", fontsize="small")
    ax.set_xlabel("simulated episodes")
    ax.set_ylabel("best mean episode cost (lower is better)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    savefig_atomic(figure, path, dpi=120, bbox_inches="tight")
    plt.close(figure)
