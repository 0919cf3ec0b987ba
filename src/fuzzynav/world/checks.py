"""The checks of a scenario file's values, bound to the file: :class:`Checks` for any field and
:class:`ShapeFields`, what an obstacle type's ``parse`` reads its parameters through.

Both go through :mod:`fuzzynav.validation` with the ranges of :mod:`fuzzynav.world.limits`, so
every problem is an :class:`~fuzzynav.errors.InputError` naming the file and the field
(``obstacles[2].circle.radius``).
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.world import limits


class Checks:
    """The checks of :mod:`fuzzynav.validation` bound to one source file, with the scenario's
    ranges (:mod:`fuzzynav.world.limits`)."""

    def __init__(self, source: str):
        self.source = source

    def fail(self, field: str, problem: str):
        validation.fail(problem, self.source, field)

    def mapping(self, value, field: str, known, required=()) -> dict:
        return validation.known_keys(value, known, self.source, field, required=required)

    def number(self, value, field: str, positive: bool = False) -> float:
        """A length (m, :func:`~fuzzynav.world.limits.length`) when ``positive``, else a coordinate."""
        return (limits.length if positive else limits.coordinate)(value, self.source, field)

    def point(self, value, field: str, positive: bool = False) -> np.ndarray:
        if not isinstance(value, (list, tuple)) or len(value) != 2:
            self.fail(field, f"must be a list of two numbers [x, y], got {validation.shown(value)}")
        return np.array([self.number(v, f"{field}[{i}]", positive) for i, v in enumerate(value)])

    def points(self, value, field: str, minimum: int, maximum: int) -> np.ndarray:
        items = validation.sequence(value, self.source, field)
        if len(items) < minimum:
            self.fail(field, f"needs at least {minimum} points, got {len(items)}")
        if len(items) > maximum:
            self.fail(field, f"at most {maximum} points (docs/limits.md), got {len(items)}")
        return np.array([self.point(v, f"{field}[{i}]") for i, v in enumerate(items)])

    def text(self, value, field: str, allow_empty: bool = True) -> str:
        return validation.text(value, self.source, field, max_length=1000, allow_empty=allow_empty)

    def label(self, value, field: str) -> str:
        """A name printed on a terminal and drawn in plots: a non-blank line of text (no ESC, NUL...)."""
        return validation.text(value, self.source, field, max_length=1000, allow_empty=False, one_line=True)


class ShapeFields:
    """The parameters of one obstacle entry (its schema's defaults filled in), each read by name
    with the check of its kind; errors name ``<entry>.<key>``."""

    def __init__(self, checks: Checks, params: dict, field: str):
        self.checks, self.params, self.field = checks, params, field

    def point(self, key: str, positive: bool = False) -> np.ndarray:
        """A point [x, y] (coordinates), or a pair of lengths when ``positive``."""
        return self.checks.point(self.params[key], f"{self.field}.{key}", positive)

    def points(self, key: str, minimum: int, maximum: int) -> np.ndarray:
        """A list of ``minimum`` to ``maximum`` points ``(n, 2)``."""
        return self.checks.points(self.params[key], f"{self.field}.{key}", minimum, maximum)

    def length(self, key: str) -> float:
        """A radius, semi-axis or thickness (m)."""
        return self.checks.number(self.params[key], f"{self.field}.{key}", positive=True)

    def angle(self, key: str) -> float:
        """An angle (rad)."""
        return limits.angle(self.params[key], self.checks.source, f"{self.field}.{key}")

    def fail(self, key: str, problem: str):
        self.checks.fail(f"{self.field}.{key}", problem)
