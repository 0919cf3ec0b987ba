"""Read-only views of the stepping core's per-robot arrays, declared one line each.

The stepping core keeps N robots in a ``state`` (N, :data:`fuzzynav.kernels.step.STATE_FIELDS`)
float array and a ``status`` (N, 3) int array, a column per quantity (``X``, ``SPEED``,
``OUTCOME``, ``STEPS`` … of :mod:`fuzzynav.kernels.step`). The classes that hold them
(:class:`fuzzynav.world.fleet.Fleet`, :class:`fuzzynav.sim.simulator.BatchSimulator`) show
those columns as attributes: ``pose = Column("state", slice(X, THETA + 1), "(N, 3) poses")``.
"""

from __future__ import annotations

from typing import Any, overload

import numpy as np


class Column:
    """The columns ``columns`` (an index or a slice) of the owner's array attribute ``array``, read
    as an attribute documented by ``doc``: a view of the owner's array, or a copy if ``copy``.
    Read-only: assigning to it raises ``AttributeError``, as a ``property`` does."""

    def __init__(self, array: str, columns: int | slice, doc: str, *, copy: bool = False):
        self.array, self.columns, self.copy, self.__doc__ = array, columns, copy, doc
        self.name = ""

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    @overload
    def __get__(self, instance: None, owner: type | None = None) -> Column: ...

    @overload
    def __get__(self, instance: object, owner: type | None = None) -> np.ndarray: ...

    def __get__(self, instance: object | None, owner: type | None = None) -> Column | np.ndarray:
        if instance is None:
            return self
        values = getattr(instance, self.array)[:, self.columns]
        return values.copy() if self.copy else values

    def __set__(self, instance: object, value: Any) -> None:
        raise AttributeError(f"{self.name} is read-only (a column of {self.array})")
