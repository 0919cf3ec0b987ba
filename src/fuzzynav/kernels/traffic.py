"""Moving obstacles in the packed scene, compiled: each step writes the moving obstacles' rows of the
scene at their current place — their rows at t = 0 (``base``) translated by their offsets
(:mod:`fuzzynav.world.moving`) — so sensing and collisions read the obstacles where they are.

``movers`` ``(M, 4)`` are their rows (:func:`fuzzynav.kernels.layout.mover_rows`): a disc or an
ellipse moves its centre; a polygon its centre and the two ends of each edge (the edge vectors,
lengths and bounding radius do not change under a translation).
"""

from __future__ import annotations

from fuzzynav.jit import jit
from fuzzynav.kernels.layout import AT_EDGES
from fuzzynav.kernels.scene import nearest_one


@jit
def place(base, movers, offsets, scene):
    """Write into ``scene`` the rows of the moving obstacles ``movers`` taken from ``base`` and
    translated by ``offsets`` ``(M, 2)``; every other entry of ``scene`` is left as it is."""
    for m in range(movers.shape[0]):
        at, dx, dy = movers[m, 1], offsets[m, 0], offsets[m, 1]
        if movers[m, 0] != 1:
            scene[at], scene[at + 1] = base[at] + dx, base[at + 1] + dy
            continue
        scene[at + 2], scene[at + 3] = base[at + 2] + dx, base[at + 3] + dy
        for i in range(movers[m, 2], movers[m, 3]):
            e = int(base[AT_EDGES]) + 7 * i
            scene[e], scene[e + 1] = base[e] + dx, base[e + 1] + dy
            scene[e + 2], scene[e + 3] = base[e + 2] + dx, base[e + 3] + dy


@jit
def nearest_over_time(base, movers, offsets, points, scene, out):
    """Nearest obstacle of point k (``points`` (T, 2)) with the moving obstacles placed at their
    offsets of time k (``offsets`` (T, M, 2)), into ``out`` (T, 5) (``scene``: a copy of ``base``
    used as scratch)."""
    for k in range(points.shape[0]):
        place(base, movers, offsets[k], scene)
        nearest_one(scene, points[k, 0], points[k, 1], out[k])
