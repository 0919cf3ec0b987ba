"""The learning curve of a tuning run: the best cost found against the candidate evaluations spent."""

from __future__ import annotations

import numpy as np


def plot_curve(curve, path, title: str = "") -> None:
    """Plot ``curve`` ([(evaluations, best cost so far)]) to ``path`` (written atomically)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from fuzzynav.storage import savefig_atomic

    points = np.asarray(curve, dtype=float).reshape(-1, 2)
    figure, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.step(points[:, 0], points[:, 1], where="post")
    ax.set_xlabel("candidate evaluations")
    ax.set_ylabel("best mean episode cost (lower is better)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    savefig_atomic(figure, path, dpi=120, bbox_inches="tight")
    plt.close(figure)
