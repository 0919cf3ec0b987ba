"""The controllers' settings checked where the controllers are made.

``make_controller(NAME, **options)`` (and the benchmark scripts' ``--options``) hand a user's
options to a controller's constructor. :func:`checked` decorates such a constructor: every
argument given for a parameter annotated ``bool``, ``int`` or ``float`` is checked before the
constructor runs — a flag must be true or false, a count a whole number and a quantity a finite
number, each within the :class:`Range` the constructor declares for it. A value outside its
meaning is an :class:`~fuzzynav.errors.InputError` naming the setting (and ``make_controller``
adds the controller's name), never a traceback, a hang on a huge count or a silently absurd robot.

Every ``int`` and ``float`` parameter of a decorated constructor must have a declared range, so
a new setting cannot slip past unchecked; the ranges are listed in ``docs/limits.md``.
"""

from __future__ import annotations

import functools
import inspect
import math
from dataclasses import dataclass

import numpy as np

from fuzzynav import validation


@dataclass(frozen=True)
class Range:
    """The values a setting may take: [``lo``, ``hi``], an end left out when ``lo_open`` /
    ``hi_open``."""

    lo: float
    hi: float
    lo_open: bool = False
    hi_open: bool = False


LENGTH = Range(0.0, 1e4, lo_open=True)  # m: a size, a reach, a look-ahead
ROOM = Range(0.0, 1e4)  # m: a margin or clearance that may be zero
SPEED = Range(0.0, 100.0, lo_open=True)  # m/s
SLOW = Range(0.0, 100.0)  # m/s: a speed that may be zero
RATE = Range(0.0, 1e4, lo_open=True)  # a gain, an acceleration (per second, m/s²)
WEIGHT = Range(0.0, 1e6)  # a weight or cost of a sum
DURATION = Range(0.0, 600.0)  # s
PREDICTION = Range(0.0, 60.0, lo_open=True)  # s: how far ahead a navigator predicts
STEERING = Range(0.0, math.pi / 2, lo_open=True, hi_open=True)  # rad: a steering limit
SPREAD = Range(0.0, math.pi, lo_open=True)  # rad: a half-width of a sector
SHARE = Range(0.0, 1.0)
STEPS = Range(0, 100_000)  # simulation steps
SAMPLES = Range(1, 1001)  # candidates sampled per decision
MEMORY = Range(1, 10_000)  # remembered scans
BODY = {"radius": LENGTH, "wheelbase": LENGTH, "max_steering": STEERING, "max_speed": SPEED}


def checked(**ranges: Range):
    """Decorate a constructor so that the arguments given for its ``bool``, ``int`` and
    ``float`` parameters are checked against their type and ``ranges`` (a :class:`Range` by
    parameter name) before it runs; see the module docstring."""

    def decorate(init):
        signature = inspect.signature(init)
        kinds = {name: parameter.annotation for name, parameter in signature.parameters.items()
                 if parameter.annotation in ("bool", "int", "float")}
        unranged = [name for name, kind in kinds.items() if kind != "bool" and name not in ranges]
        stray = sorted(set(ranges) - set(kinds))
        if unranged or stray:
            raise TypeError(f"{init.__qualname__}: no range for {unranged}, ranges for no setting {stray}")

        @functools.wraps(init)
        def checking(*args, **kwargs):
            try:
                given = signature.bind(*args, **kwargs).arguments
            except TypeError:  # an unknown or doubled keyword: the constructor says which
                return init(*args, **kwargs)
            for name, value in given.items():
                if kinds.get(name) == "bool":
                    flag(value, name)
                elif name in kinds:
                    within(value, name, ranges[name], whole=kinds[name] == "int")
            return init(*args, **kwargs)

        return checking

    return decorate


def flag(value, name: str, source=None) -> bool:
    """``value`` of the flag ``name`` (of the file ``source``, if any): an
    :class:`~fuzzynav.errors.InputError` unless true or false."""
    if not isinstance(value, (bool, np.bool_)):
        validation.fail(f"must be true or false, got {validation.shown(value)}", source, name)
    return bool(value)


def within(value, name: str, bounds: Range, *, whole: bool = False) -> float:
    """``value`` of the setting ``name``: a finite number (a whole one when ``whole``) within
    ``bounds`` (an :class:`~fuzzynav.errors.InputError` otherwise)."""
    if whole:
        return validation.integer(value, field=name, lo=int(bounds.lo), hi=int(bounds.hi))
    return validation.number(value, field=name, lo=bounds.lo, hi=bounds.hi, lo_open=bounds.lo_open,
                             hi_open=bounds.hi_open)
