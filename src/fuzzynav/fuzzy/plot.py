"""Plots of fuzzy systems (matplotlib, Agg backend, imported lazily).

- :func:`plot_variable` — the membership functions of a variable, like Figs IV.5–IV.8 and V.4–V.6
  (singletons drawn as vertical bars).
- :func:`plot_surface` — the control surface of a two-input system for one output, like Fig V.7.
- :func:`plot_system` — every variable of a system on one page.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.formula import Function
from fuzzynav.fuzzy.membership import Linear, Singleton
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.terms import Constant
from fuzzynav.fuzzy.variable import Variable


def _figure(**kwargs):
    from matplotlib.figure import Figure  # lazy: the library does not need matplotlib to compute

    return Figure(**kwargs)


def plot_variable(variable: Variable, ax=None, samples: int = 801, crisp: bool = False):
    """Draw the terms of ``variable`` over its universe on ``ax`` (a new figure if None); returns ax.
    ``crisp``: an output of Takagi–Sugeno conclusions, whose ``Constant`` terms are values (drawn
    as bars, like singletons), not degrees over the axis."""
    if ax is None:
        ax = _figure(figsize=(6, 2.6), layout="constrained").add_subplot()
    lo, hi = variable.universe
    x = np.linspace(lo, hi, samples)
    others = []  # formulas of other variables: no shape over this one's axis
    for label, mf in variable.terms.items():
        if isinstance(mf, Singleton) or (crisp and isinstance(mf, Constant)):
            value = float(mf.params()[0])
            line = ax.vlines(value, 0, 1, linewidth=2)
            ax.annotate(label, (value, 1.02), ha="center", va="bottom", fontsize=8, color=line.get_color()[0])
        elif isinstance(mf, Linear):
            continue  # an affine conclusion has no shape on the output axis
        elif isinstance(mf, Function) and mf.variables - {variable.name}:
            others.append(f"{label} = {mf.formula}")
        else:
            mu = mf(x, {variable.name: x}) if isinstance(mf, Function) else mf(x)
            (line,) = ax.plot(x, mu, linewidth=1.5)
            peak = x[np.argmax(np.where(np.isnan(mu), -np.inf, mu))]  # a formula may give NaN somewhere
            ax.annotate(label, (peak, 1.02), ha="center", va="bottom", fontsize=8, color=line.get_color())
    if others:
        ax.text(0.01, 0.97, "not drawn (formulas of other variables): " + "; ".join(others), transform=ax.transAxes,
                fontsize=7, va="top")
    bars = any(isinstance(mf, Singleton) or (crisp and isinstance(mf, Constant)) for mf in variable.terms.values())
    pad = 0.03 * (hi - lo) if bars else 0.0
    ax.set_xlim(lo - pad, hi + pad)
    ax.set_ylim(0, 1.15)
    ax.set_xlabel(variable.name)
    ax.set_ylabel(f"μ({variable.name})")
    return ax


def _crisp(system, output) -> bool:
    """Are ``output``'s terms Takagi–Sugeno conclusions (a weighted defuzzifier), not fuzzy sets?"""
    defuzzifier = getattr(output, "defuzzifier", None)  # an engine's output variable
    if defuzzifier is not None:
        return not defuzzifier.integral
    return getattr(system, "method", "mamdani") != "mamdani"


def plot_system(system: FuzzySystem):
    """One row per variable (inputs, then outputs); returns the figure."""
    variables = system.inputs + system.outputs
    fig = _figure(figsize=(6, 2.2 * len(variables)), layout="constrained")
    axes = fig.subplots(len(variables), 1, squeeze=False)[:, 0]
    for ax, var in zip(axes, variables):
        plot_variable(var, ax, crisp=var in system.outputs and _crisp(system, var))
    fig.suptitle(system.name or "fuzzy system")
    return fig


def surface(system: FuzzySystem, output: str | None = None, n: int = 61):
    """Grid (x1, x2, y) of ``output`` over the universes of a two-input system, (n, n) each."""
    if len(system.inputs) != 2:
        raise ValueError(f"a control surface needs exactly two inputs, {system.name!r} has {len(system.inputs)}")
    o = system.output_names.index(output) if output else 0
    (a, b), (c, d) = system.inputs[0].universe, system.inputs[1].universe
    x1, x2 = np.meshgrid(np.linspace(a, b, n), np.linspace(c, d, n))
    X = np.column_stack([x1.ravel(), x2.ravel()])
    y = system.evaluate(X)[:, o:o + 1]
    system.check_finite(X, y, [system.output_names[o]])  # NaN or inf: a hole in the surface, drawn without a word
    return x1, x2, y.reshape(x1.shape)


def plot_surface(system: FuzzySystem, output: str | None = None, n: int = 61):
    """3-D control surface of ``output`` (default: the first) over both inputs (Fig V.7); returns the figure."""
    x1, x2, y = surface(system, output, n)
    fig = _figure(figsize=(6, 4.5), layout="constrained")
    ax = fig.add_subplot(projection="3d")
    ax.plot_surface(x1, x2, y, cmap="viridis", linewidth=0, antialiased=True)
    ax.set_xlabel(system.input_names[0])
    ax.set_ylabel(system.input_names[1])
    ax.set_zlabel(output or system.output_names[0])
    ax.set_title(f"{system.name or 'fuzzy system'}: control surface")
    return fig
