"""Linguistic variables (thesis §II.2.3, Fig II.3): a name, a universe of discourse and named terms.

Inputs are clamped to the universe before fuzzification (§II.4.1): a controller fed a distance
beyond its sensor range or an angle beyond the last shoulder sees the value at the border, where
a strong partition's outer shoulder is 1. This is the documented behaviour of every evaluation
path of :class:`~fuzzynav.fuzzy.system.FuzzySystem`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.membership import MembershipFunction
from fuzzynav.validation import MAX_UNIVERSE_WIDTH, float_array, shown


class Variable:
    """A linguistic variable: ``Variable("drg", (0, 28.3), {"Z": mf, "P": mf, ...})``.

    Term order is the insertion order of ``terms``; rule tables and fuzzified columns use it.
    """

    def __init__(self, name: str, universe: tuple[float, float], terms: Mapping[str, MembershipFunction]):
        if not name or not str(name).isidentifier():
            raise InputError(f"variable name must be an identifier, got {name!r}", field="name")
        try:
            lo, hi = (float(v) for v in universe)
        except (TypeError, ValueError):  # not two numbers: None, "ab", (0, 1, 2)
            raise InputError(f"universe must be two numbers (lo, hi), got {shown(universe)}",
                             field=f"{name}.universe") from None
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi and hi - lo <= MAX_UNIVERSE_WIDTH):
            raise InputError(f"universe must be finite with lo < hi (and hi - lo <= {MAX_UNIVERSE_WIDTH:g}), got "
                             f"{tuple(universe)!r}", field=f"{name}.universe")
        if not isinstance(terms, Mapping):
            raise InputError(f"terms must be a mapping of labels to membership functions, got {shown(terms)}",
                             field=name)
        if not terms:
            raise InputError("variable has no terms", field=name)
        for label, mf in terms.items():
            field = f"{name}.{label}"
            if not str(label).isidentifier():
                raise InputError(f"term label must be an identifier, got {label!r}", field=field)
            if not isinstance(mf, MembershipFunction):
                raise InputError(f"{mf!r} is not a membership function", field=field)
            s_lo, s_hi = mf.support()
            if s_hi < lo or s_lo > hi:
                raise InputError(f"term {mf!r} lies outside the universe [{lo!r}, {hi!r}]", field=field)
        self.name = str(name)
        self.universe = (lo, hi)
        self.terms: dict[str, MembershipFunction] = dict(terms)

    @property
    def labels(self) -> list[str]:
        """Term labels, in order."""
        return list(self.terms)

    def index(self, label: str) -> int:
        """Position of ``label`` among the terms (KeyError if unknown)."""
        return self.labels.index(label)

    def clamp(self, x):
        """``x`` clipped to the universe (see module docstring)."""
        return np.clip(np.asarray(x, dtype=float), *self.universe)

    def fuzzify(self, x, *, clamp: bool = True) -> np.ndarray:
        """Membership degrees of a batch: ``x`` of shape (N,) -> (N, n_terms), columns in term order."""
        x = np.atleast_1d(np.asarray(x, dtype=float))
        if x.ndim != 1:
            raise ValueError(f"variable {self.name!r}: fuzzify takes a 1-D batch, got shape {x.shape}")
        if clamp:
            x = self.clamp(x)
        out = np.empty((x.shape[0], len(self.terms)))
        for j, mf in enumerate(self.terms.values()):
            out[:, j] = mf(x)
        return out

    def __eq__(self, other) -> bool:
        return (
            isinstance(other, Variable)
            and self.name == other.name
            and self.universe == other.universe
            and list(self.terms.items()) == list(other.terms.items())
        )

    def __repr__(self) -> str:
        return f"Variable({self.name!r}, {self.universe!r}, {self.terms!r})"


class VariableNames:
    """``input_names`` / ``output_names`` of anything holding ``inputs`` and ``outputs`` variables."""

    inputs: list
    outputs: list

    @property
    def input_names(self) -> list[str]:
        return [v.name for v in self.inputs]

    @property
    def output_names(self) -> list[str]:
        return [v.name for v in self.outputs]

    def input_matrix(self, X) -> np.ndarray:
        """``X`` as a float array of shape (N, number of inputs); an InputError naming the inputs otherwise."""
        X = float_array(X, field="inputs")
        if X.ndim != 2 or X.shape[1] != len(self.inputs):
            raise InputError(f"expected an array of shape (N, {len(self.inputs)}) "
                             f"({', '.join(self.input_names)}), got {X.shape}", field="inputs")
        return X

    def check_finite(self, X, Y, outputs=None) -> None:
        """Refuse an answer ``Y`` (columns: ``outputs``, default all) to the inputs ``X`` that is not
        a finite number: NaN (no rule fired and the output has no default, or a term evaluated to
        NaN) or ±inf (a Function term overflowing or dividing by zero)."""
        names = self.output_names if outputs is None else list(outputs)
        bad = ~np.isfinite(Y)
        if bad.any():
            row, column = (int(i) for i in np.argwhere(bad)[0])
            inputs = ", ".join(f"{name}={float(x)!r}" for name, x in zip(self.input_names, X[row]))
            raise InputError(f"no finite answer for {inputs}: {names[column]} = {float(Y[row, column])!r} (no rule "
                             "fired and the output has no finite default, or a term's formula gives a non-finite "
                             "value)", field=names[column])

    def check_unique_names(self) -> None:
        """InputError naming the variables that share a name, or a name or term label holding a
        control character (``fis show`` prints them: an ESC would reach the terminal)."""
        for var in self.inputs + self.outputs:
            validation.text(var.name, field="variables", one_line=True)
            for label in var.terms:
                validation.text(label, field=f"{var.name} terms", one_line=True)
        names = self.input_names + self.output_names
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise InputError(f"duplicate variable name(s) {', '.join(dupes)}", field="variables")
