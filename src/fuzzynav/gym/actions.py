"""The actions an agent gives the environments, checked before anything reaches the robot.

Gymnasium leaves an action outside the action space undefined; here each is either refused or
clipped, never passed on as it is:

- ``Box`` (continuous): an array (or nested list) of real numbers (integer or floating dtype,
  not bool, complex or object) of exactly the space's shape — ``(k,)`` for one environment,
  ``(num_envs, k)`` for the vector environment — and finite. A finite value outside [−1, 1] is
  clipped to it (what Gymnasium's ``ClipAction`` wrapper and its continuous control
  environments do); a wrong shape, a non-numeric value, NaN or ±inf is refused.
- ``Discrete``: an integer (Python ``int``, NumPy integer, or a 0-d integer array; the vector
  environment: an integer array of shape ``(num_envs,)``) in [0, n), as ``Discrete.contains``
  reads it; a float such as 2.7, a bool, or −1 is refused, never rounded or wrapped.

A refused action is an :class:`~fuzzynav.errors.InputError` (a ``ValueError``) naming the
field ``action`` and the problem; the episode is left as it was, so the agent can step again.
In the vector environment only the sub-environments whose action is used (those not being reset)
are checked for finiteness and range.
"""

from __future__ import annotations

import numpy as np
from gymnasium import spaces

from fuzzynav.errors import InputError


def _array(actions, field: str) -> np.ndarray:
    try:
        array = np.asarray(actions)
    except (TypeError, ValueError) as error:  # ragged nested lists
        raise InputError(f"must be an array of numbers, got {type(actions).__name__} ({error})", field=field) from None
    return array


def check_actions(actions, space, n: int, used=None, *, single: bool) -> np.ndarray:
    """The actions of ``n`` environments as used: ``(n,)`` indices (``Discrete``) or ``(n, k)``
    values clipped to [−1, 1] (``Box``); ``single``: ``actions`` is one environment's action.
    ``used`` (n,) bool marks the rows whose action is applied (default: all)."""
    field = "action" if single else "actions"
    used = np.ones(n, dtype=bool) if used is None else np.asarray(used, dtype=bool)
    array = _array(actions, field)
    if isinstance(space, spaces.Discrete):
        shape = () if single else (n,)
        if array.shape != shape or array.dtype.kind not in "iu":
            raise InputError(f"must be an integer {'index' if single else f'array of shape {shape}'} of "
                             f"Discrete({space.n}), got {_shown(actions, array)}", field=field)
        given = array.reshape(n)
        indices = given.astype(np.int64)  # a uint64 above 2**63 - 1 wraps to a negative index: refused below
        bad = used & ((indices < space.start) | (indices >= space.start + space.n))
        if bad.any():
            raise InputError(f"must be in [{space.start}, {space.start + space.n - 1}], got {int(given[bad][0])}",
                             field=_row(field, bad, single))
        return indices - space.start
    shape = space.shape if single else (n, *space.shape)
    if array.dtype.kind not in "iuf" or array.shape != shape:
        raise InputError(f"must be an array of real numbers of shape {shape}, got {_shown(actions, array)}", field=field)
    values = array.reshape(n, -1).astype(float)
    bad = used & ~np.isfinite(values).all(axis=1)
    if bad.any():
        raise InputError(f"must be finite, got {values[bad][0].tolist()}", field=_row(field, bad, single))
    return np.clip(values, space.low.astype(float), space.high.astype(float))


def _row(field: str, bad, single: bool) -> str:
    return field if single else f"{field}[{int(np.flatnonzero(bad)[0])}]"


def _shown(actions, array) -> str:
    text = " ".join(repr(actions).split())
    text = text if len(text) <= 60 else text[:57] + "..."
    return f"{text} (shape {array.shape}, dtype {array.dtype})"
