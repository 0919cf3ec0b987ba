"""Validation and training curve of a learned tracker (Figs V.15 and V.23).

:func:`plot_training` takes the fitted model (an MLP of :mod:`fuzzynav.learn.neural` or an ANFIS of
:mod:`fuzzynav.learn.anfis`) and its training data (validation pairs ``x_val`` ``(N, 1)``,
``y_val`` ``(N,)``, as the tracker tasks' training data holds them).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from fuzzynav.viz.trajectories import save_figure


def plot_training(kind: str, model, data, path) -> Figure:
    """Figs V.15 / V.23: (a) desired and model output on the validation pairs, (b) their error,
    (c) the training curve (MLP loss per iteration, or ANFIS RMSE per epoch)."""
    figure = Figure(figsize=(13, 3.8), layout="constrained")
    a, b, c = figure.subplots(1, 3)
    order = np.argsort(data.x_val[:, 0])
    predicted = model.predict(data.x_val)
    k = np.arange(len(order))
    a.plot(k, data.y_val[order], "o", markersize=3, label="desired output")
    a.plot(k, predicted[order], "-", label="real output")
    a.set(xlabel="validation sample (sorted by θ_er)", ylabel="α (rad)", title="(a) outputs")
    a.legend()
    b.plot(k, (data.y_val - predicted)[order])
    b.set(xlabel="validation sample", ylabel="error (rad)", title="(b) learning error")
    if kind == "anfis-tracker":
        c.semilogy(model.history_["train_rmse"], label="training RMSE")
        if model.history_["validation_rmse"] is not None:
            c.semilogy(model.history_["validation_rmse"], label="validation RMSE")
        c.set(xlabel="epoch", ylabel="RMSE (rad)", title="(c) hybrid learning (Table V.2)")
        c.legend()
    elif len(model.loss_curve) > 1:
        c.semilogy(np.arange(1, len(model.loss_curve) + 1), model.loss_curve)
        c.set(xlabel="iteration", ylabel="loss (half MSE, standardised α)", title="(c) back-propagation")
    else:  # L-BFGS records no per-iteration curve: say what it did instead of drawing one point
        c.axis("off")
        c.set_title("(c) back-propagation (L-BFGS)")
        c.text(0.5, 0.5, f"{model.iterations} solver iterations\nfinal loss {model.loss_curve[-1]:.2e}\n"
               "(half mean squared error on standardised α)\nL-BFGS records no loss per iteration",
               ha="center", va="center", transform=c.transAxes)
    figure.suptitle(f"{kind}: generalized learning, validation on {len(order)} unseen pairs")
    if path is not None:
        save_figure(figure, path)
    return figure
