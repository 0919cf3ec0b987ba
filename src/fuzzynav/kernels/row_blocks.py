"""The per-robot blocks of a compiled navigator's ``state`` row after its :class:`~fuzzynav.kernels.layers.RobotState`
fields, sized by the :class:`~fuzzynav.kernels.layers.Slots` and ``delay`` of ``params``, in this
order: the loop detector's sampled places, the latency queue, the car route kept for reuse, the
obstacle points seen and the hash set of their cells (:mod:`fuzzynav.kernels.layers` describes
each). Each function gives a view of its block, so a kernel writes into the row through it."""

from __future__ import annotations

from fuzzynav.jit import jit
from fuzzynav.kernels.layers import PARAM, PLACES_AT


@jit
def places_of(params, row):
    """The loop detector's ring buffer (places_slots, 3) in a robot's ``state`` row."""
    size = int(params[PARAM.places_slots])
    return row[PLACES_AT:PLACES_AT + 3 * size].reshape(size, 3)


@jit
def queue_of(params, row):
    """The commands sent and not yet applied (delay, 2: α, V) in a robot's ``state`` row."""
    at, size = PLACES_AT + 3 * int(params[PARAM.places_slots]), int(params[PARAM.delay])
    return row[at:at + 2 * size].reshape(size, 2)


@jit
def route_of(params, row):
    """The car route kept (route_slots, 4): x, y, θ and the primitive reaching each pose, in a robot's ``state`` row."""
    at = PLACES_AT + 3 * int(params[PARAM.places_slots]) + 2 * int(params[PARAM.delay])
    size = int(params[PARAM.route_slots])
    return row[at:at + 4 * size].reshape(size, 4)


@jit
def points_at(params):
    """Where the obstacle points begin in a robot's ``state`` row (after the places, queue and route)."""
    return (PLACES_AT + 3 * int(params[PARAM.places_slots]) + 2 * int(params[PARAM.delay])
            + 4 * int(params[PARAM.route_slots]))


@jit
def points_of(params, row):
    """The obstacle points (points_slots, 2) in a robot's ``state`` row."""
    at, size = points_at(params), int(params[PARAM.points_slots])
    return row[at:at + 2 * size].reshape(size, 2)


@jit
def cells_of(params, row):
    """The hash set of the points' cells (cell_slots,) in a robot's ``state`` row."""
    at = points_at(params) + 2 * int(params[PARAM.points_slots])
    return row[at:at + int(params[PARAM.cell_slots])]
